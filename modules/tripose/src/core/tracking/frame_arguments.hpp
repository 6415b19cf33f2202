// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_FRAME_ARGUMENTS_HPP
#define TRIPOSE_CORE_TRACKING_FRAME_ARGUMENTS_HPP

#include <vector>

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "../geometry/distortion.hpp"

namespace tripose {

//! Seconds on a steady clock, for the trackers' per-frame times.
double nowSeconds();

//! Fails, naming @p name, unless @p K is a camera matrix [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0.
void checkCameraMatrix(const Eigen::Matrix3d& K, const char* name);

//! The pose the caller gave, its rotation checked and made exact as every rotation argument is.
CameraPose checkedPose(const CameraPose& pose, const char* Rname = "R", const char* tname = "t");

/** Fails, naming "point_ids" or "line_ids", unless each holds one id per point (segment) and no id
twice: the checks of the trackers' observations. */
void checkObservationIds(size_t numPoints, const std::vector<int64_t>& pointIds, size_t numSegments,
                         const std::vector<int64_t>& lineIds);

//! @p coefficients (OpenCV's model: none, 4, 5, 8, 12 or 14) read into @p out; true when any is non-zero.
bool readDistortion(const std::vector<double>& coefficients, const char* name, Distortion& out);

} // namespace tripose

#endif
