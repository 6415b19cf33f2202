// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "p1p2l.hpp"

#include <algorithm>
#include <cmath>

#include "constrained_rotations.hpp"
#include "input_checks.hpp"

namespace tripose {

int solveP1P2L(const Eigen::Vector3d& bearing, const Eigen::Vector3d& point, const Eigen::Vector3d imageLines[2],
               const WorldLine lines[2], std::vector<CameraPose>& poses)
{
    Eigen::Vector3d f, n[2], d[2];
    if (!unitVector(bearing, f) || !point.allFinite())
        return 0;
    for (int j = 0; j < 2; ++j)
        if (!unitVector(imageLines[j], n[j]) || !unitVector(lines[j].direction, d[j]) || !lines[j].point.allFinite())
            return 0;
    const Eigen::Vector3d Q[2] = { lines[0].point - point, lines[1].point - point };
    const double scale = std::max(Q[0].norm(), Q[1].norm());
    const double offsets[2] = { n[0].dot(f), n[1].dot(f) };
    if (!(scale > 0) || isOnLine(point, lines[0].point, d[0], scale) || isOnLine(point, lines[1].point, d[1], scale) ||
        !(std::max(std::abs(offsets[0]), std::abs(offsets[1])) > kDegenerateSine) ||
        !(n[0].cross(n[1]).norm() > kDegenerateSine))
        return 0;

    const Eigen::Matrix3d G1 = n[1] * d[1].transpose();
    const Eigen::Matrix3d G2 = offsets[1] * n[0] * Q[0].transpose() - offsets[0] * n[1] * Q[1].transpose();
    Eigen::Matrix3d rotations[8];
    const int numRotations = solveConstrainedRotations(n[0], d[0], G1, G2, rotations);

    MinimalIncidences incidences;
    pointIncidences(f, point, &incidences[0]);
    lineIncidences(n[0], lines[0], &incidences[2]);
    lineIncidences(n[1], lines[1], &incidences[4]);
    const double offsetNorm2 = offsets[0] * offsets[0] + offsets[1] * offsets[1];
    int count = 0;
    for (int i = 0; i < numRotations; ++i)
    {
        CameraPose pose;
        pose.R = rotations[i];
        const double depth =
            -(offsets[0] * n[0].dot(pose.R * Q[0]) + offsets[1] * n[1].dot(pose.R * Q[1])) / offsetNorm2;
        pose.t = depth * f - pose.R * point;
        if (!polishPose(incidences, pose) || !(f.dot(pose.toCamera(point)) > 0))
            continue;
        poses.push_back(pose);
        ++count;
    }
    return count;
}

} // namespace tripose
