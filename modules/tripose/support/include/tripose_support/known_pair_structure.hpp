// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The structure a user without this module starts from: points and segments triangulated from the
// two known views alone (view 1 at [I|0], view 2 at [R12|t12]), as the triangulation + PnP peers of
// the tests, the samples and the evaluation compute it. Part of the tripose support library (built
// beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_KNOWN_PAIR_STRUCTURE_HPP
#define TRIPOSE_SUPPORT_KNOWN_PAIR_STRUCTURE_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

//! The projection matrix K [R | t] (3x4).
Matx34d projectionMatrix(const Matx33d& K, const Matx33d& R, const Vec3d& t);

/** Points (Nx2 CV_64F pixels of views 1 and 2) triangulated by cv::triangulatePoints (DLT) into
view 1's frame: Nx3 CV_64F.
*/
Mat triangulateKnownPair(const Matx33d& K1, const Matx33d& K2, const Matx33d& R12, const Vec3d& t12,
                         const Mat& points1, const Mat& points2);

/** Segments of view 1 (Mx4 CV_64F) lifted into view 1's frame (Mx6 CV_64F, two end points): each
end point's ray of view 1 cut by the plane through view 2's centre and the matching segment of view 2
(Mx4). An end point whose ray meets that plane at a sine of the angle below @p minSine is NaN: the
two views do not fix its depth.
*/
Mat liftSegmentsKnownPair(const Matx33d& K1, const Matx33d& K2, const Matx33d& R12, const Vec3d& t12,
                          const Mat& lines1, const Mat& lines2, double minSine);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_KNOWN_PAIR_STRUCTURE_HPP
