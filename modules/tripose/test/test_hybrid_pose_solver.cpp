// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"
#include "test_scene_views.hpp"

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/linear/linear_pose_solver.hpp"
#include "../src/core/robust/hybrid_pose_solver.hpp"
#include "../src/core/scoring/known_structure.hpp"
#include "../src/core/scoring/pose_scorer.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::FeatureSubset;
using ::tripose::HybridPoseSolver;
using ::tripose::LinearPoseSolver;
using ::tripose::MixedSampling;
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

//! A scene read as the estimator reads it, with the hybrid sample solver over its linear solver.
struct HybridSetup
{
    const ViewSet views;
    const PoseScorer scorer;
    const LinearPoseSolver linear;
    const HybridPoseSolver solver;
    explicit HybridSetup(const cv::tripose::support::SyntheticScene& s)
        : views(readScene(s)), scorer(views), linear(views), solver(views, scorer, linear)
    {}
};

double bestRotationErrorDeg(const std::vector<CameraPose>& poses, const cv::tripose::support::SyntheticScene& s)
{
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
    return best;
}

// Wide baselines with enough features: samples of three points, two points and a line, a point and two
// lines, or three lines; on noise-free structure the true pose is among the solutions of each kind.
TEST(Tripose_HybridPoseSolver, mixed_samples_on_wide_baselines_contain_the_true_pose)
{
    for (int seed = 0; seed < 20; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = scene(30, 10, cv::tripose::support::MOTION_LARGE, 5.0, seed);
        const HybridSetup setup(s);
        const HybridPoseSolver& solver = setup.solver;
        ASSERT_EQ(HybridPoseSolver::Sampling::Mixed, solver.sampling()) << "seed " << seed;
        EXPECT_EQ(3, solver.sampleSize());
        const MixedSampling* sampling = solver.mixedSampling();
        ASSERT_TRUE(sampling != nullptr);
        ASSERT_EQ(30u, sampling->pools[0].points.size()) << "seed " << seed;
        ASSERT_GE(sampling->pools[0].lines.size(), 3u) << "seed " << seed;
        ASSERT_EQ(4u, sampling->kinds.size());
        for (const MixedSampling::Kind& kind : sampling->kinds)
        {
            FeatureSubset sample;
            for (int k = 0; k < kind.points; ++k)
                sample.points.push_back(sampling->pools[0].points[(seed + 7 * k) % sampling->pools[0].points.size()]);
            for (int k = 0; k < kind.lines; ++k)
                sample.lines.push_back(sampling->pools[0].lines[(seed + k) % sampling->pools[0].lines.size()]);
            std::vector<CameraPose> poses;
            ASSERT_GT(solver.estimateMinimal(sample, false, poses), 0)
                << kind.points << "P" << kind.lines << "L, seed " << seed;
            EXPECT_LT(bestRotationErrorDeg(poses, s), degrees(1e-6)) << kind.points << "P" << kind.lines << "L, seed " << seed;
        }
    }
}

// Fewer features than kMinMixedFeatures keep the samples that the estimator enumerates: three points
// when they are enough, which a sample with a line is not.
TEST(Tripose_HybridPoseSolver, point_samples_on_small_sets_with_enough_points)
{
    for (int seed = 0; seed < 10; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = scene(12, 4, cv::tripose::support::MOTION_LARGE, 5.0, seed);
        const HybridSetup setup(s);
        const ViewSet& views = setup.views;
        const HybridPoseSolver& solver = setup.solver;
        ASSERT_TRUE(solver.usesPointSamples()) << "seed " << seed;
        EXPECT_TRUE(solver.mixedSampling() == nullptr);
        EXPECT_EQ(3, solver.sampleSize());
        EXPECT_EQ(12, solver.samplePool(views.numFeatures()));
        FeatureSubset sample;
        sample.points = { seed % 4, 4 + seed % 3, 11 - seed % 2 };
        std::vector<CameraPose> poses;
        ASSERT_GT(solver.estimateMinimal(sample, false, poses), 0) << "seed " << seed;
        EXPECT_LT(bestRotationErrorDeg(poses, s), degrees(1e-6)) << "seed " << seed;
        FeatureSubset mixed;
        mixed.points = { 0, 1 };
        mixed.lines = { 0 };
        poses.clear();
        EXPECT_EQ(0, solver.estimateMinimal(mixed, false, poses));
    }
}

// Narrow baselines (views 1-2 triangulate depth poorly) and small sets with few points keep the
// four-feature linear samples over every feature.
TEST(Tripose_HybridPoseSolver, linear_samples_on_narrow_baselines_and_few_points)
{
    int narrow = 0;
    for (int seed = 0; seed < 20; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = scene(30, 10, cv::tripose::support::MOTION_SMALL, 0.2, seed);
        const HybridSetup setup(s);
        const ViewSet& views = setup.views;
        const HybridPoseSolver& solver = setup.solver;
        // Views 1 and 2 at most 0.4 m apart, about 20 m from the points: angles under 1.5 degrees.
        EXPECT_EQ(HybridPoseSolver::Sampling::Linear, solver.sampling()) << "seed " << seed;
        narrow += solver.sampling() == HybridPoseSolver::Sampling::Linear;
        EXPECT_TRUE(solver.mixedSampling() == nullptr);
        EXPECT_EQ(4, solver.sampleSize());
        EXPECT_EQ(views.numFeatures(), solver.samplePool(views.numFeatures()));
    }
    EXPECT_EQ(20, narrow);
    const cv::tripose::support::SyntheticScene s = scene(6, 10, cv::tripose::support::MOTION_LARGE, 5.0, 1);
    const ViewSet views = readScene(s);
    const PoseScorer scorer(views);
    const LinearPoseSolver linear(views);
    EXPECT_EQ(HybridPoseSolver::Sampling::Linear, HybridPoseSolver(views, scorer, linear).sampling());
}

// Line-dominated sets draw line samples: the kinds their pools can fill, and only lines whose planes
// in views 1-2 meet at a usable angle.
TEST(Tripose_HybridPoseSolver, line_samples_where_lines_dominate)
{
    int leftOut = 0;
    for (int seed = 0; seed < 20; ++seed)
        for (int points : { 0, 3 })
        {
            const cv::tripose::support::SyntheticScene s = scene(points, 60, cv::tripose::support::MOTION_LARGE, 5.0, seed);
            const HybridSetup setup(s);
            const ViewSet& views = setup.views;
            const PoseScorer& scorer = setup.scorer;
            const HybridPoseSolver& solver = setup.solver;
            ASSERT_EQ(HybridPoseSolver::Sampling::Mixed, solver.sampling()) << points << "P seed " << seed;
            const MixedSampling& sampling = *solver.mixedSampling();
            ASSERT_EQ(points == 0 ? 1u : 4u, sampling.kinds.size());
            EXPECT_EQ(0, sampling.kinds.back().points);
            EXPECT_EQ(3, sampling.kinds.back().lines);
            for (int i = 0; i < views.numLines; ++i)
            {
                const bool pooled = std::find(sampling.pools[0].lines.begin(), sampling.pools[0].lines.end(), i) != sampling.pools[0].lines.end();
                const bool usable = scorer.hasKnownLine(i) &&
                                    ::tripose::linePlaneAngleDeg(views, i) >= ::tripose::kWeakLinePlaneAngleDeg;
                EXPECT_EQ(usable, pooled) << "line " << i << " seed " << seed;
                leftOut += !pooled;
            }
        }
    std::cout << "lines left out of the samples: " << leftOut << " of " << 40 * 60 << std::endl;
}

} // namespace
} // namespace opencv_test
