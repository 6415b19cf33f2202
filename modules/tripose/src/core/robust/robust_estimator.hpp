// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP
#define OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP

#include <vector>

#include "../support/options.hpp"
#include "../scoring/pose_scorer.hpp"
#include "../estimator/pose_solver.hpp"
#include "../estimator/scored_pose.hpp"

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
    /** With refinement: the minimum of the cost that the returned pose is, then the other distinct
    minima that the final refinement reached within the noise of it (refine/distinct_minima.hpp:
    their cost exceeds the returned pose's by less than the 95 % quantile of chi-square with 6
    degrees of freedom times the noise variance), lowest cost first, each with its RMS (px) over the
    inliers. More than one: the data cannot tell these poses apart. Where the refinement searched a
    single basin, the returned pose alone. Empty without refinement. */
    std::vector<ScoredPose> minima;
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
