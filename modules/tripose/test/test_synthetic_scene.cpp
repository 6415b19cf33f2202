// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::SyntheticScene;
using cv::tripose::support::SyntheticSceneParams;
using cv::tripose::support::generateSyntheticScene;

//! The three poses of a scene: view 1 = [I|0].
void scenePoses(const SyntheticScene& s, Matx33d R[3], Vec3d t[3])
{
    R[0] = Matx33d::eye();
    t[0] = Vec3d(0, 0, 0);
    R[1] = toMatx33(s.R12);
    t[1] = toVec3(s.t12);
    R[2] = toMatx33(s.R);
    t[2] = toVec3(s.t);
}

Point2d projectPoint(const Matx33d& K, const Matx33d& R, const Vec3d& t, const Vec3d& X, double* depth = nullptr)
{
    const Vec3d c = R * X + t;
    if (depth)
        *depth = c[2];
    const Vec3d p = K * c;
    return Point2d(p[0] / p[2], p[1] / p[2]);
}

//! Largest pixel distance between the observations and the projections of the 3D structure, over
//! the features whose mask entry (view 3 only) is set.
double maxReprojectionError(const SyntheticScene& s)
{
    Matx33d R[3];
    Vec3d t[3];
    scenePoses(s, R, t);
    const Mat* points[3] = { &s.points1, &s.points2, &s.points3 };
    const Mat* lines[3] = { &s.lines1, &s.lines2, &s.lines3 };
    double worst = 0;
    for (int v = 0; v < 3; ++v)
    {
        const Matx33d K = toMatx33(s.cameraMatrices[v]);
        for (int i = 0; i < s.points3d.rows; ++i)
        {
            if (v == 2 && !s.pointInliers.at<uchar>(i))
                continue;
            const Point2d x = projectPoint(K, R[v], t[v], Vec3d(s.points3d.ptr<double>(i)));
            worst = std::max(worst, cv::norm(x - Point2d(points[v]->at<double>(i, 0), points[v]->at<double>(i, 1))));
        }
        for (int i = 0; i < s.lines3d.rows; ++i)
        {
            if (v == 2 && !s.lineInliers.at<uchar>(i))
                continue;
            const double* L = s.lines3d.ptr<double>(i);
            const double* o = lines[v]->ptr<double>(i);
            const Point2d a = projectPoint(K, R[v], t[v], Vec3d(L[0], L[1], L[2]));
            const Point2d b = projectPoint(K, R[v], t[v], Vec3d(L[3], L[4], L[5]));
            worst = std::max(worst, cv::norm(a - Point2d(o[0], o[1])));
            worst = std::max(worst, cv::norm(b - Point2d(o[2], o[3])));
        }
    }
    return worst;
}

bool identicalScenes(const SyntheticScene& a, const SyntheticScene& b)
{
    bool same = identical(a.points1, b.points1) && identical(a.points2, b.points2) && identical(a.points3, b.points3) &&
                identical(a.lines1, b.lines1) && identical(a.lines2, b.lines2) && identical(a.lines3, b.lines3) &&
                identical(a.R12, b.R12) && identical(a.t12, b.t12) && identical(a.R, b.R) && identical(a.t, b.t) &&
                identical(a.points3d, b.points3d) && identical(a.lines3d, b.lines3d) &&
                identical(a.pointInliers, b.pointInliers) && identical(a.lineInliers, b.lineInliers) &&
                a.cameraMatrices.size() == b.cameraMatrices.size();
    for (size_t v = 0; same && v < a.cameraMatrices.size(); ++v)
        same = identical(a.cameraMatrices[v], b.cameraMatrices[v]);
    return same;
}

SyntheticSceneParams makeParams(int numPoints, int numLines, int motion, int seed)
{
    SyntheticSceneParams p;
    p.numPoints = numPoints;
    p.numLines = numLines;
    p.motion = motion;
    p.seed = seed;
    return p;
}

