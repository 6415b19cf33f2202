// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ML_REFINEMENT_HPP
#define OPENCV_TRIPOSE_ML_REFINEMENT_HPP

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "../support/options.hpp"
#include "../geometry/view_set.hpp"

namespace tripose {

struct RefinementSummary
{
    double initialRms = 0; //!< RMS reprojection error (px) over every view at the start (+inf: nothing usable).
    double finalRms = 0;   //!< The same at the returned estimate.
    int residuals = 0;     //!< Residuals in finalRms (two per point and per segment in each view that sees it).
    int iterations = 0;    //!< Levenberg-Marquardt steps tried (accepted or rejected).
};

/** The uncertainty of a refined pose (the convention: doc/conventions.md, "Pose covariance").
The covariance is the inverse of the 6x6 pose block of the Gauss-Newton normal equations J^T w J at
the returned estimate with the structure marginalised (eliminated, undamped): the first-order
covariance of the maximum-likelihood pose for observation noise of 1 px per coordinate (a point's
two coordinates; a segment end point's distance to the line), in the order [rotation; translation],
the rotation error d as in R_est = exp([d]x) R_true, the translation error t_est - t_true. Scale
it by the noise variance. With a robust loss the weights w are the IRLS weights at the estimate
(1 for the squared loss).
*/
struct PoseCovariance
{
    Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
    /** The estimate of the noise variance (px^2) from the residuals: sum of w r^2 over the residuals
    of the features in the cost, divided by their number minus the parameters (6 + 3 per point + 4 per
    line); +inf when there are not more residuals than parameters. */
    double noiseVariance = std::numeric_limits<double>::infinity();
    /** False, and the values above meaningless, when the refinement had no usable feature or the
    pose is not determined: the reduced pose block is singular, or a value is not finite. */
    bool valid = false;
};

//! Refined 3D structure, in the order of the selected features.
struct RefinedStructure
{
    std::vector<Eigen::Vector3d> points;   //!< One per selected point.
    std::vector<Eigen::Vector3d> lineEnds; //!< Two per selected line: the points closest to the end-point
                                           //!< rays of the first view that sees it.
    std::vector<unsigned char> pointUsed;  //!< 1 where the point entered the cost (else: its initialisation).
    std::vector<unsigned char> lineUsed;   //!< 1 where the line entered the cost.
    //! 1 where the refined line lies in front of every view that sees it, at the part each saw
    //! (geometry/segment_cheirality.hpp); a line's residuals do not tell, so the caller must.
    std::vector<unsigned char> lineInFront;
};

/** Maximum-likelihood refinement over every view of @p set: minimises the (robustified) reprojection
error in pixels (geometry/residuals.hpp) of the selected points and line segments in every view
that sees them, over the pose of the estimated camera (refined in place: R <- Exp(omega) R,
t <- t + dt; views that move with it follow through their mounts) and the structure (3D points;
3D lines in the orthonormal representation), with the known views fixed.

The structure starts from a triangulation over every view that sees it, the estimated ones at
@p pose. Features that their views do not determine (parallel rays, coinciding planes), points
behind a view and lines through a view's centre do not enter the cost. Levenberg-Marquardt on the
normal equations with each feature's structure eliminated (refine/schur_system.hpp), analytic
Jacobians (refine/observation_model.hpp), time linear in the number of features. @p params must be
valid (see checkRefineParams()). Null index lists select every point / line. The pose is never
replaced by non-finite values. @p covariance, when given, receives the uncertainty of the returned
pose (linearised once more at it, which costs one iteration). @p start, when given, is the
structure an earlier refinement of the same features returned (@p structure of a call capped by
params.maxIterations): the features it used continue from it instead of being re-triangulated.
*/
RefinementSummary refinePoseAndStructure(const ViewSet& data, CameraPose& pose, const RefineOptions& params,
                                         const std::vector<int>* pointIndices = nullptr,
                                         const std::vector<int>* lineIndices = nullptr,
                                         RefinedStructure* structure = nullptr,
                                         PoseCovariance* covariance = nullptr,
                                         const RefinedStructure* start = nullptr);

/** Maximum-likelihood refinement of several poses and the structure (a bundle adjustment with some
views fixed), as refinePoseAndStructure() over every feature of @p set: view v moves with pose
poseOfView[v] of @p poses (refined in place), at the mount set.views[v].pose (the identity for a
camera of its own), or is known when poseOfView[v] is -1. set.views[v].estimated must say the same.
The known views fix the gauge: the caller makes sure that they do (two known views at distinct
centres seeing shared features fix the world frame and the scale).
*/
RefinementSummary refinePosesAndStructure(const ViewSet& set, const std::vector<int>& poseOfView,
                                          std::vector<CameraPose>& poses, const RefineOptions& params,
                                          RefinedStructure* structure = nullptr);

} // namespace tripose

#endif // OPENCV_TRIPOSE_ML_REFINEMENT_HPP
