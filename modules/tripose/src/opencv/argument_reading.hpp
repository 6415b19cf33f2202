// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_ARGUMENT_READING_HPP
#define OPENCV_TRIPOSE_OPENCV_ARGUMENT_READING_HPP

#include <vector>

#include "opencv2/core.hpp"

#include "../core/geometry/view_set.hpp"
#include "../core/problem/problem_arguments.hpp"
#include "core_calls.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** The entry points' arguments read into the core's problems (core/problem/view_set_builder.hpp):
this file checks what only OpenCV's types can get wrong (depth, channels, layout) and copies the
values; the core validates the rest. Every violation raises cv::Exception whose message names the
argument.
*/

//! Views 1 at [I|0], 2 at [R12|t12], 3 estimated (estimatePoseLinePoint() and its relatives).
core::ViewSet readThreeViewInput(InputArray points1, InputArray points2, InputArray points3, InputArray lines1,
                                 InputArray lines2, InputArray lines3, InputArrayOfArrays cameraMatrix,
                                 InputArrayOfArrays distCoeffs, InputArray R12, InputArray t12, int minFeatures = 4);

//! The stereo rig's four views (estimatePoseLinePointStereo() and its relatives).
core::ViewSet readStereoRigInput(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                 InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                 InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs, InputArray R12,
                                 InputArray t12, int minFeatures);

//! Several known views and a new one (estimatePoseMultiView() and its relatives).
core::ViewSet readMultiViewInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                                 InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                                 int minFeatures);

//! Views of known pose only (triangulateMultiView()).
core::ViewSet readPosedViewsInput(InputArrayOfArrays points, InputArrayOfArrays lines,
                                  InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                  InputArrayOfArrays Rs, InputArrayOfArrays ts);

//! Several views whose poses are refined together (adjustPosesMultiView()).
core::ViewSet readSeveralPosesInput(InputArrayOfArrays points, InputArrayOfArrays lines,
                                    InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                    InputArrayOfArrays Rs, InputArrayOfArrays ts, InputArray fixedViews,
                                    std::vector<int>& poseOfView, std::vector<core::CameraPose>& initialPoses);

//! A 3x3 rotation matrix or a Rodrigues vector, checked and made an exact rotation.
Eigen::Matrix3d readRotation(InputArray rotation, const char* name);

//! A 3-element translation, finite (and non-zero with @p nonZero).
Eigen::Vector3d readTranslation(InputArray translation, const char* name, bool nonZero);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_ARGUMENT_READING_HPP
