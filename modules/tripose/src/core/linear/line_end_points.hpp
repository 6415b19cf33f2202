// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_LINE_END_POINTS_HPP
#define OPENCV_TRIPOSE_LINEAR_LINE_END_POINTS_HPP

#include <Eigen/Core>

#include "../geometry/view_set.hpp"

namespace tripose {

/** Two points of the 3D line of views 1-2, as the null-space pair of the line rows: where the rays
of the view-1 end points meet the plane of view 2, X = lambda [x; 1], written as q = [x; 1; 1/lambda]
(X / lambda). Any two points of the line span the same null space, so exact data gives the same
rows; this pair makes each row (R x + t / lambda) . l3 = (depth in view 3 / lambda) times the
distance of the projected end point to l3 (calibrated units), close to a geometric residual.

The depth lambda inherits the noise of l2 amplified by 1 / sin(beta), beta the angle between the
ray and the plane of view 2, and a depth error moves the projection in view 3 by about sin(alpha)
times as much, alpha the triangulation angle at X (views 1-2 stand in for views 1-3, unknown
here). Against the floor of the noise of l3 itself, the row's standard deviation is therefore
proportional to sqrt(1 + (sin alpha / sin beta)^2): @p weights receives its inverse per row.
The rows of view 4 of a stereo rig (rigLineRows) read the same way in view 4. Returns false when a
ray is nearly parallel to the plane or meets it behind view 1.
*/
bool lineEndPoints(const ViewSet& set, int line, const CameraPose& pose12, Eigen::Vector4d& qa, Eigen::Vector4d& qb,
                   double weights[2]);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_LINE_END_POINTS_HPP