TEST(Tripose_SyntheticScene, defaults_follow_the_paper)
{
    const SyntheticSceneParams p;
    EXPECT_EQ(p.numPoints, 4);
    EXPECT_EQ(p.numLines, 4);
    EXPECT_EQ(p.motion, cv::tripose::support::MOTION_LARGE);
    EXPECT_EQ(p.noiseSigma, 0.0);
    EXPECT_EQ(p.outlierRatio, 0.0);
    EXPECT_EQ(p.cubeSize, 10.0);
    EXPECT_EQ(p.cameraDistance, 20.0);
    EXPECT_EQ(p.smallMotionRadius, 5.0);
    EXPECT_EQ(p.imageSize, Size(640, 480));
    EXPECT_TRUE(p.cameraMatrices.empty());
    EXPECT_EQ(p.seed, 0);

    const SyntheticScene s = generateSyntheticScene(p);
    ASSERT_EQ(s.cameraMatrices.size(), 3u);
    const Matx33d expectedK(800, 0, 319.5, 0, 800, 239.5, 0, 0, 1);
    for (int v = 0; v < 3; ++v)
        EXPECT_EQ(cv::norm(Mat(expectedK), s.cameraMatrices[v], NORM_INF), 0.0) << "view " << v + 1;
}

TEST(Tripose_SyntheticScene, shapes_and_types)
{
    const SyntheticScene s = generateSyntheticScene(makeParams(7, 5, cv::tripose::support::MOTION_LARGE, 3));
    for (const Mat* m : { &s.points1, &s.points2, &s.points3 })
    {
        EXPECT_EQ(m->size(), Size(2, 7));
        EXPECT_EQ(m->type(), CV_64F);
    }
    for (const Mat* m : { &s.lines1, &s.lines2, &s.lines3 })
    {
        EXPECT_EQ(m->size(), Size(4, 5));
        EXPECT_EQ(m->type(), CV_64F);
    }
    EXPECT_EQ(s.points3d.size(), Size(3, 7));
    EXPECT_EQ(s.lines3d.size(), Size(6, 5));
    EXPECT_EQ(s.pointInliers.size(), Size(1, 7));
    EXPECT_EQ(s.lineInliers.size(), Size(1, 5));
    EXPECT_EQ(s.pointInliers.type(), CV_8U);
    EXPECT_EQ(s.lineInliers.type(), CV_8U);
    EXPECT_EQ(s.R12.size(), Size(3, 3));
    EXPECT_EQ(s.t12.size(), Size(1, 3));
    EXPECT_EQ(s.R.size(), Size(3, 3));
    EXPECT_EQ(s.t.size(), Size(1, 3));

    // Points only and lines only keep the other kind's column count.
    const SyntheticScene pointsOnly = generateSyntheticScene(makeParams(3, 0, cv::tripose::support::MOTION_SMALL, 1));
    EXPECT_EQ(pointsOnly.lines1.size(), Size(4, 0));
    EXPECT_EQ(pointsOnly.lines3d.size(), Size(6, 0));
    const SyntheticScene linesOnly = generateSyntheticScene(makeParams(0, 3, cv::tripose::support::MOTION_SMALL, 1));
    EXPECT_EQ(linesOnly.points3.size(), Size(2, 0));
    EXPECT_EQ(linesOnly.points3d.size(), Size(3, 0));
}

TEST(Tripose_SyntheticScene, poses_are_proper_rotations)
{
    for (int seed = 0; seed < 50; ++seed)
        for (int motion : { cv::tripose::support::MOTION_LARGE, cv::tripose::support::MOTION_SMALL })
        {
            const SyntheticScene s = generateSyntheticScene(makeParams(1, 0, motion, seed));
            for (const Mat* R : { &s.R12, &s.R })
            {
                const Matx33d r = toMatx33(*R);
                EXPECT_LT(cv::norm(r.t() * r - Matx33d::eye(), NORM_INF), 1e-12);
                EXPECT_NEAR(cv::determinant(r), 1.0, 1e-12);
            }
        }
}

