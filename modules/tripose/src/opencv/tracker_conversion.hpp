// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_TRACKER_CONVERSION_HPP
#define OPENCV_TRIPOSE_OPENCV_TRACKER_CONVERSION_HPP

#include <Eigen/Core>

#include "opencv2/core.hpp"

#include "opencv2/tripose/tracker.hpp"

#include "../core/geometry/camera.hpp"
#include "../core/tracking/track_store.hpp"
#include "../core/tracking/tracker_options.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! The core's tracker options from the public parameters, checked (core::Error naming "params.<field>").
::tripose::TrackerOptions toCoreOptions(const TrackerParams& params);

/** A frame's pose from @p R (3x3 or a rotation vector) and @p t (3 elements), given together or
not at all; false when neither is given. cv::Exception naming "R" or "t" otherwise. */
bool readFramePose(InputArray R, InputArray t, ::tripose::CameraPose& pose);

//! The distortion coefficients as given (converted to double); empty when @p distCoeffs is.
std::vector<double> readDistortion(InputArray distCoeffs);

//! cv::Exception (out of range) unless @p frame is one of the @p numFrames frames tracked.
void checkFrameIndex(int frame, int numFrames);

//! The pose of a tracked frame written to @p R and @p t; false, leaving them, when it has none.
bool writeFramePose(const ::tripose::StoredFrame& frame, OutputArray R, OutputArray t);

Mat matOf(const Eigen::Matrix3d& R); //!< 3x3 CV_64F.
Mat matOf(const Eigen::Vector3d& t); //!< 3x1 CV_64F.

TrackedFrame toTrackedFrame(const ::tripose::FrameResult& result);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_TRACKER_CONVERSION_HPP
