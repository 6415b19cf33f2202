// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "../geometry/triangulation.hpp"
#include "line_end_points.hpp"

namespace tripose {

bool lineEndPoints(const ViewSet& set, int line, const CameraPose& pose12, Eigen::Vector4d& qa, Eigen::Vector4d& qb,
                   double weights[2])
{
    const View& view1 = set.views[ViewSet::kView1];
    const Eigen::Vector4d plane2 = backProjectLine(pose12, 1.0, set.views[ViewSet::kView2].calibratedLines[line]);
    const Eigen::Vector3d centre2 = pose12.centre();
    Eigen::Vector4d* q[2] = { &qa, &qb };
    for (int end = 0; end < 2; ++end)
    {
        // View 1 is the world frame: its ray is [x; 1] and the depth along it is lambda.
        const Eigen::Vector2d x = view1.calibratedLineEnd(line, end);
        Eigen::Vector3d X;
        double lambda;
        if (!liftLineEnd(view1.pose, x, plane2, X, lambda))
            return false;
        const Eigen::Vector3d ray = x.homogeneous();
        const double sinBeta = std::abs(plane2.head<3>().dot(ray)) / (plane2.head<3>().norm() * ray.norm());
        *q[end] << ray, 1.0 / lambda;
        const double sinAlpha = ray.normalized().cross((X - centre2).normalized()).norm();
        weights[end] = sinBeta / std::sqrt(sinBeta * sinBeta + sinAlpha * sinAlpha);
    }
    return true;
}

} // namespace tripose