// Every feature, before noise, lies inside every image (with the margin) and in front of every camera.
TEST(Tripose_SyntheticScene, features_project_inside_the_images_and_in_front)
{
    for (int motion : { cv::tripose::support::MOTION_LARGE, cv::tripose::support::MOTION_SMALL })
        for (int seed = 0; seed < 40; ++seed)
        {
            const SyntheticScene s = generateSyntheticScene(makeParams(20, 20, motion, seed));
            Matx33d R[3];
            Vec3d t[3];
            scenePoses(s, R, t);
            for (int v = 0; v < 3; ++v)
            {
                const Matx33d K = toMatx33(s.cameraMatrices[v]);
                auto check = [&](const Vec3d& X, const char* what, int i) {
                    double depth = 0;
                    const Point2d x = projectPoint(K, R[v], t[v], X, &depth);
                    EXPECT_GT(depth, 0) << what << " " << i << " view " << v + 1 << " seed " << seed;
                    EXPECT_TRUE(x.x >= 0 && x.x <= 639 && x.y >= 0 && x.y <= 479)
                        << what << " " << i << " view " << v + 1 << " seed " << seed << " at " << x;
                };
                for (int i = 0; i < s.points3d.rows; ++i)
                    check(Vec3d(s.points3d.ptr<double>(i)), "point", i);
                for (int i = 0; i < s.lines3d.rows; ++i)
                {
                    const double* L = s.lines3d.ptr<double>(i);
                    check(Vec3d(L[0], L[1], L[2]), "segment start", i);
                    check(Vec3d(L[3], L[4], L[5]), "segment end", i);
                    const Point2d a = projectPoint(K, R[v], t[v], Vec3d(L[0], L[1], L[2]));
                    const Point2d b = projectPoint(K, R[v], t[v], Vec3d(L[3], L[4], L[5]));
                    EXPECT_GE(cv::norm(b - a), 20.0) << "segment " << i << " view " << v + 1;
                }
            }
        }
}

TEST(Tripose_SyntheticScene, noise_free_observations_reproject_exactly)
{
    double worst = 0;
    for (int motion : { cv::tripose::support::MOTION_LARGE, cv::tripose::support::MOTION_SMALL })
        for (int seed = 0; seed < 100; ++seed)
            worst = std::max(worst, maxReprojectionError(generateSyntheticScene(makeParams(10, 10, motion, seed))));
    EXPECT_LT(worst, 1e-9);
}

TEST(Tripose_SyntheticScene, same_seed_same_scene_different_seed_different_scene)
{
    SyntheticSceneParams p = makeParams(6, 6, cv::tripose::support::MOTION_LARGE, 1234);
    p.noiseSigma = 1.0;
    p.outlierRatio = 0.3;
    const SyntheticScene a = generateSyntheticScene(p);
    const SyntheticScene b = generateSyntheticScene(p);
    EXPECT_TRUE(identicalScenes(a, b));

    p.seed = 1235;
    const SyntheticScene c = generateSyntheticScene(p);
    EXPECT_GT(cv::norm(a.R, c.R, NORM_INF), 1e-3);
    EXPECT_GT(cv::norm(a.points3d, c.points3d, NORM_INF), 1e-3);
    EXPECT_GT(cv::norm(a.lines1, c.lines1, NORM_INF), 1e-3);

    // Negative seeds are valid and distinct from their absolute value.
    p.seed = -1234;
    EXPECT_GT(cv::norm(a.R, generateSyntheticScene(p).R, NORM_INF), 1e-3);
}

// Independent random streams: noise does not move the geometry, and the number of lines does not
// change the points (so sweeps over one parameter compare like with like).
TEST(Tripose_SyntheticScene, parameters_sweep_over_the_same_geometry)
{
    SyntheticSceneParams p = makeParams(5, 5, cv::tripose::support::MOTION_LARGE, 77);
    const SyntheticScene clean = generateSyntheticScene(p);
    p.noiseSigma = 2.0;
    const SyntheticScene noisy = generateSyntheticScene(p);
    EXPECT_TRUE(identical(clean.points3d, noisy.points3d));
    EXPECT_TRUE(identical(clean.lines3d, noisy.lines3d));
    EXPECT_TRUE(identical(clean.R, noisy.R));
    EXPECT_TRUE(identical(clean.t12, noisy.t12));
    EXPECT_GT(cv::norm(clean.points2, noisy.points2, NORM_INF), 0.0);

    p.noiseSigma = 0;
    p.numLines = 9;
    const SyntheticScene moreLines = generateSyntheticScene(p);
    EXPECT_TRUE(identical(clean.points3d, moreLines.points3d));
    EXPECT_TRUE(identical(clean.lines3d, moreLines.lines3d.rowRange(0, 5)));
}

