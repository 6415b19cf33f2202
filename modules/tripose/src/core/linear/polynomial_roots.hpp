// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP
#define OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP

namespace tripose {

/** Real roots of p(x) = sum_i coeffs[i] x^i (ascending powers, degree <= 16).

Eigenvalues of the companion matrix of p after scaling x so that the coefficients are balanced,
kept where their imaginary part is below @p imaginaryTolerance relative to their magnitude (a
larger tolerance also returns the real parts of nearly real complex pairs), then polished by Newton steps on p itself (a step
is kept only if it lowers |p|). Leading coefficients that are exactly zero lower the degree.
Returns the number of roots written to @p roots (at most the degree), in ascending order.
*/
int solveRealPolynomialRoots(const double* coeffs, int degree, double* roots, double imaginaryTolerance = 1e-6);

//! p(x) by Horner's rule (ascending coefficients).
inline double evaluatePolynomial(const double* coeffs, int degree, double x)
{
    double value = coeffs[degree];
    for (int i = degree - 1; i >= 0; --i)
        value = value * x + coeffs[i];
    return value;
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP
