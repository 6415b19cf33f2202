// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_INPUT_CHECKS_HPP
#define OPENCV_TRIPOSE_MINIMAL_INPUT_CHECKS_HPP

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tripose {

/** Sine of the angle (or relative distance) below which the minimal solvers take a configuration
as degenerate: parallel rays, a point on a line, an image line through an image point's ray. Exact
degeneracies leave only rounding (about 1e-16); the margin covers input that was itself computed.
*/
constexpr double kDegenerateSine = 1e-9;

//! @p v / |v| into @p unit; false when v is not finite or |v| <= @p minNorm.
inline bool unitVector(const Eigen::Vector3d& v, Eigen::Vector3d& unit, double minNorm = 0.0)
{
    const double length = v.norm();
    if (!(length > minNorm) || !std::isfinite(length))
        return false;
    unit = v / length;
    return true;
}

//! Whether @p X is within kDegenerateSine * @p scale of the line through @p P along the unit @p d.
inline bool isOnLine(const Eigen::Vector3d& X, const Eigen::Vector3d& P, const Eigen::Vector3d& d, double scale)
{
    return !((X - P).cross(d).norm() > kDegenerateSine * scale);
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_INPUT_CHECKS_HPP
