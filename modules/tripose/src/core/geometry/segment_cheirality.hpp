// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_SEGMENT_CHEIRALITY_HPP
#define OPENCV_TRIPOSE_GEOMETRY_SEGMENT_CHEIRALITY_HPP

#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "camera.hpp"
#include "line_parameterization.hpp"

namespace tripose {

/** Cheirality of a line's observed segment: the part of the 3D line a camera saw must lie in front
of it.

A line's residuals (the distances of the observed end points to its image, geometry/residuals.hpp)
cannot tell: the image of a 3D line is the plane through the camera centre that contains it, and
the line reflected through the centre lies in the same plane. For planar structure a pose turned by
pi about the plane's normal does exactly that to the whole plane (X_camera -> -X_camera), and seen
through lines alone it explains every observation as well as the true pose. The end points decide:
the point of the line seen at an end point must be in front of the camera.
*/

/** Below this sine of the angle between an end point's ray and the line, the point of the line seen
there is not placed: near the line's vanishing point it is at a depth that image noise sends through
infinity, to either sign. A tenth of a degree, a pixel or two for typical focal lengths. */
constexpr double kSegmentGrazingSine = 2e-3;

/** Depth in the camera of the point of a 3D line that projects to the calibrated image point
@p end, for the line's moment @p moment and direction @p direction in the camera frame (any common
scale, either sign): that point is lambda (end, 1) with moment lambda (end, 1) x direction, so in
the least-squares sense lambda = moment . (ray x direction) / |ray x direction|^2. NaN when the ray
is within kSegmentGrazingSine of the line's direction.
*/
inline double lineDepthAtImagePoint(const Eigen::Vector3d& moment, const Eigen::Vector3d& direction,
                                    const Eigen::Vector2d& end)
{
    const Eigen::Vector3d ray = end.homogeneous();
    const Eigen::Vector3d normal = ray.cross(direction);
    const double n2 = normal.squaredNorm();
    if (!(n2 > kSegmentGrazingSine * kSegmentGrazingSine * ray.squaredNorm() * direction.squaredNorm()))
        return std::numeric_limits<double>::quiet_NaN();
    return moment.dot(normal) / n2;
}

/** True when the segment with calibrated end points @p end0, @p end1 is seen behind the camera: the
points of the line (moment and direction in the camera frame, lineDepthAtImagePoint()) at both end
points have a depth <= 0. One end in front and one behind is a line whose direction the views leave
loose enough to cross infinity within the segment (its far end near the vanishing point): its side
is not determined, and a valid pose must not lose it. An end point whose ray grazes the line decides
nothing.
*/
inline bool segmentBehindCamera(const Eigen::Vector3d& moment, const Eigen::Vector3d& direction,
                                const Eigen::Vector2d& end0, const Eigen::Vector2d& end1)
{
    // Negated comparisons: a NaN (grazing) depth is not behind.
    return lineDepthAtImagePoint(moment, direction, end0) <= 0 && lineDepthAtImagePoint(moment, direction, end1) <= 0;
}

/** segmentBehindCamera() for the world line @p L seen by a camera at @p pose. */
inline bool segmentBehindCamera(const CameraPose& pose, const PluckerLine& L, const Eigen::Vector2d& end0,
                                const Eigen::Vector2d& end1)
{
    const Eigen::Vector3d direction = pose.R * L.d;
    return segmentBehindCamera(pose.R * L.m + pose.t.cross(direction), direction, end0, end1);
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_SEGMENT_CHEIRALITY_HPP
