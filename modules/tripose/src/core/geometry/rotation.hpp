// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_GEOMETRY_ROTATION_HPP
#define TRIPOSE_CORE_GEOMETRY_ROTATION_HPP

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tripose {

//! The rotation nearest to @p M in the Frobenius norm (det +1).
Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& M);

/** exp([w]x) R: the left multiplicative update by which every iterative method here moves a
rotation (the refinement, the algebraic polishes, the minimal solvers' Newton polish), so that their
increments mean the same.
*/
inline Eigen::Matrix3d rotateLeft(const Eigen::Vector3d& w, const Eigen::Matrix3d& R)
{
    const double angle = w.norm();
    return angle > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, w / angle) * R) : R;
}

/** R exp([w]x): the right update, in the frame of R itself, by which the orthonormal line
parameterisation moves its rotation U (line_parameterization).
*/
inline Eigen::Matrix3d rotateRight(const Eigen::Matrix3d& R, const Eigen::Vector3d& w)
{
    const double angle = w.norm();
    return angle > 0 ? Eigen::Matrix3d(R * Eigen::AngleAxisd(angle, w / angle).toRotationMatrix()) : R;
}

//! The rotation matrix of a rotation vector (axis times angle in radians).
inline Eigen::Matrix3d rotationFromVector(const Eigen::Vector3d& w)
{
    return rotateLeft(w, Eigen::Matrix3d::Identity());
}

//! The rotation vector (axis times angle in radians) of the rotation @p R, accurate near the identity.
Eigen::Vector3d rotationVector(const Eigen::Matrix3d& R);

} // namespace tripose

#endif // TRIPOSE_CORE_GEOMETRY_ROTATION_HPP
