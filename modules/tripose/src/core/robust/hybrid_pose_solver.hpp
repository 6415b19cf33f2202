// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP
#define OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP

#include "../scoring/pose_scorer.hpp"
#include "../estimator/pose_solver.hpp"

namespace tripose {

/** The three-view problem's sample solver for the robust estimator: minimal absolute-pose samples of
view 3 on the structure that the PoseScorer triangulated from views 1-2 where that structure is
good, the unified linear method's four-feature samples otherwise.

With the points of views 1-2 triangulated, three points of view 3 are a P3P problem (solveP3P):
a sample of three instead of four features, and a closed-form solver far cheaper than the linear
one's degree-11 polynomial. Samples are then drawn from the points alone (samplePool()), so the
stopping rule counts point inliers. Lines still vote in every score, and the local optimisation
and estimateNonMinimal() use the linear solver on every inlier, points and lines, so the final
pose is the linear method's on the consensus set.

The four-feature linear sample stays the solver when views 1-2 triangulate poorly: a narrow
baseline (median triangulation angle below kWeakTriangulationAngleDeg, scoring/known_structure.hpp), where the
depths of the triangulated points carry an error that the linear method, which never triangulates,
avoids; or too few points with structure (fewer than kMinPoints, or under a quarter of the
features: line-dominated scenes, whose hypotheses must come from their lines).
*/
class HybridPoseSolver : public PoseSolver
{
public:
    static constexpr int kMinPoints = 8;

    //! @p linear: the four-feature solver (kept for non-minimal sets and poor structure).
    HybridPoseSolver(const ViewSet& set, const PoseScorer& scorer, const PoseSolver& linear);

    //! True when samples are three points solved by P3P.
    bool usesPointSamples() const { return pointSamples_; }

    int sampleSize() const override { return pointSamples_ ? 3 : linear_.sampleSize(); }
    int nonMinimalSize() const override { return linear_.nonMinimalSize(); }
    int samplePool(int numFeatures) const override { return pointSamples_ ? set_.numPoints : numFeatures; }
    int estimateMinimal(const FeatureSubset& sample, bool exhaustive, std::vector<CameraPose>& models) const override;
    int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const override
    {
        return linear_.estimateNonMinimal(features, models);
    }

private:
    const ViewSet& set_;
    const PoseScorer& scorer_;
    const PoseSolver& linear_;
    bool pointSamples_ = false;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_ROBUST_HYBRID_POSE_SOLVER_HPP
