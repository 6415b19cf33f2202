// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "p2p1l.hpp"

#include <algorithm>
#include <cmath>

#include "constrained_rotations.hpp"
#include "input_checks.hpp"

namespace tripose {

int solveP2P1L(const Eigen::Vector3d bearings[2], const Eigen::Vector3d points[2], const Eigen::Vector3d& imageLine,
               const WorldLine& line, std::vector<CameraPose>& poses)
{
    Eigen::Vector3d f1, f2, n, d;
    if (!unitVector(bearings[0], f1) || !unitVector(bearings[1], f2) || !unitVector(imageLine, n) ||
        !unitVector(line.direction, d) || !points[0].allFinite() || !points[1].allFinite() || !line.point.allFinite())
        return 0;
    const Eigen::Vector3d D = points[1] - points[0];
    const double separation = D.norm();
    const double scale = std::max(separation, (line.point - points[0]).norm());
    Eigen::Vector3d m;
    if (!(separation > kDegenerateSine * scale) || !unitVector(f1.cross(f2), m, kDegenerateSine) ||
        isOnLine(points[0], line.point, d, scale) || isOnLine(points[1], line.point, d, scale) ||
        !(n.cross(m).norm() > kDegenerateSine))
        return 0;

    const Eigen::Vector3d mf2 = m.cross(f2);
    const Eigen::Vector3d g = mf2 / mf2.dot(f1);
    const Eigen::Vector3d Q = line.point - points[0];
    const Eigen::Matrix3d G1 = n * d.transpose();
    const Eigen::Matrix3d G2 = n * Q.transpose() - n.dot(f1) * g * D.transpose();
    Eigen::Matrix3d rotations[8];
    const int numRotations = solveConstrainedRotations(m, D / separation, G1, G2, rotations);

    MinimalIncidences incidences;
    pointIncidences(f1, points[0], &incidences[0]);
    pointIncidences(f2, points[1], &incidences[2]);
    lineIncidences(n, line, &incidences[4]);
    int count = 0;
    for (int i = 0; i < numRotations; ++i)
    {
        CameraPose pose;
        pose.R = rotations[i];
        pose.t = -g.dot(pose.R * D) * f1 - pose.R * points[0];
        if (!polishPose(incidences, pose) || !(f1.dot(pose.toCamera(points[0])) > 0) ||
            !(f2.dot(pose.toCamera(points[1])) > 0))
            continue;
        poses.push_back(pose);
        ++count;
    }
    return count;
}

} // namespace tripose
