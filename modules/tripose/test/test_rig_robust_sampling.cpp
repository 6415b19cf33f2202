// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

#include "tripose_support/synthetic_stereo_scene.hpp"

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/geometry/rotation.hpp"
#include "../src/core/linear/rig_pose_solver.hpp"
#include "../src/core/refine/ml_refinement.hpp"
#include "../src/core/refine/multi_start_refiner.hpp"
#include "../src/core/robust/hybrid_pose_solver.hpp"
#include "../src/core/scoring/pose_scorer.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::FeatureSubset;
using ::tripose::HybridPoseSolver;
using ::tripose::MixedSampling;
using ::tripose::PoseScore;
using ::tripose::PoseScorer;
using ::tripose::RigPoseSolver;
using ::tripose::ViewSet;
using cv::tripose::support::SyntheticStereoScene;

SyntheticStereoScene rigScene(int points, int lines, int seed, double noise, double outliers, double missing)
{
    return cv::tripose::support::generateSyntheticStereoScene(stereoParams(points, lines, seed, noise, outliers, missing));
}

ViewSet readRig(const SyntheticStereoScene& s)
{
    return cv::tripose::detail::readStereoRigInput(s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2,
                                                   s.lines3, s.lines4, s.cameraMatrices, noArray(), s.R12, s.t12, 3);
}

//! Angle between two rotations, accurate near zero (an arc cosine of the trace is not).
double rotationErrorDeg(const CameraPose& a, const CameraPose& b)
{
    return degrees(2.0 * std::asin(std::min(1.0, (a.R - b.R).norm() / (2.0 * std::sqrt(2.0)))));
}

//! The rig's robust set-up as estimateRobustRig() builds it.
struct RigSetup
{
    const ViewSet views;
    const PoseScorer scorer;
    const RigPoseSolver linear;
    const HybridPoseSolver solver;
    explicit RigSetup(const SyntheticStereoScene& s)
        : views(readRig(s)), scorer(views, PoseScorer::KnownDepth::Slides), linear(views), solver(views, scorer, linear)
    {}
};

// Each time-B camera has its own pools; a sample of the right camera's pool whose features the left
// camera does not see is solved in the right camera and its pose taken back through the rig's
// mount: on noise-free data the true pose of the left camera is among the solutions of every kind.
TEST(Tripose_RigRobustSampling, samples_of_either_camera_contain_the_true_pose)
{
    for (int seed = 0; seed < 10; ++seed)
    {
        // Half of the features seen by one time-B camera only.
        const SyntheticStereoScene s = rigScene(40, 20, 900 + seed, 0.0, 0.0, 0.5);
        const RigSetup setup(s);
        const HybridPoseSolver& solver = setup.solver;
        ASSERT_EQ(HybridPoseSolver::Sampling::Mixed, solver.sampling()) << "seed " << seed;
        const MixedSampling& sampling = *solver.mixedSampling();
        ASSERT_EQ(2u, sampling.pools.size());
        ASSERT_EQ(2u, solver.cameras().size());
        const CameraPose truth = corePose(s.R, s.t);
        for (int pool = 0; pool < 2; ++pool)
        {
            const ::tripose::View& own = setup.views.views[solver.cameras()[pool]];
            const ::tripose::View& other = setup.views.views[solver.cameras()[1 - pool]];
            // The pool's features that the other camera does not see, and every feature of the
            // pool is seen by its camera.
            std::vector<int> points, lines;
            for (int i : sampling.pools[pool].points)
            {
                ASSERT_TRUE(own.seesPoint(i));
                if (!other.seesPoint(i))
                    points.push_back(i);
            }
            for (int i : sampling.pools[pool].lines)
            {
                ASSERT_TRUE(own.seesLine(i));
                if (!other.seesLine(i))
                    lines.push_back(i);
            }
            for (const MixedSampling::Kind& kind : sampling.kinds)
            {
                if (kind.pool != pool || kind.points > (int)points.size() || kind.lines > (int)lines.size())
                    continue;
                FeatureSubset sample;
                sample.points.assign(points.begin(), points.begin() + kind.points);
                sample.lines.assign(lines.begin(), lines.begin() + kind.lines);
                std::vector<CameraPose> poses;
                solver.estimateMinimal(sample, false, poses);
                double best = std::numeric_limits<double>::infinity();
                double bestTranslation = std::numeric_limits<double>::infinity();
                for (const CameraPose& p : poses)
                    if (rotationErrorDeg(p, truth) < best)
                    {
                        best = rotationErrorDeg(p, truth);
                        bestTranslation = (p.t - truth.t).norm() / truth.t.norm();
                    }
                EXPECT_LT(best, 1e-6) << "seed " << seed << ", pool " << pool << ", " << kind.points << "P+"
                                      << kind.lines << "L";
                EXPECT_LT(bestTranslation, 1e-6) << "seed " << seed << ", pool " << pool;
            }
        }
    }
}

