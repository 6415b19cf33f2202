// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "trajectory_io.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tripose_samples {

namespace {

//! The rotation of the unit quaternion (x, y, z, w).
cv::Matx33d rotationOf(double x, double y, double z, double w)
{
    return cv::Matx33d(1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                       2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                       2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y));
}

//! The unit quaternion (x, y, z, w) of rotation @p R, w >= 0.
cv::Vec4d quaternionOf(const cv::Matx33d& R)
{
    const double trace = R(0, 0) + R(1, 1) + R(2, 2);
    double x, y, z, w;
    if (trace > 0)
    {
        const double s = 2 * std::sqrt(1 + trace);
        w = s / 4;
        x = (R(2, 1) - R(1, 2)) / s;
        y = (R(0, 2) - R(2, 0)) / s;
        z = (R(1, 0) - R(0, 1)) / s;
    }
    else if (R(0, 0) > R(1, 1) && R(0, 0) > R(2, 2))
    {
        const double s = 2 * std::sqrt(1 + R(0, 0) - R(1, 1) - R(2, 2));
        w = (R(2, 1) - R(1, 2)) / s;
        x = s / 4;
        y = (R(0, 1) + R(1, 0)) / s;
        z = (R(0, 2) + R(2, 0)) / s;
    }
    else if (R(1, 1) > R(2, 2))
    {
        const double s = 2 * std::sqrt(1 + R(1, 1) - R(0, 0) - R(2, 2));
        w = (R(0, 2) - R(2, 0)) / s;
        x = (R(0, 1) + R(1, 0)) / s;
        y = s / 4;
        z = (R(1, 2) + R(2, 1)) / s;
    }
    else
    {
        const double s = 2 * std::sqrt(1 + R(2, 2) - R(0, 0) - R(1, 1));
        w = (R(1, 0) - R(0, 1)) / s;
        x = (R(0, 2) + R(2, 0)) / s;
        y = (R(1, 2) + R(2, 1)) / s;
        z = s / 4;
    }
    const double sign = w < 0 ? -1 : 1;
    return cv::Vec4d(sign * x, sign * y, sign * z, sign * w);
}

} // namespace

std::vector<StampedPose> readTumTrajectory(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw std::runtime_error(path + ": cannot open the trajectory");
    std::vector<StampedPose> poses;
    std::string line;
    int number = 0;
    while (std::getline(in, line))
    {
        ++number;
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
            continue;
        std::istringstream fields(line);
        double v[8];
        int n = 0;
        while (n < 8 && fields >> v[n])
            ++n;
        std::string rest;
        if (n != 8 || (fields >> rest) || !std::isfinite(v[0] + v[1] + v[2] + v[3] + v[4] + v[5] + v[6] + v[7]))
            throw std::runtime_error(path + ":" + std::to_string(number) +
                                     ": expected 'timestamp tx ty tz qx qy qz qw' (TUM), got '" + line + "'");
        const double norm = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
        if (std::abs(norm - 1) > 1e-3)
            throw std::runtime_error(path + ":" + std::to_string(number) + ": the quaternion is not of unit length (" +
                                     std::to_string(norm) + ")");
        StampedPose pose;
        pose.timestamp = v[0];
        const cv::Matx33d cameraToWorld = rotationOf(v[4] / norm, v[5] / norm, v[6] / norm, v[7] / norm);
        pose.R = cameraToWorld.t();
        pose.t = -(pose.R * cv::Vec3d(v[1], v[2], v[3]));
        poses.push_back(pose);
    }
    return poses;
}

std::string tumLine(const StampedPose& pose)
{
    const cv::Matx33d cameraToWorld = pose.R.t();
    const cv::Vec3d centre = -(cameraToWorld * pose.t);
    const cv::Vec4d q = quaternionOf(cameraToWorld);
    return cv::format("%.9f %.17g %.17g %.17g %.17g %.17g %.17g %.17g", pose.timestamp, centre[0], centre[1], centre[2],
                      q[0], q[1], q[2], q[3]);
}

} // namespace tripose_samples
