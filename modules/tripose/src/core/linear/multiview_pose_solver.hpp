// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_MULTIVIEW_POSE_SOLVER_HPP
#define OPENCV_TRIPOSE_LINEAR_MULTIVIEW_POSE_SOLVER_HPP

#include "../estimator/pose_solver.hpp"
#include "multiview_system.hpp"

namespace tripose {

/** Pairs of known views for the over-determined multi-view system: after RANSAC and refinement,
every pair drifts no more than the best pair alone (doc/studies/tracking.md).
*/
const PairSelection kMultiViewPairs = PairSelection::All;

/** The multi-view linear system (multiview_system.hpp) as the robust estimator's solver: samples of
four features (each from its best-conditioned pair of known views), over-determined from six (then
with the pairs of @p pairs).
*/
class MultiViewPoseSolver : public PoseSolver
{
public:
    explicit MultiViewPoseSolver(const ViewSet& set, PairSelection pairs = kMultiViewPairs)
        : system_(set, pairs)
    {
    }

    int sampleSize() const override { return 4; }
    int nonMinimalSize() const override { return 6; }

    int estimateMinimal(const FeatureSubset& sample, bool exhaustive, std::vector<CameraPose>& models) const override
    {
        // As the three-view solver (linear_pose_solver.hpp).
        CandidateOptions options;
        options.twistedPairs = false;
        options.orderedKernel = exhaustive;
        return system_.candidates(models, &sample.points, &sample.lines, options);
    }

    int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const override
    {
        return system_.candidates(models, &features.points, &features.lines, CandidateOptions());
    }

private:
    MultiViewSystem system_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_MULTIVIEW_POSE_SOLVER_HPP