// All three views look at the cube centre c, which is therefore on the optical axis of view 1 at
// depth cameraDistance: c = (0, 0, d) in the frame of view 1.
TEST(Tripose_SyntheticScene, camera_placement_follows_the_motion_regime)
{
    const double d = 20, radius = 5, halfDiagonal = 5 * std::sqrt(3.0);
    const Vec3d centre(0, 0, d);
    double largestSmallMotion = 0;
    for (int seed = 0; seed < 200; ++seed)
    {
        for (int motion : { cv::tripose::support::MOTION_LARGE, cv::tripose::support::MOTION_SMALL })
        {
            const SyntheticScene s = generateSyntheticScene(makeParams(4, 4, motion, seed));
            Matx33d R[3];
            Vec3d t[3];
            scenePoses(s, R, t);
            for (int v = 1; v < 3; ++v)
            {
                const Vec3d c = R[v] * centre + t[v];   // cube centre seen from view v
                EXPECT_LT(std::abs(c[0]) + std::abs(c[1]), 1e-9) << "view " << v + 1 << " does not look at the cube centre";
                const Vec3d cameraCentre = -(R[v].t() * t[v]); // in the frame of view 1
                if (motion == cv::tripose::support::MOTION_LARGE)
                    EXPECT_NEAR(c[2], d, 1e-9) << "view " << v + 1 << " seed " << seed;
                else
                {
                    EXPECT_LE(cv::norm(cameraCentre), radius + 1e-9) << "view " << v + 1 << " seed " << seed;
                    largestSmallMotion = std::max(largestSmallMotion, cv::norm(cameraCentre));
                }
            }
            for (int i = 0; i < s.points3d.rows; ++i)
                EXPECT_LE(cv::norm(Vec3d(s.points3d.ptr<double>(i)) - centre), halfDiagonal + 1e-9);
            for (int i = 0; i < s.lines3d.rows; ++i)
            {
                const double* L = s.lines3d.ptr<double>(i);
                EXPECT_LE(cv::norm(Vec3d(L[0], L[1], L[2]) - centre), halfDiagonal + 1e-9);
                EXPECT_LE(cv::norm(Vec3d(L[3], L[4], L[5]) - centre), halfDiagonal + 1e-9);
            }
        }
    }
    // The small-motion positions fill the ball rather than collapsing onto view 1.
    EXPECT_GT(largestSmallMotion, 0.8 * radius);
}

// The perturbation of each coordinate is N(0, sigma^2): with n = 3 views * (2 * 300 + 4 * 300)
// coordinates = 5400 samples, the sample std has a relative standard error of 1/sqrt(2n) ~ 1%;
// a +-5% band is 5 standard errors wide. The mean is within 5 sigma/sqrt(n).
TEST(Tripose_SyntheticScene, noise_has_the_requested_standard_deviation)
{
    const double sigma = 1.5;
    SyntheticSceneParams p = makeParams(300, 300, cv::tripose::support::MOTION_LARGE, 5);
    const SyntheticScene clean = generateSyntheticScene(p);
    p.noiseSigma = sigma;
    const SyntheticScene noisy = generateSyntheticScene(p);
    std::vector<double> diffs;
    const Mat* c[6] = { &clean.points1, &clean.points2, &clean.points3, &clean.lines1, &clean.lines2, &clean.lines3 };
    const Mat* n[6] = { &noisy.points1, &noisy.points2, &noisy.points3, &noisy.lines1, &noisy.lines2, &noisy.lines3 };
    for (int k = 0; k < 6; ++k)
    {
        const Mat d = *n[k] - *c[k];
        for (size_t j = 0; j < d.total(); ++j)
            diffs.push_back(d.ptr<double>()[j]);
    }
    ASSERT_EQ(diffs.size(), 5400u);
    double mean = 0, sq = 0;
    for (double x : diffs)
        mean += x;
    mean /= (double)diffs.size();
    for (double x : diffs)
        sq += (x - mean) * (x - mean);
    const double stdev = std::sqrt(sq / (double)(diffs.size() - 1));
    EXPECT_NEAR(stdev, sigma, 0.05 * sigma);
    EXPECT_LT(std::abs(mean), 5 * sigma / std::sqrt((double)diffs.size()));
}

