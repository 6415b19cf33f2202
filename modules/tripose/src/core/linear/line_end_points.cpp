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

namespace {

// Sine of the angle between a view-1 end ray and the plane of view 2 below which the lifted end
// point is too uncertain to weight a row by.
constexpr double kGrazingSine = 1e-6;

} // namespace

bool lineEndPoints(const ViewSet& set, int line, const CameraPose& pose12, Eigen::Vector4d& qa, Eigen::Vector4d& qb,
                   double weights[2])
{
    const Eigen::Vector4d plane2 = backProjectLine(pose12, 1.0, set.views[ViewSet::kView2].calibratedLines[line]);
    const Eigen::Vector3d centre2 = pose12.centre();
    Eigen::Vector4d* q[2] = { &qa, &qb };
    for (int end = 0; end < 2; ++end)
    {
        const Eigen::Vector3d ray = set.views[ViewSet::kView1].calibratedLineEnd(line, end).homogeneous();
        Eigen::Vector3d X;
        double lambda;
        if (!intersectRayPlane(Eigen::Vector3d::Zero(), ray, plane2, kGrazingSine, X, lambda))
            return false;
        const double sinBeta = std::abs(plane2.head<3>().dot(ray)) / (plane2.head<3>().norm() * ray.norm());
        *q[end] << ray, 1.0 / lambda;
        const double sinAlpha = ray.normalized().cross((X - centre2).normalized()).norm();
        weights[end] = sinBeta / std::sqrt(sinBeta * sinBeta + sinAlpha * sinAlpha);
    }
    return true;
}

} // namespace tripose
