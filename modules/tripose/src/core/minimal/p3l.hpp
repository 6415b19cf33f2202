// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_P3L_HPP
#define OPENCV_TRIPOSE_MINIMAL_P3L_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "incidences.hpp"

namespace tripose {

/** Absolute pose from three lines (P3L), in the spirit of @cite Xu2017.

Input: the calibrated image lines l_j (homogeneous, any non-zero scale) and the world lines
(P_j, d_j). With n_j = l_j / |l_j| each line gives

    n_j^T R d_j = 0   and   n_j^T (R P_j + t) = 0.

The first three equations involve R only: solveConstrainedRotations with a = n_i, b = d_i and
G_k = n_j d_j^T for the two other lines j, a polynomial of degree 8 (i is a line of the most nearly
parallel pair). For each rotation the other three are linear
in t: N t = -(n_j^T R P_j)_j with N = [n_1 n_2 n_3]^T. The pose is then polished by Newton's method
on the six equations.

Returns the number of poses appended to @p poses (at most eight). A line has no depth to check: poses
that place the lines behind the camera are returned too, for the caller's scoring to reject. Zero
for degenerate input: an image line that is not finite or zero (a 3D line through the camera
centre), N singular (image lines through one point: the 3D lines are concurrent or all parallel, and
t slides along one direction), or a continuum of rotations.
*/
int solveP3L(const Eigen::Vector3d imageLines[3], const WorldLine lines[3], std::vector<CameraPose>& poses);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_P3L_HPP
