// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The geometry of two calibrated views with a known relative pose that the image front end needs:
// the fundamental matrix behind the epipolar tests of matching, and projection (the structure of
// views 1 and 2 comes from the support library's known_pair_structure.hpp).
// Poses follow the module: x ~ K (R X + t), the world frame is view 1's.
#ifndef TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP
#define TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP

#include <opencv2/core.hpp>

namespace tripose_samples {

//! F (3x3 CV_64F) with x2^T F x1 = 0 for views 1 (identity pose) and 2 (R12, t12).
cv::Matx33d fundamentalMatrix(const cv::Matx33d& K1, const cv::Matx33d& K2, const cv::Matx33d& R12,
                              const cv::Vec3d& t12);

//! @p X (3-vector) projected by @p P; false when it lies behind the camera (or at its centre plane).
bool projectPoint(const cv::Matx34d& P, const cv::Vec3d& X, cv::Point2d& x);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP
