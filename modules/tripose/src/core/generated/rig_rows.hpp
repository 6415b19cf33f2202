// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/rig_rows.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_RIG_ROWS_HPP
#define OPENCV_TRIPOSE_GENERATED_RIG_ROWS_HPP

/** @file
Rows of A v = b from view 4 of a stereo rig (the right camera at time B).

Views: 1 = [I|0] and 2 = [R12|t12] (the rig, known) at time A; 3 = [R|t] (unknown) and
4 = [R12 R | R12 t + t12] at time B. v = [r1; r2; r3; t] (r_i: the columns of R), matrices
row-major. View 3 contributes the homogeneous rows of lineRows / pointRows; view 4 the
affine rows below, so that A v = b with b != 0 fixes the metric scale.
*/

namespace tripose {
namespace generated {

/** The two rows of A and entries of b contributed by a line seen in view 4 (the right camera
at time B, P4 = [R12 R | R12 t + t12]): the points qa, qb of the 3D line from views 1 and 2
project onto l4, q^T P4^T l4 = 0. With l4' = R12^T l4,
    q[0] (r1.l4') + q[1] (r2.l4') + q[2] (r3.l4') + q[3] (t.l4') = -q[3] (t12.l4),
i.e. rows . v = b with
    rows[12*i + 3*k + j] = q_i[k] * l4'[j]   (k = 0..3, j = 0..2),
    b[i] = -q_i[3] * (t12.l4),
row 0 for qa, row 1 for qb. qa, qb and (R12, t12) are those of lineNullSpace; the rows of
view 3 (lineRows) are the same with l4' -> l3 and b = 0.

@param qa input, 4 doubles: first point of the 3D line (lineNullSpace)
@param qb input, 4 doubles: second point of the 3D line (lineNullSpace)
@param l4 input, 3 doubles: the line in view 4, calibrated homogeneous (a, b, c)
@param R12 input, 9 doubles: rotation of the rig (view 2), row-major
@param t12 input, 3 doubles: translation of the rig (view 2)
@param rows output, 24 doubles: 2x12 row-major, the rows of qa and qb
@param b output, 2 doubles: 2 right-hand sides, rows . v = b
*/
void rigLineRows(const double* qa, const double* qb, const double* l4, const double* R12,
        const double* t12, double* rows, double* b);

/** The four rows of A and entries of b contributed by a point seen in view 4 (the right
camera at time B, P4 = [R12 R | R12 t + t12]): the trilinearity of views 1, 2, 4, Hartley-
normalized exactly as pointRows normalizes views 1, 2, 3, with P3 replaced by P4.

With M(x) = (R12 x) t^T - t12 (R x)^T, x1 = F^-1 x^1 (homogeneous) and H4 the normalizing
similarity of view 4, the equations are the entries -E(2,2), E(2,1), E(1,2), -E(1,1)
(1-based) of
    E = [x^2]x G M4(x1) H4^T [x^4]x,   M4(x) = M(x) R12^T + (R12 x) t12^T,
M4 being M of P4 = [R12 R | R12 t + t12]. The part M(x1) R12^T is linear in v (rows); the
part (R12 x1) t12^T is constant, and b is minus its share of the four entries:
rows . v = b.
With exact data [rows | b] has rank 2. A point seen in views 3 and 4 gives 3 independent
equations with pointRows, not 4: both views together triangulate it at time B, and the
fourth equation is their epipolar constraint, which exact data satisfies anyway.

@param x1 input, 2 doubles: Hartley-normalized calibrated point in view 1, x^ = s (x - c)
@param x2 input, 2 doubles: Hartley-normalized calibrated point in view 2
@param x4 input, 2 doubles: Hartley-normalized calibrated point in view 4
@param n1 input, 3 doubles: normalizing similarity F of view 1 as (s, cx, cy)
@param n2 input, 3 doubles: normalizing similarity G of view 2 as (s, cx, cy)
@param n4 input, 3 doubles: normalizing similarity H4 of view 4 as (s, cx, cy)
@param R12 input, 9 doubles: rotation of the rig (view 2), row-major
@param t12 input, 3 doubles: translation of the rig (view 2)
@param rows output, 48 doubles: 4x12 row-major, the view-4 analogues of eqs. (9)-(12)
@param b output, 4 doubles: 4 right-hand sides, rows . v = b
*/
void rigPointRows(const double* x1, const double* x2, const double* x4, const double* n1,
        const double* n2, const double* n4, const double* R12, const double* t12, double* rows,
        double* b);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_RIG_ROWS_HPP
