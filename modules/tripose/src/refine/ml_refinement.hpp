// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ML_REFINEMENT_HPP
#define OPENCV_TRIPOSE_ML_REFINEMENT_HPP

#include <vector>

#include <Eigen/Core>

#include "opencv2/tripose/refine.hpp"
#include "../geometry/view_set.hpp"

namespace cv {
namespace tripose {
namespace detail {

struct RefinementSummary
{
    double initialRms = 0; //!< RMS reprojection error (px) over the three views at the start (+inf: nothing usable).
    double finalRms = 0;   //!< The same at the returned estimate.
    int iterations = 0;    //!< Levenberg-Marquardt steps tried (accepted or rejected).
};

//! Refined 3D structure, in the order of the selected features.
struct RefinedStructure
{
    std::vector<Eigen::Vector3d> points;   //!< One per selected point.
    std::vector<Eigen::Vector3d> lineEnds; //!< Two per selected line: the points closest to the view-1 end rays.
    std::vector<unsigned char> pointUsed;  //!< 1 where the point entered the cost (else: its initialisation).
    std::vector<unsigned char> lineUsed;   //!< 1 where the line entered the cost.
};

/** Maximum-likelihood refinement over the three views: minimises the (robustified) reprojection
error in pixels of the selected points and line segments in views 1, 2 and 3 over the pose of view 3
(refined in place: R <- Exp(omega) R, t <- t + dt) and the structure (3D points; 3D lines in the
orthonormal representation), with views 1 and 2 fixed.

Levenberg-Marquardt on the normal equations with each feature's structure block eliminated
(Schur complement to a 6x6 system), analytic Jacobians and per-call buffers only, so it stays linear
in the number of features. @p params must be valid (see checkRefineParams()). Null index lists
select every point / line. The pose is never replaced by non-finite values.
*/
RefinementSummary refinePoseAndStructure(const ViewSet& data, CameraPose& pose, const RefineParams& params,
                                         const std::vector<int>* pointIndices = nullptr,
                                         const std::vector<int>* lineIndices = nullptr,
                                         RefinedStructure* structure = nullptr);

//! Throws cv::Exception (StsBadArg) naming the first out-of-range field of @p params, called @p name.
void checkRefineParams(const RefineParams& params, const char* name = "params");

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_ML_REFINEMENT_HPP
