// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "p3l.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include <Eigen/LU>

#include "constrained_rotations.hpp"
#include "input_checks.hpp"

namespace cv {
namespace tripose {
namespace detail {

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

    const Eigen::Matrix3d G1 = N.row(1).transpose() * directions[1].transpose();
    const Eigen::Matrix3d G2 = N.row(2).transpose() * directions[2].transpose();
    Eigen::Matrix3d rotations[8];
    const int numRotations = solveConstrainedRotations(N.row(0).transpose(), directions[0], G1, G2, rotations);

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

} // namespace detail
} // namespace tripose
} // namespace cv
