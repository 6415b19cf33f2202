// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/beta_constraints.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_BETA_CONSTRAINTS_HPP
#define OPENCV_TRIPOSE_GENERATED_BETA_CONSTRAINTS_HPP

/** @file
Rotation constraints as quadrics in the kernel coefficients (paper Sec. III-D).

v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
*/

namespace tripose {
namespace generated {

/** N = 2: the five homogeneous constraints on v = b1 v1 + b2 v2 (paper eq. 19) as a 5x3
matrix C with C [b1^2, b2^2, b1 b2]^T = 0.
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - |r2|^2, |r2|^2 - |r3|^2; columns: b1^2, b2^2, b1 b2.

@param v1 input, 12 doubles: first kernel vector [r1; r2; r3; t]
@param v2 input, 12 doubles: second kernel vector [r1; r2; r3; t]
@param C output, 15 doubles: 5x3 row-major
*/
void betaConstraintsN2(const double* v1, const double* v2, double* C);

/** N = 3: the orthogonality and unit-norm constraints on v = b1 v1 + b2 v2 + b3 v3 (paper
eq. 21) as a 6x6 matrix C with C [b1^2, b2^2, b3^2, b1 b2, b1 b3, b2 b3]^T = [0 0 0 1 1 1]^T.
Rows: r1.r2, r2.r3, r3.r1, |r1|^2, |r2|^2, |r3|^2;
columns: b1^2, b2^2, b3^2, b1 b2, b1 b3, b2 b3.

@param v1 input, 12 doubles: first kernel vector [r1; r2; r3; t]
@param v2 input, 12 doubles: second kernel vector [r1; r2; r3; t]
@param v3 input, 12 doubles: third kernel vector [r1; r2; r3; t]
@param C output, 36 doubles: 6x6 row-major
*/
void betaConstraintsN3(const double* v1, const double* v2, const double* v3, double* C);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_BETA_CONSTRAINTS_HPP
