// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_AFFINE_KERNEL_SOLUTIONS_HPP
#define OPENCV_TRIPOSE_LINEAR_AFFINE_KERNEL_SOLUTIONS_HPP

#include <vector>

#include <Eigen/Core>

#include "kernel_solutions.hpp"

namespace tripose {

//! Basis of an affine kernel of dimension 1 to 6, one vector [r1; r2; r3; t] per column.
typedef Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 6> AffineKernelBasis;

/** Solution vectors v = v0 + sum_k c_k e_k of a system A v = b (or of a homogeneous one, v0 = 0)
whose R part [r1 r2 r3] is a rotation, for the kernel basis e_1..e_d (the columns of @p basis,
d = 1..6), given how many such v exact data admits (@p count: 1, 2, 4 or 8). The twenty quadrics
that vanish exactly on SO(3) (generated affineConstraintsD<d>) give C m(c) = 0 in the monomials
m(c) = [c_k^2, c_k c_l (k < l), c_k, 1]:
- d <= 5, one solution: linearisation, the monomials taken as independent unknowns; least squares
  (minimum norm, since a few mixes leave C null vectors on quadratic monomials only) with the
  constant fixed to 1, c read off the linear monomials.
- d = 4, 5, two solutions (two features seen in both time-B views): C's two-dimensional null space
  holds both monomial vectors, which an eigenproblem separates (see affine_kernel_solutions.cpp).
- d = 6 (six constraints, 8 or 4 poses): the same eigenproblem on the null space of the degree-3
  Macaulay matrix of the twenty quadrics.
The R parts are not projected onto SO(3); with noise they are only close to it. Appends the real
solutions to @p solutions and returns how many were appended.
*/
int solveAffineKernel(const Vector12d& v0, const AffineKernelBasis& basis, int count, std::vector<Vector12d>& solutions);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_AFFINE_KERNEL_SOLUTIONS_HPP
