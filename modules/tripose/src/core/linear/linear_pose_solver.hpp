// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_POSE_SOLVER_HPP
#define OPENCV_TRIPOSE_LINEAR_POSE_SOLVER_HPP

#include "../estimator/pose_solver.hpp"
#include "linear_solver.hpp"

namespace tripose {

/** The unified linear method as the robust estimator's solver for the three-view problem: samples of
four features (any mix: the smallest set it solves), over-determined from six.
*/
class LinearPoseSolver : public PoseSolver
{
public:
    explicit LinearPoseSolver(const ViewSet& set) : set_(set) {}

    int sampleSize() const override { return 4; }
    int nonMinimalSize() const override { return 6; }

    int estimateMinimal(const FeatureSubset& sample, bool exhaustive, std::vector<CameraPose>& models) const override
    {
        // Twisted pairs double the hypotheses for little gain here: local optimisation and refinement
        // on the inliers repair hypotheses that are merely close. With exhaustive (few-feature)
        // sampling nothing does, and the kernel basis ordered by fit gives the better hypotheses.
        CandidateOptions options;
        options.twistedPairs = false;
        options.orderedKernel = exhaustive;
        return linearPoseCandidates(set_, models, &sample.points, &sample.lines, options);
    }

    int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const override
    {
        return linearPoseCandidates(set_, models, &features.points, &features.lines);
    }

private:
    const ViewSet& set_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_POSE_SOLVER_HPP
