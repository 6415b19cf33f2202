// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ML_REFINEMENT_HPP
#define OPENCV_TRIPOSE_ML_REFINEMENT_HPP

#include <vector>

#include <Eigen/Core>

#include "../support/options.hpp"
#include "../geometry/view_set.hpp"

namespace tripose {

struct RefinementSummary
{
    double initialRms = 0; //!< RMS reprojection error (px) over every view at the start (+inf: nothing usable).
    double finalRms = 0;   //!< The same at the returned estimate.
    int iterations = 0;    //!< Levenberg-Marquardt steps tried (accepted or rejected).
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
replaced by non-finite values.
*/
RefinementSummary refinePoseAndStructure(const ViewSet& data, CameraPose& pose, const RefineOptions& params,
                                         const std::vector<int>* pointIndices = nullptr,
                                         const std::vector<int>* lineIndices = nullptr,
                                         RefinedStructure* structure = nullptr);

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
