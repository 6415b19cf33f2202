// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "p3l.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include <Eigen/LU>

#include "constrained_rotations.hpp"
#include "input_checks.hpp"

namespace tripose {

namespace {

// |det [n1 n2 n3]| of the unit normals below which the image lines are taken as concurrent.
constexpr double kConcurrentDeterminant = 1e-9;

} // namespace

int solveP3L(const Eigen::Vector3d imageLines[3], const WorldLine lines[3], std::vector<CameraPose>& poses)
{
    Eigen::Matrix3d N;
    Eigen::Vector3d directions[3];
    for (int j = 0; j < 3; ++j)
    {
        Eigen::Vector3d n;
        if (!unitVector(imageLines[j], n) || !unitVector(lines[j].direction, directions[j]) ||
            !lines[j].point.allFinite())
            return 0;
        N.row(j) = n.transpose();
    }
    if (!(std::abs(N.determinant()) > kConcurrentDeterminant))
        return 0;
    const Eigen::Matrix3d Ninverse = N.inverse();

    // The rank-one constraint is taken from a line of the most nearly parallel pair: the rotation
    // solver then meets that pair in its beta-free branch, which nearly parallel lines need.
    const double sines[3] = { directions[1].cross(directions[2]).norm(), directions[0].cross(directions[2]).norm(),
                              directions[0].cross(directions[1]).norm() };
    const int lonely = int(std::max_element(sines, sines + 3) - sines); // not in the most parallel pair
    const int first = lonely == 0 ? 1 : 0;
    const int second = 3 - lonely - first;
    const Eigen::Matrix3d G1 = N.row(second).transpose() * directions[second].transpose();
    const Eigen::Matrix3d G2 = N.row(lonely).transpose() * directions[lonely].transpose();
    Eigen::Matrix3d rotations[8];
    const int numRotations = solveConstrainedRotations(N.row(first).transpose(), directions[first], G1, G2, rotations);

    MinimalIncidences incidences;
    for (int j = 0; j < 3; ++j)
        lineIncidences(N.row(j).transpose(), lines[j], &incidences[2 * j]);
    int count = 0;
    for (int i = 0; i < numRotations; ++i)
    {
        CameraPose pose;
        pose.R = rotations[i];
        Eigen::Vector3d planeOffsets;
        for (int j = 0; j < 3; ++j)
            planeOffsets(j) = N.row(j).dot(pose.R * lines[j].point);
        pose.t = -Ninverse * planeOffsets;
        if (!polishPose(incidences, pose))
            continue;
        poses.push_back(pose);
        ++count;
    }
    return count;
}

} // namespace tripose
