// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_TRIANGULATION_HPP
#define OPENCV_TRIPOSE_GEOMETRY_TRIANGULATION_HPP

#include <vector>

#include <Eigen/Core>

#include "line_parameterization.hpp"
#include "view_set.hpp"

namespace tripose {

//! Which views of a ViewSet a triangulation uses (always only those that see the feature).
enum class ViewSelection
{
    Known, //!< The views whose pose is known: structure independent of the estimated pose.
    All,   //!< Every view, the estimated ones at the given pose.
};

//! Pose of every view of @p set when the estimated camera is at @p estimatedPose.
std::vector<CameraPose> viewPoses(const ViewSet& set, const CameraPose& estimatedPose);

/** Point @p point of @p set from the selected views that see it, by linear least squares whose rows
approximate pixel errors: each view's two rows are scaled by its focal length and, in a second pass,
divided by the depth found in the first (which turns the algebraic error into the reprojection
error to first order). @p poses holds the pose of every view (viewPoses()).

Returns det / trace^3 of the 3x3 normal matrix, a lower bound of its inverse condition number, and
0 (X unchanged) when fewer than two views see the point or that measure is below
@p minConditioning (rays nearly parallel). A point that lands at a depth <= @p minDepth in a view
after the first pass keeps that first-pass position: the caller's depth test then rejects it.
*/
double triangulatePoint(const ViewSet& set, const CameraPose* poses, int point, ViewSelection which,
                        Eigen::Vector3d& X, double minConditioning, double minDepth);

/** Plane through the centre of a camera at @p pose and its calibrated image line @p line, as
homogeneous coordinates scaled by @p focal so that its value at a point is, to first order, the
depth times the pixel distance of the point's projection to the line.
*/
inline Eigen::Vector4d backProjectLine(const CameraPose& pose, double focal, const Eigen::Vector3d& line)
{
    Eigen::Vector4d plane;
    plane.head<3>() = focal * (pose.R.transpose() * line);
    plane(3) = focal * pose.t.dot(line);
    return plane;
}

/** Line @p line of @p set from the back-projected planes of the selected views that see it
(lineFromPlanes()); false when fewer than two views see it or the planes do not pin it down
(@p minRatio as in lineFromPlanes()).
*/
bool triangulateLine(const ViewSet& set, const CameraPose* poses, int line, ViewSelection which, PluckerLine& L,
                     double minRatio);

/** Where the ray from @p origin along @p direction meets @p plane (homogeneous, pi^T [X; 1] = 0):
false when the ray is within @p minSine of parallel to the plane (sine of the angle between them)
or meets it behind the origin. @p depth receives the distance along @p direction in its units.
*/
inline bool intersectRayPlane(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              const Eigen::Vector4d& plane, double minSine, Eigen::Vector3d& X, double& depth)
{
    const double denominator = plane.head<3>().dot(direction);
    if (!(std::abs(denominator) > minSine * plane.head<3>().norm() * direction.norm()))
        return false;
    depth = -(plane.head<3>().dot(origin) + plane(3)) / denominator;
    X = origin + depth * direction;
    return depth > 0 && X.allFinite();
}

/** Sine of the angle between an end point's ray and the plane it is lifted onto (liftLineEnd())
below which the intersection is not taken. The depth's rounding error is about 1e-16 / sine of the
depth, so at this bound it still holds seven digits, more than any image measurement carries: the
bound only keeps the arithmetic defined. The larger uncertainty of a grazing ray under image noise
(the depth error grows as 1 / sine) is weighed where the lifted point is used: the linear solver
weights the point's row by the sine, the scorer tests the point's depth in every known view.
*/
constexpr double kGrazingSine = 1e-9;

/** End point @p end (calibrated image coordinates) of a line seen by a camera at @p pose, lifted
onto @p plane, the line's back-projected plane from another view (backProjectLine()): where the end
point's ray meets the plane. @p depth receives its depth in the camera. Returns false when the ray
grazes the plane (kGrazingSine) or meets it behind the camera.
*/
inline bool liftLineEnd(const CameraPose& pose, const Eigen::Vector2d& end, const Eigen::Vector4d& plane,
                        Eigen::Vector3d& X, double& depth)
{
    return intersectRayPlane(pose.centre(), pose.R.transpose() * end.homogeneous(), plane, kGrazingSine, X, depth);
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_TRIANGULATION_HPP
