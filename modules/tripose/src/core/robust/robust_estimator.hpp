// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP
#define OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP

#include <vector>

#include "../support/options.hpp"
#include "../scoring/pose_scorer.hpp"
#include "../estimator/pose_solver.hpp"

namespace tripose {

struct RobustEstimate
{
    CameraPose pose;
    std::vector<unsigned char> pointInliers, lineInliers;
    int numInliers = 0;
    int iterations = 0; //!< Samples drawn.
    //! With a solver of several sample kinds (PoseSolver::mixedSampling()): the samples drawn of
    //! each kind, in the order of its kinds; empty otherwise.
    std::vector<int> samplesOfKind;
    //! RMS (px) over the inliers of the residuals that decide them (PoseScorer::refitResiduals()).
    double inlierRms = 0;
};

/** LO-MSAC over the samples of @p solver, hypotheses scored by @p scorer against 2 x threshold,
adaptive stopping, then @p refiner (null: none) on the inliers; the returned masks compare each
feature's PoseScorer::refitResiduals() with the threshold. See estimatePoseLinePointRansac() for
the user-facing description. Returns false when no sample gave a pose with inliers.
*/
bool estimatePoseRobust(const PoseSolver& solver, const PoseScorer& scorer, const PoseRefiner* refiner,
                        const RansacOptions& params, RobustEstimate& estimate);

} // namespace tripose

#endif // OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP
