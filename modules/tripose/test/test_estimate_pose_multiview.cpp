// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Registration against several known views (estimatePoseMultiView*, refinePoseMultiView): exact on
// noise-free scenes where every feature is seen by a random subset of the known views, the
// three-view function as its two-view case, the input errors, and tracking a VGG sequence.

#include "test_pose_common.hpp"

#include "tripose_support/random_draws.hpp"

#include <functional>
#include <limits>

#include "../src/opencv/opencv_compat.hpp" // Rodrigues: calib3d in OpenCV 4, geometry in 5

namespace opencv_test {
namespace {

using cv::tripose::support::poseError;
using cv::tripose::support::uniformInCube;

typedef cv::tripose::support::SyntheticMultiViewScene MultiViewScene;

// Exact data: the linear method is exact to rounding, amplified by the conditioning of a system of
// a few features (the three-view tests allow the same).
const double kExactRotationDeg = 1e-6;
const double kExactTranslation = 1e-6; // relative to |t|, about 20 m

struct MixCase
{
    int known, points, lines;
};

TEST(Tripose_MultiView, exact_on_noise_free_scenes_with_partial_visibility)
{
    const MixCase cases[] = { { 2, 10, 10 }, { 3, 20, 0 }, { 4, 0, 20 }, { 5, 15, 15 }, { 6, 3, 3 },
                              { 3, 4, 0 }, { 3, 0, 4 }, { 4, 2, 2 }, { 3, 3, 2 } };
    for (const MixCase& c : cases)
        for (int seed = 1; seed <= 5; ++seed)
        {
            SCOPED_TRACE(cv::format("%d known views, %d points, %d lines, seed %d", c.known, c.points, c.lines, seed));
            const MultiViewScene s(c.known, c.points, c.lines, 1000 * c.known + 10 * c.points + c.lines + seed);
            Mat R, t;
            ASSERT_GT(cv::tripose::estimatePoseMultiView(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, R, t), 0);
            const cv::tripose::support::PoseError e = poseError(R, t, Mat(s.R), Mat(s.t));
            EXPECT_LT(e.rotationDeg, kExactRotationDeg);
            EXPECT_LT(e.relativeTranslation, kExactTranslation);

            if (c.points + c.lines < 6)
                continue; // RANSAC's samples need redundancy to score
            Mat Rr, tr, pointInliers, lineInliers;
            cv::tripose::RansacParams params;
            params.minInliers = 0; // a few features, all right: no floor on the inliers above them
            const int inliers = cv::tripose::estimatePoseMultiViewRansac(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, Rr,
                                                                     tr, params, pointInliers, lineInliers);
            EXPECT_EQ(c.points + c.lines, inliers);
            const cv::tripose::support::PoseError er = poseError(Rr, tr, Mat(s.R), Mat(s.t));
            EXPECT_LT(er.rotationDeg, kExactRotationDeg);
            EXPECT_LT(er.relativeTranslation, kExactTranslation);
        }
}

//! Swaps pairs among the first half of the rows of @p m that are seen (not NaN): those matches
//! become wrong. Returns the mask of the rows left right (seen rows only).
Mat swapHalfOfTheSeenRows(Mat& m)
{
    if (m.empty())
        return Mat();
    std::vector<int> seen;
    for (int i = 0; i < m.rows; ++i)
        if (cvIsNaN(m.at<double>(i, 0)) == 0)
            seen.push_back(i);
    Mat right(m.rows, 1, CV_8U, Scalar(0));
    for (int i : seen)
        right.at<uchar>(i) = 1;
    for (size_t k = 0; k + 1 < seen.size() / 2; k += 2)
    {
        Mat a = m.row(seen[k]).clone();
        m.row(seen[k + 1]).copyTo(m.row(seen[k]));
        a.copyTo(m.row(seen[k + 1]));
        right.at<uchar>(seen[k]) = right.at<uchar>(seen[k + 1]) = 0;
    }
    return right;
}

// Line-dominated registration with about half of the new view's matches wrong, noise-free: the
// robust estimator draws samples of points and lines mixed on the known views' structure and
// returns the pose to rounding wherever the inliers it finds are the right matches (a wrong match
// can fall within the threshold by chance).
TEST(Tripose_MultiView, line_dominated_ransac_with_half_the_matches_wrong)
{
    const MixCase cases[] = { { 3, 0, 60 }, { 4, 3, 60 }, { 3, 10, 100 } };
    for (const MixCase& c : cases)
    {
        int exact = 0;
        for (int seed = 1; seed <= 10; ++seed)
        {
            SCOPED_TRACE(cv::format("%d known views, %d points, %d lines, seed %d", c.known, c.points, c.lines, seed));
            MultiViewScene s(c.known, c.points, c.lines, 7000 + 10 * c.lines + seed);
            // A kind the scene has none of has no arrays at all.
            const Mat rightPoints = s.points.empty() ? Mat() : swapHalfOfTheSeenRows(s.points.back());
            const Mat rightLines = s.lines.empty() ? Mat() : swapHalfOfTheSeenRows(s.lines.back());
            cv::tripose::RansacParams params;
            params.threshold = 0.5;
            params.seed = seed;
            Mat R, t, pointInliers, lineInliers;
            ASSERT_GT(cv::tripose::estimatePoseMultiViewRansac(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, R, t,
                                                               params, pointInliers, lineInliers),
                      0);
            const cv::tripose::support::PoseError e = poseError(R, t, Mat(s.R), Mat(s.t));
            const auto same = [](const Mat& a, const Mat& b) {
                return a.total() == b.total() && (a.empty() || cv::countNonZero(a.reshape(1, 1) != b.reshape(1, 1)) == 0);
            };
            const bool masksRight = same(pointInliers, rightPoints) && same(lineInliers, rightLines);
            if (masksRight)
            {
                EXPECT_LT(e.rotationDeg, kExactRotationDeg);
                EXPECT_LT(e.relativeTranslation, kExactTranslation);
            }
            EXPECT_LT(e.rotationDeg, 0.1);
            exact += masksRight && e.rotationDeg < kExactRotationDeg;
        }
        std::cout << c.known << " known views, " << c.points << "P+" << c.lines << "L, half the matches wrong: exact "
                  << exact << "/10" << std::endl;
        EXPECT_GE(exact, 6);
    }
}

TEST(Tripose_MultiView, refinement_returns_to_the_exact_pose)
{
    const MultiViewScene s(4, 15, 15, 77);
    Mat rvec;
    Rodrigues(Mat(s.R), rvec);
    rvec += Mat(Vec3d(0.01, -0.01, 0.005));
    Mat t = Mat(s.t) + Mat(Vec3d(0.2, -0.1, 0.3));
    Mat points3d, lines3d;
    const double rms = cv::tripose::refinePoseMultiView(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, rvec, t,
                                                    cv::tripose::RefineParams(), points3d, lines3d);
    EXPECT_LT(rms, 1e-6);
    const cv::tripose::support::PoseError e = poseError(rvec, t, Mat(s.R), Mat(s.t));
    EXPECT_LT(e.rotationDeg, 1e-6);
    EXPECT_LT(e.relativeTranslation, 1e-7);
    EXPECT_EQ(Size(3, 15), points3d.size());
    EXPECT_EQ(Size(6, 15), lines3d.size());
}

TEST(Tripose_MultiView, two_known_views_are_the_three_view_problem)
{
    // Noisy, so that the two must agree beyond exactness: the same rows, kernel and selection.
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = 12;
    params.numLines = 12;
    params.noiseSigma = 1.0;
    for (int seed = 1; seed <= 5; ++seed)
    {
        SCOPED_TRACE(cv::format("seed %d", seed));
        params.seed = seed;
        const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
        Mat R3, t3, R, t;
        ASSERT_GT(cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                 s.cameraMatrices, noArray(), s.R12, s.t12, R3, t3),
                  0);
        const std::vector<Mat> points = { s.points1, s.points2, s.points3 }, lines = { s.lines1, s.lines2, s.lines3 };
        const std::vector<Mat> Rs = { Mat::eye(3, 3, CV_64F), s.R12 }, ts = { Mat::zeros(3, 1, CV_64F), s.t12 };
        ASSERT_GT(cv::tripose::estimatePoseMultiView(points, lines, s.cameraMatrices, noArray(), Rs, ts, R, t), 0);
        EXPECT_LT(cv::norm(R, R3, NORM_INF), 1e-9);
        EXPECT_LT(cv::norm(t, t3, NORM_INF), 1e-9 * cv::norm(s.t12, NORM_L2));
    }
}

TEST(Tripose_MultiView, the_world_frame_is_arbitrary)
{
    // Moving the world frame moves every pose with it: the estimate follows to rounding.
    const MultiViewScene s(3, 10, 10, 5);
    Mat R, t;
    ASSERT_GT(cv::tripose::estimatePoseMultiView(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, R, t), 0);
    Mat G;
    Rodrigues(Mat(Vec3d(0.3, -1.2, 0.7)), G);
    const Mat g = (Mat_<double>(3, 1) << 1000, -2000, 500); // X = G^T (X' - g): new world X'
    std::vector<Mat> Rs, ts;
    for (size_t k = 0; k < s.Rs.size(); ++k)
    {
        Rs.push_back(s.Rs[k] * G.t());
        ts.push_back(s.ts[k] - s.Rs[k] * G.t() * g);
    }
    Mat R2, t2;
    ASSERT_GT(cv::tripose::estimatePoseMultiView(s.points, s.lines, s.K, noArray(), Rs, ts, R2, t2), 0);
    EXPECT_LT(cv::norm(R2, R * G.t(), NORM_INF), 1e-7);
    EXPECT_LT(cv::norm(t2, Mat(t - R * G.t() * g), NORM_INF), 1e-6 * cv::norm(g, NORM_L2));
}

TEST(Tripose_MultiView, bad_input_is_named)
{
    const MultiViewScene s(3, 6, 6, 9);
    Mat R, t;
    auto run = [&](const std::vector<Mat>& points, const std::vector<Mat>& lines, const std::vector<Mat>& Rs,
                   const std::vector<Mat>& ts) {
        return [=, &R, &t]() { cv::tripose::estimatePoseMultiView(points, lines, s.K, noArray(), Rs, ts, R, t); };
    };
    // One known view only.
    expectNamed(run({ s.points[0], s.points[3] }, { s.lines[0], s.lines[3] }, { s.Rs[0] }, { s.ts[0] }), "Rs");
    // ts not matching Rs.
    expectNamed(run(s.points, s.lines, s.Rs, { s.ts[0], s.ts[1] }), "ts");
    // One array too few.
    expectNamed(run({ s.points[0], s.points[1], s.points[3] }, s.lines, s.Rs, s.ts), "points");
    // A row count that differs.
    std::vector<Mat> shortLines = s.lines;
    shortLines[2] = shortLines[2].rowRange(0, 5).clone();
    expectNamed(run(s.points, shortLines, s.Rs, s.ts), "lines[2]");
    // A feature the new view does not see.
    std::vector<Mat> hidden = s.points;
    hidden[3] = hidden[3].clone();
    hidden[3].row(1).setTo(std::numeric_limits<double>::quiet_NaN());
    expectNamed(run(hidden, s.lines, s.Rs, s.ts), "points[3]");
    // A feature seen in one known view only.
    std::vector<Mat> once = s.lines;
    for (int v = 0; v < 3; ++v)
    {
        once[v] = once[v].clone();
        if (v > 0)
            once[v].row(2).setTo(std::numeric_limits<double>::quiet_NaN());
    }
    once[0].row(2).setTo(1.0); // seen only by view 0
    once[0].at<double>(2, 2) = 50;
    expectNamed(run(s.points, once, s.Rs, s.ts), "line 2");
    // A half-NaN row.
    std::vector<Mat> half = s.points;
    half[0] = half[0].clone();
    half[0].at<double>(0, 0) = std::numeric_limits<double>::quiet_NaN();
    half[0].at<double>(0, 1) = 1;
    expectNamed(run(half, s.lines, s.Rs, s.ts), "points[0]");
    // Every known view at one centre: nothing fixes the scale.
    std::vector<Mat> sameCentre = { s.ts[0], s.Rs[1] * s.Rs[0].t() * s.ts[0], s.Rs[2] * s.Rs[0].t() * s.ts[0] };
    expectNamed(run(s.points, s.lines, s.Rs, sameCentre), "ts");
    // A rotation that is not one.
    std::vector<Mat> badR = s.Rs;
    badR[1] = Mat(2 * s.Rs[1]); // a new header: the vector shares the scene's data
    expectNamed(run(s.points, s.lines, badR, s.ts), "Rs[1]");
    // Too few features.
    std::vector<Mat> p3, l0;
    for (const Mat& p : s.points)
        p3.push_back(p.rowRange(0, 3).clone());
    expectNamed(run(p3, l0, s.Rs, s.ts), "features");
}

TEST(Tripose_MultiView, degenerate_known_views_give_no_pose_not_nan)
{
    // Known view 1 moved to view 0's centre, its observations kept: the rows of a feature seen by
    // views 0 and 1 are those of zero baseline and fix nothing, and no pose fits all the data. The
    // features that known view 2 also sees still give candidates; the pose returned must be finite.
    MultiViewScene s(3, 8, 8, 11, 2);
    std::vector<Mat> Rs = s.Rs, ts = s.ts;
    ts[1] = Rs[1] * Rs[0].t() * ts[0]; // view 1 at view 0's centre
    Mat R, t;
    const int n = cv::tripose::estimatePoseMultiView(s.points, s.lines, s.K, noArray(), Rs, ts, R, t);
    ASSERT_GE(n, 1);
    EXPECT_TRUE(cv::checkRange(R));
    EXPECT_TRUE(cv::checkRange(t));
}

/** The views of @p s as one list for adjustPosesMultiView(): the known views, then the new one. */
struct AllViews
{
    std::vector<Mat> Rs, ts;
    explicit AllViews(const MultiViewScene& s) : Rs(s.Rs), ts(s.ts)
    {
        Rs.push_back(Mat(s.R));
        ts.push_back(Mat(s.t));
    }
};

TEST(Tripose_MultiView, several_poses_return_to_the_exact_poses)
{
    // Views 0 and 1 fixed, the other three known views and the new one moved off and refined
    // together: noise-free data, so the joint refinement returns every pose exactly.
    const MultiViewScene s(4, 20, 20, 31);
    const AllViews truth(s);
    std::vector<Mat> Rs, ts;
    RNG rng(3);
    for (size_t v = 0; v < truth.Rs.size(); ++v)
    {
        Mat rvec;
        Rodrigues(truth.Rs[v], rvec);
        Mat t = truth.ts[v].clone();
        if (v >= 2)
        {
            rvec += Mat(uniformInCube(rng, 0.02));
            t += Mat(uniformInCube(rng, 0.3));
        }
        Rs.push_back(rvec);
        ts.push_back(t);
    }
    const Mat fixed = (Mat_<uchar>(5, 1) << 1, 1, 0, 0, 0);
    Mat points3d, lines3d;
    const double rms = cv::tripose::adjustPosesMultiView(s.points, s.lines, s.K, noArray(), fixed, Rs, ts,
                                                         cv::tripose::RefineParams(), points3d, lines3d);
    EXPECT_LT(rms, 1e-6);
    ASSERT_EQ(5u, Rs.size());
    ASSERT_EQ(5u, ts.size());
    for (size_t v = 0; v < Rs.size(); ++v)
    {
        SCOPED_TRACE(cv::format("view %d", (int)v));
        const cv::tripose::support::PoseError e = poseError(Rs[v], ts[v], truth.Rs[v], truth.ts[v]);
        EXPECT_LT(e.rotationDeg, 1e-6);
        EXPECT_LT(e.relativeTranslation, 1e-7);
    }
    EXPECT_EQ(Size(3, 20), points3d.size());
    EXPECT_EQ(Size(6, 20), lines3d.size());
}

TEST(Tripose_MultiView, one_free_view_is_refinePoseMultiView)
{
    // With noise, so that the two must agree beyond exactness: the same cost and the same minimum.
    MultiViewScene s(3, 15, 15, 41);
    s.addNoise(1.0, 8);
    Mat rvec;
    Rodrigues(Mat(s.R), rvec);
    rvec += Mat(Vec3d(0.01, 0.0, -0.01));
    Mat t = Mat(s.t) + Mat(Vec3d(0.1, 0.2, -0.1));
    std::vector<Mat> Rs = s.Rs, ts = s.ts;
    Rs.push_back(rvec.clone());
    ts.push_back(t.clone());
    cv::tripose::RefineParams params;
    params.tolerance = 1e-14;
    const double single = cv::tripose::refinePoseMultiView(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, rvec, t, params);
    const Mat fixed = (Mat_<uchar>(4, 1) << 1, 1, 1, 0);
    const double joint = cv::tripose::adjustPosesMultiView(s.points, s.lines, s.K, noArray(), fixed, Rs, ts, params);
    EXPECT_NEAR(single, joint, 1e-9 * single);
    ASSERT_EQ(Size(3, 3), rvec.size()); // the refined rotation comes back as a matrix
    EXPECT_LT(cv::norm(Rs[3], rvec, NORM_INF), 1e-8);
    EXPECT_LT(cv::norm(ts[3], t, NORM_INF), 1e-8 * cv::norm(t, NORM_L2));
    for (int v = 0; v < 3; ++v) // as given, up to the rounding of reading a rotation as the nearest one
    {
        EXPECT_LT(cv::norm(Rs[v], s.Rs[v], NORM_INF), 1e-14);
        EXPECT_EQ(0, cv::norm(ts[v], s.ts[v], NORM_INF));
    }
}

TEST(Tripose_MultiView, several_poses_bad_input_is_named)
{
    const MultiViewScene s(3, 6, 6, 9);
    const AllViews all(s);
    std::vector<Mat> Rs, ts;
    auto run = [&](const std::vector<Mat>& points, const std::vector<Mat>& lines, const std::vector<Mat>& R,
                   const std::vector<Mat>& t, const Mat& fixed) {
        return [=, &Rs, &ts]() {
            Rs = R;
            ts = t;
            cv::tripose::adjustPosesMultiView(points, lines, s.K, noArray(), fixed, Rs, ts);
        };
    };
    const Mat twoFixed = (Mat_<uchar>(4, 1) << 1, 1, 0, 0);
    // Every view fixed: nothing to refine.
    expectNamed(run(s.points, s.lines, all.Rs, all.ts, Mat(4, 1, CV_8U, Scalar(1))), "fixedViews");
    // One fixed view: the scale is free.
    expectNamed(run(s.points, s.lines, all.Rs, all.ts, (Mat_<uchar>(4, 1) << 1, 0, 0, 0)), "fixedViews");
    // Two fixed views at one centre.
    std::vector<Mat> sameCentre = all.ts;
    sameCentre[1] = Mat(all.Rs[1] * all.Rs[0].t() * all.ts[0]); // a new header: the vector shares the scene's data
    expectNamed(run(s.points, s.lines, all.Rs, sameCentre, twoFixed), "fixedViews");
    // A mask of the wrong length or type.
    expectNamed(run(s.points, s.lines, all.Rs, all.ts, (Mat_<uchar>(3, 1) << 1, 1, 0)), "fixedViews");
    expectNamed(run(s.points, s.lines, all.Rs, all.ts, Mat(4, 1, CV_64F, Scalar(1))), "fixedViews");
    // ts not matching Rs, an array too few.
    expectNamed(run(s.points, s.lines, all.Rs, { all.ts[0], all.ts[1] }, twoFixed), "ts");
    expectNamed(run({ s.points[0], s.points[1], s.points[3] }, s.lines, all.Rs, all.ts, twoFixed), "points");
    // A feature seen by one view only.
    std::vector<Mat> once;
    for (int v = 0; v < 4; ++v)
    {
        once.push_back(s.points[v].clone());
        if (v != 3)
            once[v].row(4).setTo(std::numeric_limits<double>::quiet_NaN());
    }
    expectNamed(run(once, s.lines, all.Rs, all.ts, twoFixed), "point 4");
    // Bad refinement parameters.
    cv::tripose::RefineParams params;
    params.maxIterations = 0;
    expectNamed([&]() {
        Rs = all.Rs;
        ts = all.ts;
        cv::tripose::adjustPosesMultiView(s.points, s.lines, s.K, noArray(), twoFixed, Rs, ts, params);
    }, "maxIterations");
}

//! Tracks a VGG sequence as tripose_track does: frames 0 and 1 given, each later frame registered
//! (RANSAC + refinement) against the last @p window frames, on the features it shares with two of them.
double trackingDrift(const std::string& name, int window)
{
    const cv::tripose::support::VggSequence seq = cv::tripose::support::loadVggSequence(findDataDirectory("vgg/" + name));
    const int F = (int)seq.Rs.size();
    std::vector<Mat> Rs = { seq.Rs[0], seq.Rs[1] }, ts = { seq.ts[0], seq.ts[1] };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int k = 2; k < F; ++k)
    {
        const int first = std::max(0, k - window);
        std::vector<int> points, lines;
        for (int kind = 0; kind < 2; ++kind)
        {
            const std::vector<Mat>& rows = kind == 0 ? seq.points : seq.lines;
            for (int i = 0; i < rows[k].rows; ++i)
            {
                int count = 0;
                for (int w = first; w < k; ++w)
                    count += std::isnan(rows[w].at<double>(i, 0)) ? 0 : 1;
                if (!std::isnan(rows[k].at<double>(i, 0)) && count >= 2)
                    (kind == 0 ? points : lines).push_back(i);
            }
        }
        std::vector<Mat> p, l, K, knownR, knownT;
        for (int w = first; w <= k; ++w)
        {
            Mat pw((int)points.size(), 2, CV_64F, Scalar::all(nan)), lw((int)lines.size(), 4, CV_64F, Scalar::all(nan));
            for (size_t i = 0; i < points.size(); ++i)
                seq.points[w].row(points[i]).copyTo(pw.row((int)i));
            for (size_t i = 0; i < lines.size(); ++i)
                seq.lines[w].row(lines[i]).copyTo(lw.row((int)i));
            p.push_back(pw);
            l.push_back(lw);
            K.push_back(seq.cameraMatrices[w]);
            if (w < k)
            {
                knownR.push_back(Rs[w]);
                knownT.push_back(ts[w]);
            }
        }
        Mat R, t;
        EXPECT_GT(cv::tripose::estimatePoseMultiViewRansac(p, l, K, noArray(), knownR, knownT, R, t), 0) << "frame " << k;
        if (R.empty())
            return std::numeric_limits<double>::infinity();
        Rs.push_back(R);
        ts.push_back(t);
    }
    double path = 0;
    for (int k = 1; k < F; ++k)
        path += cv::norm(Mat(-seq.Rs[k].t() * seq.ts[k]), Mat(-seq.Rs[k - 1].t() * seq.ts[k - 1]), NORM_L2);
    const Mat estimated = -Rs[F - 1].t() * ts[F - 1], reference = -seq.Rs[F - 1].t() * seq.ts[F - 1];
    return 100 * cv::norm(estimated, reference, NORM_L2) / path;
}

TEST(Tripose_MultiView, tracks_model_house)
{
    // The window is tripose_track's default, 5 (its drift here: doc/studies/tracking.md). The bound leaves
    // half as much again for other OpenCV versions' rounding in RANSAC and refinement, and stays under
    // the 0.3 % the tracker is meant to reach on this sequence.
    const double drift = trackingDrift("Model-House", 5);
    EXPECT_LT(drift, 0.25);
}

} // namespace
} // namespace opencv_test