// The rig at time A (0.1-0.5 m at 5-30 m) places its structure poorly in depth, and a time-B camera
// that moved sideways sees that error as pixels: against the structure held fixed, the true pose
// loses inliers; with the structure free to slide along view 1's rays it keeps them, and the wrong
// matches (at least 20 px off in each time-B view) stay out.
TEST(Tripose_RigRobustSampling, sliding_known_depth_keeps_the_inliers_of_the_true_pose)
{
    const double threshold = 2.0 * 2.0; // the estimator's sampling threshold for a 2 px threshold
    int observations = 0, fixedInliers = 0, slidInliers = 0, wrongMatches = 0, wrongAccepted = 0;
    for (int seed = 0; seed < 20; ++seed)
    {
        const SyntheticStereoScene s = rigScene(100, 40, 950 + seed, 1.0, 0.3, 0.2);
        const ViewSet views = readRig(s);
        const PoseScorer fixed(views), slid(views, PoseScorer::KnownDepth::Slides);
        ASSERT_FALSE(fixed.slidesKnownDepth());
        ASSERT_TRUE(slid.slidesKnownDepth());
        const CameraPose truth = corePose(s.R, s.t);
        FeatureSubset fixedSet, slidSet;
        const PoseScore a = fixed.score(truth, threshold, std::numeric_limits<double>::infinity(), &fixedSet);
        const PoseScore b = slid.score(truth, threshold, std::numeric_limits<double>::infinity(), &slidSet);
        ASSERT_EQ(a.considered, b.considered);
        fixedInliers += a.inliers;
        slidInliers += b.inliers;
        // Observations of true matches, and wrong matches accepted, by feature; a true feature
        // without structure from time A (triangulated behind the rig) is unmeasured.
        const auto count = [&](int features, const Mat& truth, const std::vector<int>& accepted, bool isPoint) {
            for (int i = 0; i < features; ++i)
            {
                const ::tripose::View &left = views.views[2], &right = views.views[3];
                if (truth.at<uchar>(i) != 0)
                {
                    if (isPoint ? slid.hasKnownPoint(i) : slid.hasKnownLine(i))
                        observations += isPoint ? left.seesPoint(i) + right.seesPoint(i)
                                                : left.seesLine(i) + right.seesLine(i);
                    continue;
                }
                ++wrongMatches;
                wrongAccepted += std::count(accepted.begin(), accepted.end(), i) > 0;
            }
        };
        count(views.numPoints, s.pointInliers, slidSet.points, true);
        count(views.numLines, s.lineInliers, slidSet.lines, false);
    }
    std::cout << "[ rig      ] true pose, 20 scenes 100P+40L, 1 px, 30 % wrong matches: inlier observations "
              << "with the structure fixed " << fixedInliers << ", sliding " << slidInliers << " of " << observations
              << " true with structure; wrong matches accepted " << wrongAccepted << "/" << wrongMatches << std::endl;
    // At 1 px and a 4 px test about 1 in 3000 true observations fall outside; the slide has one
    // degree of freedom per point (two per line) and leaves more than that in every view.
    EXPECT_GE(slidInliers, 0.97 * observations);
    EXPECT_LT(fixedInliers, 0.9 * observations);
    EXPECT_LE(wrongAccepted, 0.03 * wrongMatches + 1);
}

// On noise-free data the true pose explains every observation exactly whatever the depths do.
TEST(Tripose_RigRobustSampling, sliding_scorer_is_exact_at_the_true_pose)
{
    for (int seed = 0; seed < 5; ++seed)
    {
        const SyntheticStereoScene s = rigScene(30, 15, 980 + seed, 0.0, 0.0, 0.2);
        const ViewSet views = readRig(s);
        const PoseScorer slid(views, PoseScorer::KnownDepth::Slides);
        const PoseScore score = slid.score(corePose(s.R, s.t), 1.0);
        int observations = 0;
        for (int v = 2; v < 4; ++v)
        {
            for (int i = 0; i < views.numPoints; ++i)
                observations += views.views[v].seesPoint(i);
            for (int i = 0; i < views.numLines; ++i)
                observations += views.views[v].seesLine(i);
        }
        EXPECT_EQ(observations, score.inliers) << "seed " << seed;
        EXPECT_EQ(0, score.behind) << "seed " << seed;
        EXPECT_LT(score.rms(), 1e-6) << "seed " << seed;
    }
}

