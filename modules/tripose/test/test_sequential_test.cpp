// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"
#include "test_scene_views.hpp"

#include <cmath>

#include "../src/core/linear/linear_pose_solver.hpp"
#include "../src/core/pipeline/pose_pipelines.hpp"
#include "../src/core/robust/robust_estimator.hpp"
#include "../src/core/scoring/pose_scorer.hpp"
#include "../src/core/scoring/sequential_test.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::PoseScore;
using ::tripose::PoseScorer;
using ::tripose::SequentialTest;
using ::tripose::ViewSet;

//! Observations of one kind until the test rejects, all consistent or all not; -1 if it never does.
int observationsToReject(const SequentialTest& test, int kind, bool consistent, int limit = 1000)
{
    double logRatio = 0;
    for (int n = 1; n <= limit; ++n)
    {
        logRatio += test.step(kind, consistent);
        if (logRatio > test.logThreshold())
            return n;
    }
    return -1;
}

TEST(Tripose_SequentialTest, inactive_until_a_good_rate_exceeds_the_bad_one)
{
    SequentialTest test;
    EXPECT_FALSE(test.active());
    EXPECT_EQ(0.0, test.step(SequentialTest::Point, false));
    // The prior bad rate is 0.05: a good rate of 0.07 cannot tell them apart.
    test.setGoodRates(0.07, 0.0);
    EXPECT_FALSE(test.active());
    test.setGoodRates(0.0, 0.5);
    EXPECT_TRUE(test.active());
    EXPECT_EQ(0.0, test.step(SequentialTest::Point, false)) << "a kind without support must not vote";
    EXPECT_GT(test.step(SequentialTest::Line, false), 0.0);
    EXPECT_LT(test.step(SequentialTest::Line, true), 0.0);
}

// Wald's test: with epsilon 0.5 and delta 0.05, each wrong observation multiplies the ratio by
// 0.95 / 0.5 = 1.9, and 1.9^11 is the first power over the threshold 1000.
TEST(Tripose_SequentialTest, rejects_a_wrong_pose_after_eleven_wrong_observations)
{
    SequentialTest test;
    test.setGoodRates(0.5, 0.5);
    const int expected = (int)std::ceil(std::log(SequentialTest::kThreshold) / std::log(0.95 / 0.5));
    EXPECT_EQ(11, expected);
    EXPECT_EQ(expected, observationsToReject(test, SequentialTest::Point, false));
    EXPECT_EQ(expected, observationsToReject(test, SequentialTest::Line, false));
    EXPECT_EQ(-1, observationsToReject(test, SequentialTest::Point, true));
    // The capped good rate: every observation of the best pose consistent is taken for 0.95.
    test.setGoodRates(1.0, 1.0);
    EXPECT_DOUBLE_EQ(SequentialTest::kMaxGoodRate, test.goodRate(SequentialTest::Point));
    EXPECT_EQ(3, observationsToReject(test, SequentialTest::Point, false)) << "log(1000) / log(0.95 / 0.05)";
}

TEST(Tripose_SequentialTest, bad_rates_follow_the_rejected_poses)
{
    SequentialTest test;
    test.setGoodRates(0.8, 0.8);
    const double before = test.step(SequentialTest::Line, true);
    const int tested[2] = { 100, 80 }, consistent[2] = { 0, 40 };
    test.addRejected(tested, consistent);
    // (consistent + 0.05 * 20) / (tested + 20), at least kMinBadRate.
    EXPECT_NEAR(1.0 / 120, test.badRate(SequentialTest::Point), 1e-15);
    EXPECT_NEAR(41.0 / 100, test.badRate(SequentialTest::Line), 1e-15);
    EXPECT_NEAR(std::log(0.41 / 0.8), test.step(SequentialTest::Line, true), 1e-12);
    EXPECT_GT(test.step(SequentialTest::Line, true), before) << "a consistent line says less when wrong poses fit many";
    // Wrong poses that fit lines nearly as often as the best pose: the lines no longer vote.
    const int more[2] = { 0, 1000 }, fitting[2] = { 0, 700 };
    test.addRejected(more, fitting);
    EXPECT_EQ(0.0, test.step(SequentialTest::Line, false));
    EXPECT_TRUE(test.active()) << "the points still vote";
}

