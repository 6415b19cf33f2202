// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_OPTIONS_CONVERSION_HPP
#define OPENCV_TRIPOSE_OPENCV_OPTIONS_CONVERSION_HPP

#include "opencv2/tripose.hpp"

#include "../core/support/options.hpp"
#include "core_calls.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** The core's options from the public parameter structs, checked (core::Error naming
"params.<field>", which the entry points turn into cv::Exception).
*/
core::RefineOptions toCoreOptions(const RefineParams& params);
core::RansacOptions toCoreOptions(const RansacParams& params);

//! Raises cv::Exception naming @p method unless it is POSE_LINEAR or POSE_LINEAR_REFINE.
void checkPoseMethod(int method);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_OPTIONS_CONVERSION_HPP
