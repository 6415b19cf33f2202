// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_P2P1L_HPP
#define OPENCV_TRIPOSE_MINIMAL_P2P1L_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "incidences.hpp"

namespace tripose {

/** Absolute pose from two points and one line (P2P1L); the problem of @cite Ramalingam2011, with
the elimination written here.

Input: the bearings f_1, f_2 (any non-zero scale, e.g. [x; 1]) of the world points X_1, X_2, and
the calibrated image line l (any non-zero scale, n = l / |l|) of the world line (P, d). Unknowns: the
depths in R X_i + t = lambda_i f_i and the pose.

The points: t = lambda_1 f_1 - R X_1 and R D = lambda_2 f_2 - lambda_1 f_1 with D = X_2 - X_1, so
R D lies in the plane of the two rays: m^T R D = 0 with m = f_1 x f_2. With g = (m x f_2) /
((m x f_2) . f_1) (g . f_2 = 0, g . f_1 = 1), lambda_1 = -g^T R D. The line, with Q = P - X_1:

    n^T R d = 0,   n^T (R P + t) = n^T R Q - (n^T f_1) g^T R D = 0.

So R solves solveConstrainedRotations with a = m, b = D / |D|, G1 = n d^T and
G2 = n Q^T - (n^T f_1) g D^T, a polynomial of degree 8 (up to eight poses before the depth test);
then t = -(g^T R D) f_1 - R X_1, and Newton's method on the six equations polishes the pose.

Returns the number of poses appended to @p poses (at most eight, both depths positive). Zero for
degenerate input: non-finite or zero bearings, directions or image line; coincident points or
parallel bearings; a point on the world line (its incidence repeats the line's: a one-parameter
family of poses), among which the line through both points; the image line through both image points
(the camera centre in the plane of the line and both points: the rotation about X_1 X_2 is free).
*/
int solveP2P1L(const Eigen::Vector3d bearings[2], const Eigen::Vector3d points[2], const Eigen::Vector3d& imageLine,
               const WorldLine& line, std::vector<CameraPose>& poses);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_P2P1L_HPP
