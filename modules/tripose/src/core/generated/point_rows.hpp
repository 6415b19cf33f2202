// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/point_rows.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_POINT_ROWS_HPP
#define OPENCV_TRIPOSE_GENERATED_POINT_ROWS_HPP

/** @file
Rows of A from point triplets (paper Sec. III-B).

v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
*/

namespace tripose {
namespace generated {

/** The four rows of A contributed by one point triplet (paper Sec. III-B, eqs. 8-12).

With P2 = [a1 a2 a3 a4] = [R12|t12], P3 = [b1 b2 b3 b4] = [R|t], the trifocal tensor
T_i^{jk} = a_i^j b_4^k - a_4^j b_i^k and the normalized tensor (eq. 8)
    T^_i^{jk} = (F^-1)^r_i G^j_s H^k_t T_r^{st},
row e (e = 0..3 for eqs. 9..12, (a, b) = (1,1), (1,2), (2,1), (2,2)) holds the coefficients
on v = [r1; r2; r3; t] of
    x^1^k (x^2^a x^3^b T^_k^33 - x^3^b T^_k^a3 - x^2^a T^_k^3b + T^_k^ab) = 0,
x^_j the normalized points with third coordinate 1. Equivalently, with
M(x) = (R12 x) t^T - t12 (R x)^T and x1 = F^-1 x^1 (homogeneous), the equations are the
entries -E(2,2), E(2,1), E(1,2), -E(1,1) of E = [x^2]x G M(x1) H^T [x^3]x (1-based).
With exact data the four rows have rank 2.

@param x1 input, 2 doubles: Hartley-normalized calibrated point in view 1, x^ = s (x - c)
@param x2 input, 2 doubles: Hartley-normalized calibrated point in view 2
@param x3 input, 2 doubles: Hartley-normalized calibrated point in view 3
@param n1 input, 3 doubles: normalizing similarity F of view 1 as (s, cx, cy)
@param n2 input, 3 doubles: normalizing similarity G of view 2 as (s, cx, cy)
@param n3 input, 3 doubles: normalizing similarity H of view 3 as (s, cx, cy)
@param R12 input, 9 doubles: rotation of view 2, row-major
@param t12 input, 3 doubles: translation of view 2
@param rows output, 48 doubles: 4x12 row-major, eqs. (9)-(12)
*/
void pointRows(const double* x1, const double* x2, const double* x3, const double* n1,
        const double* n2, const double* n3, const double* R12, const double* t12, double* rows);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_POINT_ROWS_HPP
