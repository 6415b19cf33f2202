// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MINIMAL_STURM_ROOTS_HPP
#define OPENCV_TRIPOSE_MINIMAL_STURM_ROOTS_HPP

namespace tripose {

//! The highest degree solveRealRootsSturm accepts.
constexpr int kMaxSturmDegree = 8;

/** Real roots of p(x) = sum_i coeffs[i] x^i (ascending powers, degree <= kMaxSturmDegree), for the
small eliminants of the minimal solvers, where a companion-matrix eigen-decomposition would cost
most of the solve.

The Sturm sequence p_0 = p, p_1 = p', p_{k+1} = -(p_{k-1} mod p_k) counts the distinct real roots in
(a, b] as V(a) - V(b), V the number of sign changes along the sequence. Bisection of the Cauchy
interval |x| <= 1 + max_i |c_i / c_n| isolates each root; a bracketed Newton iteration on p then
converges to it. Leading coefficients that are exactly zero lower the degree. Unlike the companion
matrix, a complex pair close to the real axis yields no root.

Returns the number of roots written to @p roots (at most the degree), in ascending order.
*/
int solveRealRootsSturm(const double* coeffs, int degree, double* roots);

} // namespace tripose

#endif // OPENCV_TRIPOSE_MINIMAL_STURM_ROOTS_HPP