/** On outlier-free scenes at 1 px, the true pose passes the test with the good rates of its own
score (what the estimator holds once its best pose is right), whether wrong poses were found to fit
few observations or a third of them, and is then scored exactly as without the test; the true pose
turned by 10 degrees is rejected after a few observations (on sets of PoseScorer::kMinTestedObservations or more; smaller
ones are not tested). Wald's bound puts the chance of
rejecting the true pose at 1 / 1000 per scene. */
TEST(Tripose_SequentialTest, passes_the_true_pose_and_rejects_a_wrong_one_early)
{
    const double threshold = 4.0; // the estimator's 2 x 2 px
    const double inf = std::numeric_limits<double>::infinity();
    int scenes = 0;
    for (const FeatureMix mix : { FeatureMix{ 100, 40 }, FeatureMix{ 10, 100 }, FeatureMix{ 20, 20 } })
        for (int seed = 0; seed < 30; ++seed, ++scenes)
        {
            const cv::tripose::support::SyntheticScene s = makeScene(mix, cv::tripose::support::MOTION_LARGE, 1.0, seed);
            const ViewSet views = readScene(s);
            const PoseScorer scorer(views);
            const CameraPose truth = corePose(s.R, s.t);
            const std::string name = mixName(mix) + ", seed " + std::to_string(seed);

            ::tripose::FeatureSubset plain, tested;
            const PoseScore reference = scorer.score(truth, threshold, inf, &plain);
            const int observations =
                scorer.observations(SequentialTest::Point) + scorer.observations(SequentialTest::Line);
            SequentialTest usual;
            usual.setGoodRates(double(reference.pointInliers) / scorer.observations(SequentialTest::Point),
                               double(reference.inliers - reference.pointInliers) /
                                   scorer.observations(SequentialTest::Line));
            ASSERT_TRUE(usual.active()) << name;
            SequentialTest fitting = usual;
            const int rejected[2] = { 1000, 1000 }, consistent[2] = { 300, 300 };
            fitting.addRejected(rejected, consistent);
            for (const SequentialTest* test : { &usual, &fitting })
            {
                const PoseScore s2 = scorer.score(truth, threshold, inf, &tested, test);
                ASSERT_FALSE(s2.rejected) << name;
                EXPECT_EQ(reference.cost, s2.cost) << name;
                EXPECT_EQ(reference.inliers, s2.inliers) << name;
                EXPECT_EQ(plain.points, tested.points) << name;
                EXPECT_EQ(plain.lines, tested.lines) << name;
                EXPECT_EQ(observations < PoseScorer::kMinTestedObservations ? 0 : std::min(PoseScorer::kMaxTested, observations),
                          s2.tested[SequentialTest::Point] + s2.tested[SequentialTest::Line]) << name;
            }

            Mat R, t;
            RNG rng(seed);
            perturbPose(s.R, s.t, 10.0, 0.0, rng, R, t);
            const PoseScore wrong = scorer.score(corePose(R, t), threshold, inf, nullptr, &usual);
            // Small sets are not tested (the cost bound stops as early).
            EXPECT_EQ(observations >= PoseScorer::kMinTestedObservations, wrong.rejected) << name;
            EXPECT_EQ(wrong.rejected, std::isinf(wrong.cost)) << name;
            EXPECT_LE(wrong.tested[SequentialTest::Point] + wrong.tested[SequentialTest::Line], 20) << name;
        }
    EXPECT_EQ(90, scenes);
}

/** The estimator with and without the test on seeded scenes with wrong matches (mixed samples, and
the four-feature linear samples of a small set with few points): the test only decides which poses
are scored in full, and the final pose is the refinement's on the consensus, so the results agree. */
TEST(Tripose_SequentialTest, the_estimate_is_the_one_without_the_test)
{
    struct Case
    {
        FeatureMix mix;
        double outliers;
    };
    int same = 0, scenes = 0;
    for (const Case c : { Case{ { 100, 40 }, 0.5 }, Case{ { 10, 100 }, 0.5 }, Case{ { 12, 8 }, 0.5 },
                          Case{ { 5, 12 }, 0.3 } })
        for (int seed = 0; seed < 10; ++seed, ++scenes)
        {
            const FeatureMix mix = c.mix;
            cv::tripose::support::SyntheticSceneParams params =
                sceneParams(mix, cv::tripose::support::MOTION_LARGE, 1.0, 500 + seed);
            params.outlierRatio = c.outliers;
            const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
            const ViewSet views = readScene(s);
            const ::tripose::LinearPoseSolver linear(views);
            ::tripose::RansacOptions options;
            options.threshold = 2.0;
            options.minInliers = 0; // 12 + 8 features with half of them wrong: no floor above the inliers
            ::tripose::RobustEstimate with, without;
            ASSERT_TRUE(::tripose::estimateRobustOnKnownStructure(views, linear, options, with)) << seed;
            options.sequentialTest = false;
            ASSERT_TRUE(::tripose::estimateRobustOnKnownStructure(views, linear, options, without)) << seed;
            const double apart = (with.pose.R - without.pose.R).norm() + (with.pose.t - without.pose.t).norm() /
                                                                            without.pose.t.norm();
            EXPECT_EQ(without.iterations, with.iterations) << mixName(mix) << ", seed " << seed;
            same += apart < 1e-9;
            EXPECT_LT(apart, 1e-3) << mixName(mix) << ", seed " << seed;
            EXPECT_EQ(without.pointInliers, with.pointInliers) << mixName(mix) << ", seed " << seed;
            EXPECT_EQ(without.lineInliers, with.lineInliers) << mixName(mix) << ", seed " << seed;
        }
    EXPECT_GE(same, scenes - 1);
}

} // namespace
} // namespace opencv_test
