// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP
#define OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP

#include <vector>

#include "../scoring/pose_scorer.hpp"
#include "../estimator/pose_solver.hpp"

namespace tripose {

/** The sample solver for the robust estimator of the problems that absolute-pose the estimated
camera(s) on the structure of known views (the three-view problem, registration against several
known views, the stereo rig at time B): minimal samples on the structure that the PoseScorer
triangulated from the known views where that structure serves, the problem's linear solver's
samples otherwise.

With the points and lines of the known views triangulated, three features of an estimated camera
are a minimal absolute-pose problem: three points (solveP3P), two points and a line (solveP2P1L), a
point and two lines (solveP1P2L) or three lines (solveP3L), each a sample of three instead of four
features and a solver far cheaper than the linear one's degree-11 polynomial. From kMinMixedFeatures
features with structure on, samples of all four kinds are drawn (mixedSampling(), MixedSampler),
each kind in proportion to its probability of being all inliers: where the lines are plentiful or
the reliable matches, the samples are mostly lines. Lines whose known planes meet at a grazing angle
(kWeakLinePlaneAngleDeg) are left out of the samples. Every feature votes in every score, and the
local optimisation and estimateNonMinimal() use the linear solver on every inlier, so the final
pose is the linear method's on the consensus set.

A stereo rig at time B has two estimated cameras, each seeing part of the features: each has its
own pools, a sample is drawn from one of them and solved in a camera that sees it all, and the pose
of that camera is taken back to the estimated one through its mount.

Smaller sets keep samples of three points (P3P) when there are at least kMinPoints with structure
and they are a quarter of the features: every distinct triple, enumerated (SampleGenerator), for one
estimated camera; per camera, drawn by the mixed sampler with the three-point kinds alone, for a
rig. Otherwise the samples are the linear solver's. Three lines of the structure within
kParallelLinesDeg of one direction are no sample: the pose is then fixed only by their
differences in direction, of the order of the structure's error.

The linear sample stays the solver when the known views triangulate poorly (a narrow baseline:
median triangulation angle below kWeakTriangulationAngleDeg, scoring/known_structure.hpp) and the
scorer holds their structure fixed: the depths of that structure carry an error that the linear
method, which never triangulates, avoids. A scorer that lets the depths slide
(PoseScorer::KnownDepth::Slides, the stereo rig's) judges the minimal samples' poses without that
error.
*/
class HybridPoseSolver : public PoseSolver
{
public:
    static constexpr int kMinPoints = 8;
    /** From here on the samples of three features are too many to enumerate (C(20, 3) = 1140 >
    SampleGenerator::kEnumerationLimit), and the mixed samples are drawn at random. */
    static constexpr int kMinMixedFeatures = 20;

    enum class Sampling
    {
        Linear,      //!< Four features of any kind, the linear solver.
        PointTriples, //!< Three points, P3P.
        Mixed,       //!< Three points, two points and a line, a point and two lines, or three lines.
    };

    //! @p linear: the four-feature solver (kept for non-minimal sets and poor structure).
    HybridPoseSolver(const ViewSet& set, const PoseScorer& scorer, const PoseSolver& linear);

    Sampling sampling() const { return sampling_; }
    //! True when samples are three points solved by P3P.
    bool usesPointSamples() const { return sampling_ == Sampling::PointTriples; }

    int sampleSize() const override { return sampling_ == Sampling::Linear ? linear_.sampleSize() : 3; }
    int nonMinimalSize() const override { return linear_.nonMinimalSize(); }
    int samplePool(int numFeatures) const override
    {
        return sampling_ == Sampling::PointTriples ? set_.numPoints : numFeatures;
    }
    //! The estimated cameras (view indices) whose observations the minimal samples use.
    const std::vector<int>& cameras() const { return cameras_; }
    const MixedSampling* mixedSampling() const override
    {
        return sampling_ == Sampling::Mixed ? &mixed_ : nullptr;
    }
    int estimateMinimal(const FeatureSubset& sample, bool exhaustive, std::vector<CameraPose>& models) const override;
    int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const override
    {
        return linear_.estimateNonMinimal(features, models);
    }

private:
    const ViewSet& set_;
    const PoseScorer& scorer_;
    const PoseSolver& linear_;
    std::vector<int> cameras_;
    Sampling sampling_ = Sampling::Linear;
    MixedSampling mixed_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP
