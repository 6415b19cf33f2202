// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POSE_RECOVERY_HPP
#define OPENCV_TRIPOSE_POSE_RECOVERY_HPP

#include "kernel_solutions.hpp"
#include "linear_system.hpp"
#include "triplet_data.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** A pose from a solution vector v = [r1; r2; r3; t] of unknown scale and sign
(@cite QadirNeubert2017, Sec. III-D, III-E): scale and sign from det(R) = 1, the nearest rotation
(SVD), then the translation by least squares with R fixed, t = -(A_t^T A_t)^-1 A_t^T A_r r (eq. 28),
read off the blocks of the normal matrix. Returns false for a degenerate v (det(R) ~ 0) or a
translation the system does not determine.
*/
bool poseFromSolutionVector(const Vector12d& v, const Matrix12d& normalMatrix, CameraPose& pose);

/** Gauss-Newton on the algebraic error v^T (A^T A) v over R in SO(3) and t, from @p pose (left
increment R <- exp([w]x) R). The nearest rotation of a kernel solution does not minimise the
algebraic error; with exact data this restores the exact pose to full precision whatever the
conditioning of the coefficient step, and with noise it lowers the error the method minimises.
Steps that do not lower the error are rejected, so the result is never worse than the input.
*/
void polishPoseAlgebraic(const Matrix12d& normalMatrix, CameraPose& pose);

//! The rotation nearest to M in the Frobenius norm (det +1).
Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& M);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_POSE_RECOVERY_HPP
