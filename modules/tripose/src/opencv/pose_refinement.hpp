// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_POSE_REFINEMENT_HPP
#define OPENCV_TRIPOSE_OPENCV_POSE_REFINEMENT_HPP

#include "opencv2/tripose.hpp"

#include "../core/geometry/view_set.hpp"
#include "core_calls.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** What the refine* entry points share: reads the initial pose from @p R (3x3 or Rodrigues, named
"R" in errors) and @p t, refines it over every view of @p views, writes the pose back as every
pose output is written (3x3 and 3x1 CV_64F), and the structure and the pose's uncertainty
(covariance_writing.hpp) where wanted. Returns the final RMS reprojection error (px).
*/
double refineGivenPose(const core::ViewSet& views, InputOutputArray R, InputOutputArray t, const RefineParams& params,
                       OutputArray points3d, OutputArray lines3d, OutputArray covariance, OutputArray noiseVariance);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_POSE_REFINEMENT_HPP