TEST(Tripose_SyntheticScene, outliers_have_the_requested_count_and_are_marked)
{
    struct Case { int n; double ratio; int expected; };
    for (const Case& c : { Case{ 10, 0.3, 3 }, Case{ 7, 0.5, 4 }, Case{ 20, 0.0, 0 }, Case{ 4, 0.9, 4 }, Case{ 3, 0.1, 0 } })
    {
        SyntheticSceneParams p = makeParams(c.n, c.n, cv::tripose::support::MOTION_LARGE, 9);
        p.outlierRatio = c.ratio;
        const SyntheticScene s = generateSyntheticScene(p);
        p.outlierRatio = 0;
        const SyntheticScene truth = generateSyntheticScene(p);
        EXPECT_EQ(c.n - cv::countNonZero(s.pointInliers), c.expected) << "ratio " << c.ratio;
        EXPECT_EQ(c.n - cv::countNonZero(s.lineInliers), c.expected) << "ratio " << c.ratio;

        // Views 1 and 2 are untouched; view 3 changes exactly where the mask says.
        EXPECT_TRUE(identical(s.points1, truth.points1));
        EXPECT_TRUE(identical(s.lines2, truth.lines2));
        for (int i = 0; i < c.n; ++i)
        {
            const Point2d x(s.points3.at<double>(i, 0), s.points3.at<double>(i, 1));
            const Point2d x0(truth.points3.at<double>(i, 0), truth.points3.at<double>(i, 1));
            if (s.pointInliers.at<uchar>(i))
                EXPECT_EQ(cv::norm(x - x0), 0.0);
            else
            {
                EXPECT_GE(cv::norm(x - x0), 20.0) << "point outlier " << i << " is consistent with the truth";
                EXPECT_TRUE(x.x >= 0 && x.x <= 639 && x.y >= 0 && x.y <= 479);
            }
            const double* o = s.lines3.ptr<double>(i);
            const double* o0 = truth.lines3.ptr<double>(i);
            if (s.lineInliers.at<uchar>(i))
                EXPECT_EQ(cv::norm(s.lines3.row(i), truth.lines3.row(i), NORM_INF), 0.0);
            else
            {
                // Largest end-point distance to the true image line.
                const Point2d a(o0[0], o0[1]), b(o0[2], o0[3]), d = b - a;
                const double da = std::abs(d.cross(Point2d(o[0], o[1]) - a)) / cv::norm(d);
                const double db = std::abs(d.cross(Point2d(o[2], o[3]) - a)) / cv::norm(d);
                EXPECT_GE(std::max(da, db), 20.0) << "line outlier " << i << " is consistent with the truth";
            }
        }
        EXPECT_LT(maxReprojectionError(s), 1e-9) << "inliers must stay exact";
    }
}

TEST(Tripose_SyntheticScene, outliers_are_chosen_at_random)
{
    // Over many seeds, every index is an outlier sometimes (no fixed subset).
    std::vector<int> hits(10, 0);
    for (int seed = 0; seed < 100; ++seed)
    {
        SyntheticSceneParams p = makeParams(10, 0, cv::tripose::support::MOTION_LARGE, seed);
        p.outlierRatio = 0.3;
        const SyntheticScene s = generateSyntheticScene(p);
        for (int i = 0; i < 10; ++i)
            hits[i] += !s.pointInliers.at<uchar>(i);
    }
    for (int i = 0; i < 10; ++i)
        EXPECT_GT(hits[i], 10) << "index " << i; // expected 30 of 100
}

