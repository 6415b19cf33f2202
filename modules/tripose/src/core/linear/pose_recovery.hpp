// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POSE_RECOVERY_HPP
#define OPENCV_TRIPOSE_POSE_RECOVERY_HPP

#include "kernel_solutions.hpp"
#include "linear_system.hpp"
#include "../geometry/camera.hpp"
#include "../geometry/rotation.hpp"

namespace tripose {

typedef Eigen::Matrix<double, 9, 9> Matrix9d;
typedef Eigen::Matrix<double, 9, 1> Vector9d;

/** The algebraic error v^T M v (M = A^T A, v = [r; t], r = vec(R) column by column) with the
translation eliminated. For a fixed R the least-squares translation is t = T r,
T = -M_tt^-1 M_tr (@cite QadirNeubert2017, eq. 28), and the error left is r^T S r with
S = M_rr - M_rt M_tt^-1 M_tr (Schur complement). Every candidate needs both, so they are formed once
per system.
*/
struct ReducedNormalSystem
{
    Matrix9d S;
    Eigen::Matrix<double, 3, 9> T;
};

/** Forms the reduced system of @p normalMatrix. Returns false when the rows do not determine the
translation (M_tt numerically singular).
*/
bool reduceNormalMatrix(const Matrix12d& normalMatrix, ReducedNormalSystem& system);

/** A pose from a solution vector v = [r1; r2; r3; t] of unknown scale and sign
(@cite QadirNeubert2017, Sec. III-D, III-E): scale and sign from det(R) = 1, the nearest rotation,
then the translation by least squares with R fixed (t = T r; the t part of v is not used). Returns
false for a degenerate v (det(R) ~ 0).
*/
bool poseFromSolutionVector(const Vector12d& v, const ReducedNormalSystem& system, CameraPose& pose);

/** The algebraic error over R in SO(3) with t eliminated (r^T S r) minimised from @p pose by
polishRotation(); t is set to its least-squares value T r at the end. The same minimum as over
(R, t) jointly, at half the cost per step.
*/
void polishPoseAlgebraic(const ReducedNormalSystem& system, CameraPose& pose);

} // namespace tripose

#endif // OPENCV_TRIPOSE_POSE_RECOVERY_HPP
