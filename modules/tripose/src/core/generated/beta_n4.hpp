// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/beta_n4.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_BETA_N4_HPP
#define OPENCV_TRIPOSE_GENERATED_BETA_N4_HPP

/** @file
N = 4: relinearization with beta3 hidden (paper Sec. III-D, eqs. 22-26).

v = [r1; r2; r3; t] (r_i: the columns of R); v = b1 v1 + b2 v2 + b3 v3 + v4 (beta4 = 1).
Typical use: betaN4NullVector(v, u); betaN4Polynomial(u, p); the real roots b3 of p give
b1 = u4(b3) / u6(b3), b2 = u5(b3) / u6(b3).
*/

namespace tripose {
namespace generated {

/** N = 4, beta4 = 1, beta3 hidden: the 5x6 matrix of eq. (24). With
v = b1 v1 + b2 v2 + b3 v3 + v4, each homogeneous constraint equals
row . [b1^2, b2^2, b1 b2, b1, b2, 1] where the last three entries are polynomials in b3.

Matrix layout (row-major 5x10, one row per constraint r1.r2, r2.r3, r3.r1,
|r1|^2 - |r2|^2, |r2|^2 - |r3|^2):
    [b1^2, b2^2, b1 b2, b1: (1, b3), b2: (1, b3), 1: (1, b3, b3^2)],
i.e. the 5x6 matrix of eq. (24) in [b1^2, b2^2, b1 b2, b1, b2, 1] with its polynomial
entries in b3 expanded as ascending coefficients.

@param v input, 48 doubles: the kernel vectors v1|v2|v3|v4 concatenated, each [r1; r2; r3; t]
@param M output, 50 doubles: 5x10 row-major, see layout
*/
void betaN4Matrix(const double* v, double* M);

/** N = 4: the null vector u of the 5x6 matrix of eq. (24) (see betaN4Matrix) as polynomials
in b3, u_i = (-1)^(i-1) det(matrix without column i) (eq. 25), so that
matrix(b3) u(b3) = 0 and, for a consistent solution, u ~ [b1^2, b2^2, b1 b2, b1, b2, 1].
Computed by cofactor expansion over the matrix coefficients with shared sub-minors.

u packing (26 doubles, ascending powers of b3): u1, u2, u3 (degree 4, 5 coefficients each),
u4, u5 (degree 3, 4 each), u6 (degree 2, 3), at offsets 0, 5, 10, 15, 19, 23.

@param v input, 48 doubles: the kernel vectors v1|v2|v3|v4 concatenated, each [r1; r2; r3; t]
@param u output, 26 doubles: packed null vector, see layout
*/
void betaN4NullVector(const double* v, double* u);

/** N = 4: the three consistency polynomials of eq. (26), degree 6 in b3:
f1 = u4 u5 - u3 u6, f2 = u4^2 - u1 u6, f3 = u5^2 - u2 u6.
Output f: 3x7 row-major, ascending powers.

u packing (26 doubles, ascending powers of b3): u1, u2, u3 (degree 4, 5 coefficients each),
u4, u5 (degree 3, 4 each), u6 (degree 2, 3), at offsets 0, 5, 10, 15, 19, 23.

@param u input, 26 doubles: packed null vector from betaN4NullVector
@param f output, 21 doubles: 3x7 row-major, ascending powers
*/
void betaN4Consistency(const double* u, double* f);

/** N = 4: the 12 coefficients (ascending powers of b3) of the degree-11 polynomial
sum_i f_i f_i' whose real roots are the stationary points of sum_i f_i^2, with
f1 = u4 u5 - u3 u6, f2 = u4^2 - u1 u6, f3 = u5^2 - u2 u6 (eq. 26).

u packing (26 doubles, ascending powers of b3): u1, u2, u3 (degree 4, 5 coefficients each),
u4, u5 (degree 3, 4 each), u6 (degree 2, 3), at offsets 0, 5, 10, 15, 19, 23.

@param u input, 26 doubles: packed null vector from betaN4NullVector
@param p output, 12 doubles: 12 coefficients, ascending powers
*/
void betaN4Polynomial(const double* u, double* p);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_BETA_N4_HPP
