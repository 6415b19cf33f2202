// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Trajectories in the TUM format: one line per pose, "timestamp tx ty tz qx qy qz qw", the camera's
// position and orientation in the world (camera to world), what trajectory evaluation tools read.
#ifndef TRIPOSE_SAMPLES_TRAJECTORY_IO_HPP
#define TRIPOSE_SAMPLES_TRAJECTORY_IO_HPP

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

//! One pose of a trajectory, in the module's convention: x_cam = R X + t.
struct StampedPose
{
    double timestamp = 0;
    cv::Matx33d R;
    cv::Vec3d t;
};

/** The poses of a TUM file, in the module's convention. Throws std::runtime_error naming the file and
line on a line that is not eight numbers or a quaternion that is not of unit length (within 1e-3;
it is then normalised). Lines starting with # are comments. */
std::vector<StampedPose> readTumTrajectory(const std::string& path);

//! The TUM line of @p pose (full precision).
std::string tumLine(const StampedPose& pose);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_TRAJECTORY_IO_HPP
