// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/affine_constraints.py
// through the template codegen/tripose_codegen/templates/header.hpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#ifndef OPENCV_TRIPOSE_GENERATED_AFFINE_CONSTRAINTS_HPP
#define OPENCV_TRIPOSE_GENERATED_AFFINE_CONSTRAINTS_HPP

/** @file
Stereo rig: the quadrics of SO(3) in the coefficients of an affine kernel.

A v = b (views 3 and 4 of a stereo rig, b != 0) with a kernel of dimension d:
v = v0 + sum_k c_k e_k, v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
Rows 0-5 of every C are the column orthonormality with unit norms (the scale is fixed by
b); rows 6-19 the row orthonormality and the handedness, with which C m(c) = 0 solved
for the monomials as unknowns gives the pose for d <= 5, and d = 6 (six constraints,
finitely many poses) becomes an eigenproblem (codegen/README.md, "Stereo rig").
*/

namespace tripose {
namespace generated {

/** Affine kernel of dimension 1: the twenty quadrics of SO(3) on
v = v0 + c1 e1 as a 20x3 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..1), c_k c_l (k < l, lexicographic), c_k (k = 1..1), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 12 doubles: the kernel basis e1 concatenated, each [r1; r2; r3; t]
@param C output, 60 doubles: 20x3 row-major, see the row and column order above
*/
void affineConstraintsD1(const double* v0, const double* e, double* C);

/** Affine kernel of dimension 2: the twenty quadrics of SO(3) on
v = v0 + c1 e1 + c2 e2 as a 20x6 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..2), c_k c_l (k < l, lexicographic), c_k (k = 1..2), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 24 doubles: the kernel basis e1|e2 concatenated, each [r1; r2; r3; t]
@param C output, 120 doubles: 20x6 row-major, see the row and column order above
*/
void affineConstraintsD2(const double* v0, const double* e, double* C);

/** Affine kernel of dimension 3: the twenty quadrics of SO(3) on
v = v0 + c1 e1 + c2 e2 + c3 e3 as a 20x10 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..3), c_k c_l (k < l, lexicographic), c_k (k = 1..3), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 36 doubles: the kernel basis e1|e2|e3 concatenated, each [r1; r2; r3; t]
@param C output, 200 doubles: 20x10 row-major, see the row and column order above
*/
void affineConstraintsD3(const double* v0, const double* e, double* C);

/** Affine kernel of dimension 4: the twenty quadrics of SO(3) on
v = v0 + c1 e1 + ... + c4 e4 as a 20x15 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..4), c_k c_l (k < l, lexicographic), c_k (k = 1..4), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 48 doubles: the kernel basis e1|...|e4 concatenated, each [r1; r2; r3; t]
@param C output, 300 doubles: 20x15 row-major, see the row and column order above
*/
void affineConstraintsD4(const double* v0, const double* e, double* C);

/** Affine kernel of dimension 5: the twenty quadrics of SO(3) on
v = v0 + c1 e1 + ... + c5 e5 as a 20x21 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..5), c_k c_l (k < l, lexicographic), c_k (k = 1..5), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 60 doubles: the kernel basis e1|...|e5 concatenated, each [r1; r2; r3; t]
@param C output, 420 doubles: 20x21 row-major, see the row and column order above
*/
void affineConstraintsD5(const double* v0, const double* e, double* C);

/** Affine kernel of dimension 6: the twenty quadrics of SO(3) on
v = v0 + c1 e1 + ... + c6 e6 as a 20x28 matrix C with C m(c) = 0,
    m(c) = [c_k^2 (k = 1..6), c_k c_l (k < l, lexicographic), c_k (k = 1..6), 1].
Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.

@param v0 input, 12 doubles: particular solution of A v = b, [r1; r2; r3; t]
@param e input, 72 doubles: the kernel basis e1|...|e6 concatenated, each [r1; r2; r3; t]
@param C output, 560 doubles: 20x28 row-major, see the row and column order above
*/
void affineConstraintsD6(const double* v0, const double* e, double* C);

} // namespace generated
} // namespace tripose

#endif // OPENCV_TRIPOSE_GENERATED_AFFINE_CONSTRAINTS_HPP
