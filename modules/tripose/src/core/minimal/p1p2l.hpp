// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_P1P2L_HPP
#define OPENCV_TRIPOSE_MINIMAL_P1P2L_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "incidences.hpp"

namespace tripose {

/** Absolute pose from one point and two lines (P1P2L); the problem of @cite Ramalingam2011, with
the elimination written here.

Input: the bearing f (any non-zero scale, e.g. [x; 1]) of the world point X, and the calibrated
image lines l_j (any non-zero scale, n_j = l_j / |l_j|) of the world lines (P_j, d_j). The point
gives t = lambda f - R X; with Q_j = P_j - X the lines give

    n_j^T R d_j = 0,   n_j^T R Q_j + lambda (n_j^T f) = 0   (j = 1, 2),

and eliminating lambda from the last two,

    (n_2^T f) n_1^T R Q_1 - (n_1^T f) n_2^T R Q_2 = 0.

So R solves solveConstrainedRotations with a = n_1, b = d_1, G1 = n_2 d_2^T and
G2 = (n_2^T f) n_1 Q_1^T - (n_1^T f) n_2 Q_2^T: a polynomial of degree 8 (up to eight poses), or,
for parallel lines, alpha fixed by the directions and up to four poses. lambda is the least-squares
solution of its two equations, t = lambda f - R X, and Newton's method on the six equations
polishes the pose.

Returns the number of poses appended to @p poses (at most eight, positive depth). Zero for
degenerate input: non-finite or zero bearing, directions or image lines; the point on a world line
(its incidence repeats the line's: a one-parameter family of poses); both image lines through the
image point (its depth is free); one image line for both lines (the camera centre in the plane of
two coplanar lines).
*/
int solveP1P2L(const Eigen::Vector3d& bearing, const Eigen::Vector3d& point, const Eigen::Vector3d imageLines[2],
               const WorldLine lines[2], std::vector<CameraPose>& poses);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_P1P2L_HPP