TEST(Tripose_SyntheticScene, per_view_intrinsics_are_honoured)
{
    SyntheticSceneParams p = makeParams(15, 15, cv::tripose::support::MOTION_SMALL, 21);
    p.imageSize = Size(1024, 768);
    p.cameraMatrices = { Mat(Matx33d(700, 0, 500, 0, 720, 380, 0, 0, 1)),
                         Mat(Matx33d(1200, 0.5, 530, 0, 1190, 400, 0, 0, 1)),
                         Mat(Matx33d(2 * 950, 0, 2 * 511.5, 0, 2 * 950, 2 * 383.5, 0, 0, 2)) }; // scaled: normalised
    const SyntheticScene s = generateSyntheticScene(p);
    ASSERT_EQ(s.cameraMatrices.size(), 3u);
    EXPECT_EQ(cv::norm(s.cameraMatrices[0], p.cameraMatrices[0], NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(s.cameraMatrices[1], p.cameraMatrices[1], NORM_INF), 0.0);
    EXPECT_LT(cv::norm(s.cameraMatrices[2], Mat(Matx33d(950, 0, 511.5, 0, 950, 383.5, 0, 0, 1)), NORM_INF), 1e-12);
    EXPECT_LT(maxReprojectionError(s), 1e-9);
    for (const Mat* m : { &s.points1, &s.points2, &s.points3 })
        for (int i = 0; i < m->rows; ++i)
            EXPECT_TRUE(m->at<double>(i, 0) <= 1023 && m->at<double>(i, 1) <= 767);

    // One matrix is shared by the three views; a CV_32F input is accepted.
    Mat K32;
    Mat(Matx33d(640, 0, 512, 0, 640, 384, 0, 0, 1)).convertTo(K32, CV_32F);
    p.cameraMatrices = { K32 };
    const SyntheticScene shared = generateSyntheticScene(p);
    for (int v = 0; v < 3; ++v)
    {
        EXPECT_EQ(shared.cameraMatrices[v].type(), CV_64F);
        EXPECT_EQ(cv::norm(shared.cameraMatrices[v], Mat(Matx33d(640, 0, 512, 0, 640, 384, 0, 0, 1)), NORM_INF), 0.0);
    }
    EXPECT_LT(maxReprojectionError(shared), 1e-9);
}

void expectBadParam(const SyntheticSceneParams& p, const std::string& name)
{
    try
    {
        generateSyntheticScene(p);
        ADD_FAILURE() << "no exception for a bad " << name;
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(e.msg.find(name), std::string::npos) << "message does not name " << name << ": " << e.msg;
    }
}

TEST(Tripose_SyntheticScene, bad_parameters_throw_naming_the_parameter)
{
    SyntheticSceneParams p;
    p.numPoints = -1;
    expectBadParam(p, "numPoints");
    p = SyntheticSceneParams();
    p.numLines = -2;
    expectBadParam(p, "numLines");
    p = SyntheticSceneParams();
    p.motion = 2;
    expectBadParam(p, "motion");
    p = SyntheticSceneParams();
    p.noiseSigma = -0.1;
    expectBadParam(p, "noiseSigma");
    p.noiseSigma = std::numeric_limits<double>::quiet_NaN();
    expectBadParam(p, "noiseSigma");
    p = SyntheticSceneParams();
    p.outlierRatio = 1.0;
    expectBadParam(p, "outlierRatio");
    p.outlierRatio = -0.01;
    expectBadParam(p, "outlierRatio");
    p = SyntheticSceneParams();
    p.cubeSize = 0;
    expectBadParam(p, "cubeSize");
    p = SyntheticSceneParams();
    p.cameraDistance = 8.0; // inside the cube's circumscribed sphere (half diagonal 8.66)
    expectBadParam(p, "cameraDistance");
    p = SyntheticSceneParams();
    p.smallMotionRadius = -1;
    expectBadParam(p, "smallMotionRadius");
    p = SyntheticSceneParams();
    p.motion = cv::tripose::support::MOTION_SMALL;
    p.smallMotionRadius = 12; // could bring views 2, 3 into the cube
    expectBadParam(p, "smallMotionRadius");
    p = SyntheticSceneParams();
    p.imageSize = Size(0, 480);
    expectBadParam(p, "imageSize");
    p = SyntheticSceneParams();
    p.cameraMatrices = { Mat::eye(3, 3, CV_64F), Mat::eye(3, 3, CV_64F) };
    expectBadParam(p, "cameraMatrices");
    p.cameraMatrices = { Mat::eye(3, 4, CV_64F) };
    expectBadParam(p, "cameraMatrices[0]");
    p.cameraMatrices = { Mat(Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 1)),
                         Mat(Matx33d(800, 0, 320, 0, std::numeric_limits<double>::infinity(), 240, 0, 0, 1)),
                         Mat(Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 1)) };
    expectBadParam(p, "cameraMatrices[1]");
    p.cameraMatrices = { Mat(Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 1)), Mat(Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 1)),
                         Mat(Matx33d(800, 0, 320, 0, 800, 240, 0.1, 0, 1)) };
    expectBadParam(p, "cameraMatrices[2]");
    p.cameraMatrices = { Mat(Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 0)) };
    expectBadParam(p, "cameraMatrices[0]");
}

