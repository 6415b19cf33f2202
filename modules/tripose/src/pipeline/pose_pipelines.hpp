// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_PIPELINE_POSE_PIPELINES_HPP
#define OPENCV_TRIPOSE_PIPELINE_POSE_PIPELINES_HPP

#include "opencv2/tripose.hpp"
#include "../geometry/view_set.hpp"
#include "../robust/pose_solver.hpp"
#include "../scoring/pose_scorer.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** What the public functions do once their input is a ViewSet, for any arrangement of views: the
problem-specific part is the PoseSolver. Outputs as the public functions document them.
*/

//! estimatePoseLinePoint() and its stereo variant: the solver's candidates from every feature,
//! ranked by PoseScorer (POSE_LINEAR) or refined and ranked by the refined error (POSE_LINEAR_REFINE).
int estimateCandidates(const ViewSet& views, const PoseSolver& solver, int method, OutputArray R, OutputArray t,
                       OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray reprojectionErrors);

//! estimatePoseLinePointRansac() and its stereo variant; @p params is validated here.
int estimateRobust(const ViewSet& views, const PoseSolver& solver, const RansacParams& params, OutputArray R,
                   OutputArray t, OutputArray pointInliers, OutputArray lineInliers);

//! The same with the caller's scorer of @p views, for solvers that use its structure.
int estimateRobust(const ViewSet& views, const PoseScorer& scorer, const PoseSolver& solver,
                   const RansacParams& params, OutputArray R, OutputArray t, OutputArray pointInliers,
                   OutputArray lineInliers);

//! refinePoseLinePoint() and its stereo variant: reads the initial pose from @p R, @p t (named "R",
//! "t" in errors), validates @p params, refines over every view and writes pose and structure.
double refineInitialPose(const ViewSet& views, InputOutputArray R, InputOutputArray t, const RefineParams& params,
                         OutputArray points3d, OutputArray lines3d);

//! Throws cv::Exception naming @p method unless it is POSE_LINEAR or POSE_LINEAR_REFINE.
void checkPoseMethod(int method);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_PIPELINE_POSE_PIPELINES_HPP
