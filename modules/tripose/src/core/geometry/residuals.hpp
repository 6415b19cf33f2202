// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_RESIDUALS_HPP
#define OPENCV_TRIPOSE_GEOMETRY_RESIDUALS_HPP

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "camera.hpp"
#include "line_parameterization.hpp"

namespace tripose {

/** The two residuals of every observation, in pixels, that scoring, inlier tests and refinement all
measure (the maximum-likelihood residuals under Gaussian image noise on points and segment end
points):
- a point: its projection minus the observed pixel;
- a line: the signed distances of the two observed end points to the image of the 3D line.
The functions below are the only place they are computed; the Jacobians are with respect to the
feature in the camera frame, so one chain rule serves every pose parameterization.
*/

typedef Eigen::Matrix<double, 2, 3> Matrix23d;

/** Residual of a point at @p Xc (camera frame) observed at @p observed (pixels), and optionally
d(residual)/d(Xc). False, with nothing written, when the point is not in front of the camera
(depth <= @p minDepth).
*/
inline bool pointResidual(const Intrinsics& c, const Eigen::Vector3d& Xc, const Eigen::Vector2d& observed,
                          Eigen::Vector2d& residual, Matrix23d* jacobian = nullptr, double minDepth = 0)
{
    if (!(Xc.z() > minDepth))
        return false;
    const double iz = 1.0 / Xc.z();
    const double x = Xc.x() * iz, y = Xc.y() * iz;
    residual << c.fx * x + c.shear * y + c.cx - observed.x(), c.fy * y + c.cy - observed.y();
    if (jacobian)
        *jacobian << c.fx * iz, c.shear * iz, -(c.fx * x + c.shear * y) * iz, 0, c.fy * iz, -c.fy * y * iz;
    return true;
}

/** Moment, in the camera frame of @p pose, of the 3D line @p L: R m + t x (R d). It is the line's
image in calibrated coordinates (up to scale).
*/
inline Eigen::Vector3d lineMomentInCamera(const CameraPose& pose, const PluckerLine& L)
{
    const Eigen::Vector3d Rd = pose.R * L.d;
    return pose.R * L.m + pose.t.cross(Rd);
}

/** Residuals of a 3D line whose moment in the camera frame is @p moment (for two points A, B of the
line in that frame, A x B) against the observed end points @p end0, @p end1 (pixels), and optionally
d(residuals)/d(moment). False, with nothing written, when the image line is undefined: the line
passes through the camera centre (|image line normal| <= @p minNorm, in the units of lineK * moment).
*/
inline bool lineResidual(const Intrinsics& c, const Eigen::Vector3d& moment, const Eigen::Vector2d& end0,
                         const Eigen::Vector2d& end1, Eigen::Vector2d& residual, Matrix23d* jacobian = nullptr,
                         double minNorm = 0)
{
    const Eigen::Vector3d l = c.lineK * moment;
    const double n = l.head<2>().norm();
    if (!(n > minNorm) || !std::isfinite(n))
        return false;
    const double invN = 1.0 / n;
    const Eigen::Vector3d p0 = end0.homogeneous(), p1 = end1.homogeneous();
    residual << l.dot(p0) * invN, l.dot(p1) * invN;
    if (jacobian)
    {
        // d(l.p / |l_12|) / dl = (p - r n_hat) / |l_12|, n_hat the unit normal (l_1, l_2, 0) / |l_12|.
        const Eigen::Vector3d normal(l(0) * invN, l(1) * invN, 0.0);
        jacobian->row(0).noalias() = (invN * (p0 - residual(0) * normal)).transpose() * c.lineK;
        jacobian->row(1).noalias() = (invN * (p1 - residual(1) * normal)).transpose() * c.lineK;
    }
    return true;
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_RESIDUALS_HPP