// The settle of the rig's robust estimator refines a round at most kSettleRoundIterations before it
// re-classifies the inliers; when they have settled, the refinement of the same features goes on
// from the structure that round reached instead of re-triangulating it (robust_estimator.cpp,
// multi_start_refiner.hpp). On the small sets whose refinement is slow (far lines on a short
// baseline: the slowest of the seeded 10P+10L scenes of doc/studies/speed.md, "Stereo rig"), refined from
// a perturbed true pose, the continued refinement starts where the capped one stopped, takes no
// more iterations than re-triangulating there, and ends where both that and (where it converged)
// one uncapped refinement end.
TEST(Tripose_RigRobustSampling, capped_refinement_continues_from_its_structure)
{
    const int cap = 12;
    int slow = 0;
    for (int seed : {9014, 9005, 8000, 8009, 11003, 9015})
    {
        const SyntheticStereoScene s = rigScene(10, 10, seed, 1.0, 0.0, 0.0);
        const RigSetup setup(s);
        CameraPose start = corePose(s.R, s.t);
        start.R = ::tripose::rotateLeft(Eigen::Vector3d(0.02, -0.015, 0.01), start.R);
        start.t += 0.05 * start.t.norm() * Eigen::Vector3d(1.0, -0.5, 0.3).normalized();
        ::tripose::RefineOptions options;
        CameraPose full = start;
        const ::tripose::RefinementSummary uncapped = ::tripose::refinePoseAndStructure(setup.views, full, options);
        ::tripose::RefineOptions capped = options;
        capped.maxIterations = cap;
        CameraPose pose = start;
        ::tripose::RefinedStructure structure;
        const ::tripose::RefinementSummary first =
            ::tripose::refinePoseAndStructure(setup.views, pose, capped, nullptr, nullptr, &structure);
        if (first.iterations < cap)
            continue;
        ++slow;
        const ::tripose::RefinementSummary rest =
            ::tripose::refinePoseAndStructure(setup.views, pose, options, nullptr, nullptr, nullptr, nullptr, &structure);
        // Re-triangulated at the same pose, the structure lies nearer by its residuals but not along
        // the valley the capped refinement was following: that refinement takes as long at least.
        CameraPose again = pose;
        const ::tripose::RefinementSummary retriangulated = ::tripose::refinePoseAndStructure(setup.views, again, options);
        EXPECT_NEAR(first.finalRms, rest.initialRms, 1e-9) << "seed " << seed;
        EXPECT_LE(rest.iterations, retriangulated.iterations) << "seed " << seed;
        EXPECT_NEAR(retriangulated.finalRms, rest.finalRms, 1e-6) << "seed " << seed;
        EXPECT_LT(rotationErrorDeg(again, pose), 1e-4) << "seed " << seed;
        // Where one uncapped refinement converged, the two end where it does.
        if (uncapped.iterations < options.maxIterations)
        {
            EXPECT_NEAR(uncapped.finalRms, rest.finalRms, 1e-6) << "seed " << seed;
            EXPECT_LT(rotationErrorDeg(full, pose), 1e-4) << "seed " << seed;
        }

        // The robust estimator's refiner does the same when asked again on the features and from
        // the pose of a call that stopped at its cap.
        FeatureSubset all = FeatureSubset::all(setup.views.numPoints, setup.views.numLines);
        const ::tripose::MultiStartRefiner refiner(setup.views, options, &setup.solver, true, false);
        CameraPose viaRefiner = start;
        bool stoppedAtCap = false;
        ASSERT_TRUE(refiner.refine(all, viaRefiner, cap, &stoppedAtCap));
        EXPECT_TRUE(stoppedAtCap) << "seed " << seed;
        ASSERT_TRUE(refiner.refine(all, viaRefiner, 0, &stoppedAtCap));
        EXPECT_FALSE(stoppedAtCap);
        EXPECT_LT(rotationErrorDeg(pose, viaRefiner), 1e-9) << "seed " << seed;
    }
    EXPECT_GE(slow, 3);
}

} // namespace
} // namespace opencv_test
