// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/linear/linear_pose_solver.hpp"
#include "../src/core/robust/hybrid_pose_solver.hpp"
#include "../src/core/scoring/pose_scorer.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::FeatureSubset;
using ::tripose::HybridPoseSolver;
using ::tripose::LinearPoseSolver;
using ::tripose::PoseScorer;
using ::tripose::ViewSet;

cv::tripose::support::SyntheticScene scene(int points, int lines, int motion, double smallMotionRadius, int seed)
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = points;
    params.numLines = lines;
    params.motion = motion;
    params.smallMotionRadius = smallMotionRadius;
    params.noiseSigma = 0.0;
    params.seed = seed;
    return cv::tripose::support::generateSyntheticScene(params);
}

ViewSet readScene(const cv::tripose::support::SyntheticScene& s)
{
    return cv::tripose::detail::readThreeViewInput(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                               s.cameraMatrices, noArray(), s.R12, s.t12);
}

// Wide baselines with enough points: three-point samples, and on noise-free structure the true pose is
// among the P3P solutions of any three points.
TEST(Tripose_HybridPoseSolver, point_samples_on_wide_baselines_contain_the_true_pose)
{
    for (int seed = 0; seed < 20; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = scene(30, 10, cv::tripose::support::MOTION_LARGE, 5.0, seed);
        const ViewSet views = readScene(s);
        const PoseScorer scorer(views);
        const LinearPoseSolver linear(views);
        const HybridPoseSolver solver(views, scorer, linear);
        ASSERT_TRUE(solver.usesPointSamples()) << "seed " << seed;
        EXPECT_EQ(3, solver.sampleSize());
        EXPECT_EQ(30, solver.samplePool(views.numFeatures()));
        FeatureSubset sample;
        sample.points = { seed % 10, 10 + seed % 7, 29 - seed % 5 };
        std::vector<CameraPose> poses;
        ASSERT_GT(solver.estimateMinimal(sample, false, poses), 0) << "seed " << seed;
        double best = std::numeric_limits<double>::infinity();
        for (const CameraPose& p : poses)
        {
            Mat R(3, 3, CV_64F), t(3, 1, CV_64F);
            for (int r = 0; r < 3; ++r)
            {
                t.at<double>(r) = p.t(r);
                for (int c = 0; c < 3; ++c)
                    R.at<double>(r, c) = p.R(r, c);
            }
            best = std::min(best, poseError(R, t, s.R, s.t).rotationDeg);
        }
        EXPECT_LT(best, 1e-6) << "seed " << seed;
        // A sample that is not three points is not a P3P problem.
        FeatureSubset mixed;
        mixed.points = { 0, 1 };
        mixed.lines = { 0 };
        poses.clear();
        EXPECT_EQ(0, solver.estimateMinimal(mixed, false, poses));
    }
}

// Narrow baselines (views 1-2 triangulate depth poorly) and line-dominated sets keep the four-feature
// linear samples over every feature.
TEST(Tripose_HybridPoseSolver, linear_samples_on_narrow_baselines_and_few_points)
{
    int narrow = 0;
    for (int seed = 0; seed < 20; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = scene(30, 10, cv::tripose::support::MOTION_SMALL, 0.2, seed);
        const ViewSet views = readScene(s);
        const PoseScorer scorer(views);
        const LinearPoseSolver linear(views);
        const HybridPoseSolver solver(views, scorer, linear);
        // Views 1 and 2 at most 0.4 m apart, about 20 m from the points: angles under 1.5 degrees.
        EXPECT_FALSE(solver.usesPointSamples()) << "seed " << seed;
        narrow += !solver.usesPointSamples();
        EXPECT_EQ(4, solver.sampleSize());
        EXPECT_EQ(views.numFeatures(), solver.samplePool(views.numFeatures()));
    }
    EXPECT_EQ(20, narrow);
    const cv::tripose::support::SyntheticScene s = scene(6, 40, cv::tripose::support::MOTION_LARGE, 5.0, 1);
    const ViewSet views = readScene(s);
    const PoseScorer scorer(views);
    const LinearPoseSolver linear(views);
    EXPECT_FALSE(HybridPoseSolver(views, scorer, linear).usesPointSamples());
}

} // namespace
} // namespace opencv_test