// The generator checks of the intrinsics only what projecting needs; which intrinsics the estimators
// accept is theirs to check, on scenes made with any camera.
TEST(Tripose_SyntheticScene, intrinsics_the_estimators_reject_still_make_scenes)
{
    SyntheticSceneParams p = makeParams(6, 6, cv::tripose::support::MOTION_LARGE, 8);
    const Matx33d mirrored(800, 0, 319.5, 0, -800, 239.5, 0, 0, 1); // negative focal length: y flipped
    p.cameraMatrices = { Mat(mirrored) };
    const SyntheticScene s = generateSyntheticScene(p);
    EXPECT_EQ(cv::norm(s.cameraMatrices[2], Mat(mirrored), NORM_INF), 0.0);
    EXPECT_LT(maxReprojectionError(s), 1e-9);
    Mat R, t;
    try
    {
        cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3, s.cameraMatrices,
                                       noArray(), s.R12, s.t12, R, t);
        ADD_FAILURE() << "the estimator accepted a negative focal length";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(e.msg.find("cameraMatrix"), std::string::npos) << e.msg;
    }
}

// Parameters under which no feature can be placed fail with a clear message instead of looping.
TEST(Tripose_SyntheticScene, infeasible_parameters_throw_instead_of_looping)
{
    SyntheticSceneParams p;
    p.numPoints = 1;
    p.numLines = 0;
    // Principal point far outside the image: the cube centre projects 5000 px away.
    p.cameraMatrices = { Mat(Matx33d(800, 0, 5000, 0, 800, 5000, 0, 0, 1)) };
    EXPECT_THROW(generateSyntheticScene(p), cv::Exception);

    // A 12x12 image cannot hold a 20 px segment.
    p = SyntheticSceneParams();
    p.numPoints = 0;
    p.numLines = 1;
    p.imageSize = Size(12, 12);
    EXPECT_THROW(generateSyntheticScene(p), cv::Exception);
}

// No shared state: scenes generated concurrently equal the ones generated one after the other.
TEST(Tripose_SyntheticScene, concurrent_generation_is_deterministic)
{
    const int count = 64;
    std::vector<SyntheticScene> serial(count), parallel(count);
    auto params = [](int i) {
        SyntheticSceneParams p = makeParams(5 + i % 7, 3 + i % 5, i % 2, 1000 + i);
        p.noiseSigma = 0.5 * (i % 3);
        p.outlierRatio = 0.2;
        return p;
    };
    for (int i = 0; i < count; ++i)
        serial[i] = generateSyntheticScene(params(i));
    parallel_for_(Range(0, count), [&](const Range& r) {
        for (int i = r.start; i < r.end; ++i)
            parallel[i] = generateSyntheticScene(params(i));
    });
    for (int i = 0; i < count; ++i)
        EXPECT_TRUE(identicalScenes(serial[i], parallel[i])) << "scene " << i;
}

TEST(Tripose_SyntheticScene, large_scenes_are_generated)
{
    SyntheticSceneParams p = makeParams(2000, 2000, cv::tripose::support::MOTION_SMALL, 4);
    p.noiseSigma = 0.5;
    p.outlierRatio = 0.5;
    const SyntheticScene s = generateSyntheticScene(p);
    EXPECT_EQ(s.points3.rows, 2000);
    EXPECT_EQ(cv::countNonZero(s.lineInliers), 1000);
}

}} // namespace opencv_test::namespace
