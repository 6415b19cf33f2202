// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_INCIDENCES_HPP
#define OPENCV_TRIPOSE_MINIMAL_INCIDENCES_HPP

#include <array>

#include <Eigen/Core>

#include "../geometry/camera.hpp"

namespace tripose {

//! A 3D line of the known structure: the points point + s direction.
struct WorldLine
{
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();

    //! The line through two end points; its reference point is their midpoint, which lies on the
    //! observed segment.
    static WorldLine throughPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
    {
        WorldLine line;
        line.point = 0.5 * (a + b);
        line.direction = b - a;
        return line;
    }
};

/** One scalar equation of the point and line solvers: a plane through the camera centre, with unit
normal n in the camera frame, that contains a world point Y or is parallel to a world direction d,

    n^T (R Y + t) = 0   (point)   or   n^T R d = 0   (direction).

An image line l (calibrated, l^T (R Y + t) = 0 on its 3D line) gives two: its normal with the line's
point and with its direction. An image point with bearing f gives two: any two independent normals
orthogonal to f with the world point. Every minimal solver below thus ends in six such equations in
the six pose parameters, polished by one Newton routine.
*/
struct Incidence
{
    Eigen::Vector3d normal;
    Eigen::Vector3d world;
    bool isDirection;
};

using MinimalIncidences = std::array<Incidence, 6>;

//! The two incidences of the point @p X seen along the unit bearing @p f, written at @p out[0..1].
void pointIncidences(const Eigen::Vector3d& f, const Eigen::Vector3d& X, Incidence* out);

//! The two incidences of @p line seen as the image line with unit normal @p n, at @p out[0..1].
void lineIncidences(const Eigen::Vector3d& n, const WorldLine& line, Incidence* out);

/** Newton's method on the six incidences (left-multiplied rotation increment, additive
translation) from @p pose; returns whether the result satisfies every incidence to within a small
angle: each residual divided by |R Y + t| (point) or |d| (direction) is the sine of the angle
between the plane and the point's ray or the direction. A square system: rescaling an equation does
not change the Newton step, so the normalisation only serves the acceptance test. A root of a
solver's eliminant that is no pose (where its elimination divided by zero) fails the test.
*/
bool polishPose(const MinimalIncidences& incidences, CameraPose& pose);

//! A unit vector orthogonal to the unit vector @p a.
Eigen::Vector3d orthogonalUnitVector(const Eigen::Vector3d& a);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_INCIDENCES_HPP
