// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/line_rows.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_LINE_ROWS_HPP
#define OPENCV_TRIPOSE_GENERATED_LINE_ROWS_HPP

/** @file
Rows of A from line triplets (paper Sec. III-A).

v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
*/

namespace tripose {
namespace generated {

/** An orthonormal basis {qa, qb} of the null space of [pi1 pi2]^T, where
pi1 = [l1; 0] and pi2 = [R12^T l2; t12^T l2] are the planes back-projected from views 1
and 2 (the two homogeneous points of their 3D line that lineRows needs).

Closed form (equivalent to the last two columns of the Householder Q up to a 2x2
rotation, which leaves A^T A unchanged): with n1 = l1, n2 = R12^T l2, d2 = t12.l2,
d = n1 x n2 and m = n1 x d,
    qa = [d; 0] / |d|,   qb = [d2 m; |d|^2] / (|d| sqrt(d2^2 |n1|^2 + |d|^2)).
qa is the line's point at infinity. Degenerate (division by zero) when d = 0, i.e. when
the two planes are parallel: the line lies in an epipolar plane of views 1-2 and cannot be
triangulated; callers reject such lines before calling.

@param l1 input, 3 doubles: the line in view 1, calibrated homogeneous (a, b, c)
@param l2 input, 3 doubles: the line in view 2, calibrated homogeneous (a, b, c)
@param R12 input, 9 doubles: rotation of view 2, row-major
@param t12 input, 3 doubles: translation of view 2
@param qa output, 4 doubles: unit 4-vector, the point at infinity of the line
@param qb output, 4 doubles: unit 4-vector orthogonal to qa
*/
void lineNullSpace(const double* l1, const double* l2, const double* R12, const double* t12,
        double* qa, double* qb);

/** The two rows of A contributed by one line triplet (paper Sec. III-A, eqs. 1-3).

For q in {qa, qb}, a homogeneous point of the 3D line defined by views 1 and 2, the
constraint q^T pi3 = 0 with pi3 = [R^T l3; t^T l3] reads
    q[0] (r1.l3) + q[1] (r2.l3) + q[2] (r3.l3) + q[3] (t.l3) = 0,
linear in v = [r1; r2; r3; t]. Row 0 is the row of qa, row 1 the row of qb:
    rows[12*i + 3*k + j] = q_i[k] * l3[j]   (k = 0..3, j = 0..2).

@param qa input, 4 doubles: first point of the 3D line (null space of [pi1 pi2]^T)
@param qb input, 4 doubles: second point of the 3D line (null space of [pi1 pi2]^T)
@param l3 input, 3 doubles: the line in view 3, calibrated homogeneous (a, b, c)
@param rows output, 24 doubles: 2x12 row-major, the rows of qa and qb
*/
void lineRows(const double* qa, const double* qb, const double* l3, double* rows);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_LINE_ROWS_HPP
