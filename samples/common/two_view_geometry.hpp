// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The geometry of two calibrated views with a known relative pose that the image front end needs:
// the fundamental matrix behind the epipolar tests of matching, and the structure seen by views 1
// and 2 (points and segments), which the overlay and the triangulation + PnP comparison reproject.
// Poses follow the module: x ~ K (R X + t), the world frame is view 1's.
#ifndef TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP
#define TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP

#include <opencv2/core.hpp>

namespace tripose_samples {

//! F (3x3 CV_64F) with x2^T F x1 = 0 for views 1 (identity pose) and 2 (R12, t12).
cv::Matx33d fundamentalMatrix(const cv::Matx33d& K1, const cv::Matx33d& K2, const cv::Matx33d& R12,
                              const cv::Vec3d& t12);

//! Projection matrix K [R | t] (3x4).
cv::Matx34d projectionMatrix(const cv::Matx33d& K, const cv::Matx33d& R, const cv::Vec3d& t);

/** Points (Nx2 CV_64F, pixels of views 1 and 2) triangulated in view 1's frame (Nx3 CV_64F), linear
(DLT), as cv::triangulatePoints does. */
cv::Mat triangulatePoints(const cv::Mat& points1, const cv::Mat& points2, const cv::Matx34d& P1,
                          const cv::Matx34d& P2);

/** Segments of view 1 (Mx4) lifted to 3D (Mx6, in view 1's frame): each end point's ray of view 1
cut by the plane through view 2's centre and the matching segment of view 2 (Mx4). A row is NaN
where the ray runs parallel to that plane (a segment along the epipolar lines has no depth). */
cv::Mat triangulateSegments(const cv::Mat& lines1, const cv::Mat& lines2, const cv::Matx34d& P1,
                            const cv::Matx34d& P2);

//! @p X (3-vector) projected by @p P; false when it lies behind the camera (or at its centre plane).
bool projectPoint(const cv::Matx34d& P, const cv::Vec3d& X, cv::Point2d& x);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_TWO_VIEW_GEOMETRY_HPP
