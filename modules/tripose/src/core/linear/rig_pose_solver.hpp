// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_RIG_POSE_SOLVER_HPP
#define OPENCV_TRIPOSE_LINEAR_RIG_POSE_SOLVER_HPP

#include "../estimator/pose_solver.hpp"
#include "rig_solver.hpp"

namespace tripose {

/** The stereo-rig linear solver as the robust estimator's solver (ViewSet layout: rig_system.hpp).
Samples of three features, any mix and visibility: the smallest sets it solves (up to 8 candidates
when each is seen in one time-B view; none when the sample does not fix the pose, e.g. two points
seen in both views plus a feature seen in neither). From six features every mix leaves a kernel of
dimension at most 1, which fixes one pose: the non-minimal size.
*/
class RigPoseSolver : public PoseSolver
{
public:
    explicit RigPoseSolver(const ViewSet& set) : set_(set) {}

    int sampleSize() const override { return 3; }
    int nonMinimalSize() const override { return 6; }

    int estimateMinimal(const FeatureSubset& sample, bool /*exhaustive*/, std::vector<CameraPose>& models) const override
    {
        return rigPoseCandidates(set_, models, &sample.points, &sample.lines);
    }

    int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const override
    {
        return rigPoseCandidates(set_, models, &features.points, &features.lines);
    }

private:
    const ViewSet& set_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_RIG_POSE_SOLVER_HPP
