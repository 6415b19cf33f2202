// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_CONSTRAINED_ROTATIONS_HPP
#define OPENCV_TRIPOSE_MINIMAL_CONSTRAINED_ROTATIONS_HPP

#include <Eigen/Core>

namespace tripose {

/** The rotations R with

    a^T R b = 0,   tr(G1^T R) = 0,   tr(G2^T R) = 0,

a and b unit vectors, G1 and G2 any 3x3 matrices: the rotational core shared by the P3L, P2P1L and
P1P2L solvers (a line's direction constraint n^T R d = 0 is tr((n d^T)^T R) = 0; each solver
eliminates its translation into G2). In the spirit of the P3L solutions of @cite Xu2017 (align one
constraint, two angles remain, eliminate one), derived here for a general linear pair:

With rotations C (rows c1, c2, a: C a = e3) and W (rows b, w2, w3: W b = e1), every rotation with
a^T R b = 0 is R = C^T Rz(alpha) Rx(beta) W, since the third coordinate of Rz Rx e1 = (ca, sa, 0)
vanishes and the rotation about that image of e1 is the remaining freedom. With G' = C G W^T each
linear constraint reads

    [ca sa 1] M [cb sb 1]^T = 0,   M = [G'11 -G'12 G'00; -G'01 G'02 G'10; G'22 G'21 0]

(ca = cos alpha, ...). For fixed alpha the two are linear in (cb, sb): (p_k, q_k, w_k) = [ca sa 1]
M_k, p_k cb + q_k sb = -w_k; by Cramer cb = Dc / D, sb = Ds / D with D = p1 q2 - p2 q1,
Dc = q1 w2 - w1 q2, Ds = p2 w1 - p1 w2, and cb^2 + sb^2 = 1 is

    Dc^2 + Ds^2 - D^2 = 0,

quartic in (ca, sa); with s = tan(alpha / 2) and both sides times (1 + s^2)^4 it is a polynomial of
degree 8 in s: up to eight rotations (alpha = pi exactly, s infinite, is lost; C and W are arbitrary
completions, so it has probability zero, and near it s is merely large). When one constraint does not
depend on beta (two parallel line directions, one of them b), it fixes alpha (two opposite values)
and the other gives up to two beta each: up to four rotations. Nearly parallel directions take this
branch too: there pairs of roots of the degree-8 polynomial merge and may turn complex, whereas the
beta-free rotations are only approximate, for the caller to polish.

Returns the number of rotations written to @p rotations (at most 8); zero when the constraints
leave a continuum of rotations (the degree-8 polynomial vanishes identically).
*/
int solveConstrainedRotations(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Matrix3d& G1,
                              const Eigen::Matrix3d& G2, Eigen::Matrix3d rotations[8]);

//! A rotation whose last row is the unit vector @p a (it maps a to e3).
Eigen::Matrix3d rotationTakingToZ(const Eigen::Vector3d& a);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_CONSTRAINED_ROTATIONS_HPP
