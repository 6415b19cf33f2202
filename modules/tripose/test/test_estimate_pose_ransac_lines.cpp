// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

#include <numeric>

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/linear/linear_pose_solver.hpp"
#include "../src/core/pipeline/pose_pipelines.hpp"
#include "../src/core/robust/hybrid_pose_solver.hpp"

namespace opencv_test {
namespace {

// Line-dominated sets with half of the view-3 matches wrong: the robust estimator's samples are then
// mostly lines (three lines, a point and two lines), on the lines triangulated from views 1-2.

int runRansac(const cv::tripose::support::SyntheticScene& s, int seed, Mat& R, Mat& t, double threshold = 2.0,
              Mat* pointMask = nullptr, Mat* lineMask = nullptr)
{
    cv::tripose::RansacParams params;
    params.seed = seed;
    params.threshold = threshold;
    Mat points, lines;
    return cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                    s.cameraMatrices, noArray(), s.R12, s.t12, R, t, params,
                                                    pointMask ? *pointMask : points, lineMask ? *lineMask : lines);
}

bool sameMask(const Mat& a, const Mat& b)
{
    return a.total() == b.total() && (a.empty() || cv::countNonZero(a.reshape(1, 1) != b.reshape(1, 1)) == 0);
}

//! The rows of @p m where @p mask is non-zero.
Mat rowsWhere(const Mat& m, const Mat& mask)
{
    Mat out;
    for (int i = 0; i < m.rows; ++i)
        if (mask.at<uchar>(i))
            out.push_back(m.row(i));
    return out.empty() ? Mat(0, m.cols, m.type()) : out;
}

//! Rotation error (deg) of the maximum-likelihood refinement from the truth on the true matches: the
//! accuracy an estimator can reach on the scene.
double mlRotationErrorDeg(const cv::tripose::support::SyntheticScene& s)
{
    Mat R = s.R.clone(), t = s.t.clone();
    const Mat& pm = s.pointInliers;
    const Mat& lm = s.lineInliers;
    cv::tripose::refinePoseLinePoint(rowsWhere(s.points1, pm), rowsWhere(s.points2, pm), rowsWhere(s.points3, pm),
                                     rowsWhere(s.lines1, lm), rowsWhere(s.lines2, lm), rowsWhere(s.lines3, lm),
                                     s.cameraMatrices, noArray(), s.R12, s.t12, R, t);
    return poseError(R, t, s.R, s.t).rotationDeg;
}

const FeatureMix kLineHeavy[] = { { 0, 60 }, { 3, 60 }, { 10, 100 } };

// Noise-free, half of the matches wrong, threshold 0.5 px: the pose to rounding wherever the inliers
// found are the true matches; a few wrong matches fall within the threshold by chance (then the
// estimate is the optimum over them too, hundredths of a degree away).
TEST(Tripose_RansacLineHeavy, noise_free_scenes_with_half_wrong_matches_are_exact)
{
    for (const FeatureMix& mix : kLineHeavy)
    {
        int exact = 0;
        const int trials = 20;
        for (int seed = 0; seed < trials; ++seed)
        {
            const cv::tripose::support::SyntheticScene s = makeScene(mix, cv::tripose::support::MOTION_LARGE, 0.0, seed, 0.5);
            Mat R, t, pointMask, lineMask;
            ASSERT_GT(runRansac(s, seed, R, t, 0.5, &pointMask, &lineMask), 0) << mixName(mix) << " seed " << seed;
            const PoseError e = poseError(R, t, s.R, s.t);
            const bool masksRight = sameMask(pointMask, s.pointInliers) && sameMask(lineMask, s.lineInliers);
            if (masksRight)
            {
                EXPECT_LT(e.rotationDeg, degrees(1e-6)) << mixName(mix) << " seed " << seed;
                EXPECT_LT(e.relativeTranslation, 1e-6) << mixName(mix) << " seed " << seed;
            }
            else
                EXPECT_LT(e.rotationDeg, 0.1) << mixName(mix) << " seed " << seed;
            exact += masksRight && e.rotationDeg < degrees(1e-6);
        }
        std::cout << mixName(mix) << ", 50 % wrong, noise-free: inliers right and pose exact " << exact << "/"
                  << trials << std::endl;
        EXPECT_GE(exact, 15) << mixName(mix);
    }
}

// 1 px noise, half of the matches wrong: near the maximum-likelihood estimate from the truth on the true
// matches in nearly every scene.
TEST(Tripose_RansacLineHeavy, one_pixel_noise_with_half_wrong_matches_is_near_the_ml_limit)
{
    for (const FeatureMix& mix : kLineHeavy)
    {
        const int trials = 30;
        int near = 0;
        std::vector<double> errors, limits;
        for (int seed = 0; seed < trials; ++seed)
        {
            const cv::tripose::support::SyntheticScene s =
                makeScene(mix, cv::tripose::support::MOTION_LARGE, 1.0, 1000 + seed, 0.5);
            Mat R, t;
            ASSERT_GT(runRansac(s, seed, R, t), 0) << mixName(mix) << " seed " << seed;
            const double error = poseError(R, t, s.R, s.t).rotationDeg;
            const double limit = mlRotationErrorDeg(s);
            errors.push_back(error);
            limits.push_back(limit);
            near += error <= 1.5 * limit + 0.05;
        }
        std::sort(errors.begin(), errors.end());
        std::sort(limits.begin(), limits.end());
        std::cout << mixName(mix) << ", 50 % wrong, 1 px: within 1.5 x ML + 0.05 deg " << near << "/" << trials
                  << ", median rotation error " << errors[trials / 2] << " deg (ML from the truth "
                  << limits[trials / 2] << ")" << std::endl;
        EXPECT_GE(near, trials - 1) << mixName(mix);
        EXPECT_LT(errors[trials / 2], 1.2 * limits[trials / 2] + 0.01) << mixName(mix);
    }
}

//! Shifts the view-3 observations of @p m by one row: every match wrong.
Mat everyMatchWrong(const Mat& m)
{
    Mat out(m.size(), m.type());
    for (int i = 0; i < m.rows; ++i)
        m.row((i + 1) % m.rows).copyTo(out.row(i));
    return out;
}

::tripose::RobustEstimate robustEstimate(const cv::tripose::support::SyntheticScene& s, const Mat& points3,
                                         const Mat& lines3, ::tripose::HybridPoseSolver::Sampling& sampling)
{
    const ::tripose::ViewSet views = cv::tripose::detail::readThreeViewInput(
        s.points1, s.points2, points3, s.lines1, s.lines2, lines3, s.cameraMatrices, noArray(), s.R12, s.t12);
    const ::tripose::PoseScorer scorer(views);
    const ::tripose::LinearPoseSolver linear(views);
    const ::tripose::HybridPoseSolver solver(views, scorer, linear);
    sampling = solver.sampling();
    ::tripose::RansacOptions options;
    options.refine = false;
    ::tripose::RobustEstimate estimate;
    ::tripose::estimateRobust(views, scorer, solver, options, estimate);
    return estimate;
}

// The kind of each sample follows the matches that hold. 100 points and 100 lines, half of each kind
// wrong, then every match of one kind wrong: once a model has support, the samples are nearly all of
// the other kind (three points, or three lines), and their number stays near the three-feature bound
// at 50 % inliers (54 samples drawn without replacement, confidence 0.999) plus the uniform draws
// before the first good model. Choosing the kinds regardless of the inlier ratios would draw a
// quarter of the samples of the kind that holds and four times as many in all. The samples are
// counted in the order of the solver's kinds: P3P, P2P1L, P1P2L, P3L.
TEST(Tripose_RansacLineHeavy, samples_follow_the_matches_that_hold)
{
    std::vector<int> linesWrongSamples, pointsWrongSamples;
    int p3p = 0, p3l = 0;
    for (int seed = 0; seed < 10; ++seed)
    {
        const cv::tripose::support::SyntheticScene s =
            makeScene(FeatureMix{ 100, 100 }, cv::tripose::support::MOTION_LARGE, 1.0, seed, 0.5);
        ::tripose::HybridPoseSolver::Sampling sampling;
        const ::tripose::RobustEstimate linesWrong = robustEstimate(s, s.points3, everyMatchWrong(s.lines3), sampling);
        ASSERT_EQ(::tripose::HybridPoseSolver::Sampling::Mixed, sampling);
        ASSERT_EQ(4u, linesWrong.samplesOfKind.size());
        const ::tripose::RobustEstimate pointsWrong = robustEstimate(s, everyMatchWrong(s.points3), s.lines3, sampling);
        ASSERT_EQ(4u, pointsWrong.samplesOfKind.size());
        linesWrongSamples.push_back(linesWrong.iterations);
        pointsWrongSamples.push_back(pointsWrong.iterations);
        p3p += linesWrong.samplesOfKind[0];
        p3l += pointsWrong.samplesOfKind[3];
    }
    const int linesWrongTotal = std::accumulate(linesWrongSamples.begin(), linesWrongSamples.end(), 0);
    const int pointsWrongTotal = std::accumulate(pointsWrongSamples.begin(), pointsWrongSamples.end(), 0);
    std::cout << "every line match wrong: " << p3p << " of " << linesWrongTotal << " samples P3P, median "
              << median(linesWrongSamples) << " samples; every point match wrong: " << p3l << " of " << pointsWrongTotal
              << " P3L, median " << median(pointsWrongSamples) << std::endl;
    EXPECT_GT(p3p, 0.65 * linesWrongTotal);
    EXPECT_GT(p3l, 0.65 * pointsWrongTotal);
    EXPECT_LT(median(linesWrongSamples), 120);
    EXPECT_LT(median(pointsWrongSamples), 120);
}

// Line-dominated: 10 points and 100 lines, half of each wrong. Samples with two or three lines are most
// of them, and the samples stay below the four-feature bound (108 at 50 % inliers, confidence 0.999).
TEST(Tripose_RansacLineHeavy, line_dominated_sets_draw_line_samples)
{
    int lineSamples = 0, samples = 0;
    std::vector<int> iterations;
    for (int seed = 0; seed < 10; ++seed)
    {
        const cv::tripose::support::SyntheticScene s =
            makeScene(FeatureMix{ 10, 100 }, cv::tripose::support::MOTION_LARGE, 1.0, seed, 0.5);
        ::tripose::HybridPoseSolver::Sampling sampling;
        const ::tripose::RobustEstimate e = robustEstimate(s, s.points3, s.lines3, sampling);
        ASSERT_EQ(::tripose::HybridPoseSolver::Sampling::Mixed, sampling);
        ASSERT_EQ(4u, e.samplesOfKind.size());
        lineSamples += e.samplesOfKind[2] + e.samplesOfKind[3];
        samples += e.iterations;
        iterations.push_back(e.iterations);
    }
    std::cout << "10P+100L, 50 % wrong: " << lineSamples << " of " << samples
              << " samples with two or three lines, median " << median(iterations) << " samples" << std::endl;
    EXPECT_GT(lineSamples, samples / 2);
    EXPECT_LT(median(iterations), 108);
}

} // namespace
} // namespace opencv_test
