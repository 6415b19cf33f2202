// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// How far an estimated pose is from a reference one: the one measure that the module's tests, the
// samples, the benchmarks and the evaluation report, so that their figures compare. Part of the
// tripose support library (built beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_POSE_ERROR_HPP
#define TRIPOSE_SUPPORT_POSE_ERROR_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

//! Distance of a pose (R, t) from a reference pose (Rref, tref); see poseError().
struct PoseError
{
    double rotationDeg;         //!< Angle (degrees) of the rotation R Rref^T.
    double translation;         //!< |t - tref|, in the units of t.
    double relativeTranslation; //!< |t - tref| / |tref|.
};

/** @brief Rotation and translation errors of a pose (R, t) against a reference (Rref, tref).

Each rotation is a 3x3 matrix or a Rodrigues vector (3 elements: 3x1, 1x3 or one 3-channel
element) and each translation has 3 elements in any of those shapes, CV_32F or CV_64F; the two poses
need not have the same shapes. The rotation angle is computed from the chord
|R - Rref|_F = 2 sqrt(2) sin(angle / 2), which stays accurate for angles down to round-off, where
the arccos of the trace of R Rref^T cannot resolve less than about 1e-8 rad.
@throws cv::Exception naming the argument when a rotation or translation has another size or type
or holds NaN or Inf.
*/
PoseError poseError(InputArray R, InputArray t, InputArray Rref, InputArray tref);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_POSE_ERROR_HPP
