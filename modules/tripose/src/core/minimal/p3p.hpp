// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_P3P_HPP
#define OPENCV_TRIPOSE_MINIMAL_P3P_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"

namespace tripose {

/** Absolute pose from three points (P3P), after the "Lambda Twist" construction of M. Persson and
K. Nordberg, "Lambda Twist: An Accurate Fast Robust Perspective Three Point (P3P) Solver", ECCV 2018.

Unknowns: the depths L = (l1, l2, l3) of the world points X_i along the unit bearings y_i of the
camera, l_i y_i = R X_i + t. Distances are preserved:

    |l_i y_i - l_j y_j|^2 = a_ij = |X_i - X_j|^2,  i.e.  L^T M_ij L = a_ij,  b_ij = y_i . y_j,

with M_12 = [1 -b12 0; -b12 1 0; 0 0 0] and likewise M_13, M_23. Eliminating the right-hand sides
gives two homogeneous quadrics, L^T D1 L = 0 and L^T D2 L = 0 with D1 = a23 M_12 - a12 M_23 and
D2 = a23 M_13 - a13 M_23. A real root g of the cubic det(D1 + g D2) = 0 makes D0 = D1 + g D2
singular: its quadric is a pair of planes through the origin, found from the two non-zero eigen
pairs (s+, e+), (s-, e-) of D0 as (e+ +/- sqrt(-s-/s+) e-) . L = 0. On each plane L = u v0 + w
(n x v0) (v0 spans D0's kernel) and L^T D1 L = 0 is a homogeneous quadratic in (u, w): up to two
directions per plane, scaled by L^T (M_12 + M_13 + M_23) L = a12 + a13 + a23. The depths are polished
by Gauss-Newton on the three distance equations; then R = [d12 d13 d12xd13] [D12 D13 D12xD13]^-1
with d1j = l1 y1 - lj yj, D1j = X1 - Xj, and t = l1 y1 - R X1.

Returns the number of poses appended to @p poses (at most four, positive depths only); zero for
degenerate input (coincident or collinear points, parallel bearings).
*/
int solveP3P(const Eigen::Vector3d bearings[3], const Eigen::Vector3d points[3], std::vector<CameraPose>& poses);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_P3P_HPP
