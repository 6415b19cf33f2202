// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP
#define OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP

#include "../support/horner.hpp"

namespace tripose {

/** Real roots of p(x) = sum_i coeffs[i] x^i (ascending powers, degree <= 16).

Eigenvalues of the companion matrix of p after scaling x so that the coefficients are balanced,
kept where their imaginary part is below @p imaginaryTolerance relative to their magnitude (a
larger tolerance also returns the real parts of nearly real complex pairs), then polished by Newton steps on p itself (a step
is kept only if it lowers |p|). Leading coefficients that are exactly zero lower the degree.
Returns the number of roots written to @p roots (at most the degree), in ascending order.
*/
int solveRealPolynomialRoots(const double* coeffs, int degree, double* roots, double imaginaryTolerance = 1e-6);

/** Real roots of p (ascending coefficients, degree <= 16), and the real parts of complex pairs
within @p nearlyRealTolerance of the real axis, as solveRealPolynomialRoots() returns them, without
an eigen-decomposition.

After the same balancing (x = s y, p made monic in y), the real roots of each derivative of p
bracket those of the one before: between two neighbouring roots of p^(k+1), p^(k) is monotone and
has a root exactly when its sign changes, found by Newton's method safeguarded by bisection; the
chain starts from the linear p^(n-1). A complex pair a +- ib close to the axis leaves no root but a
minimum of |p| at a root c of p' where p does not change sign: there p(c) ~ q b^2 and
p''(c) ~ 2 q, and c is kept when b = sqrt(2 p(c) / p''(c)) <= nearlyRealTolerance max(1, |c|) (in
y, as the companion matrix's eigenvalues are judged). Roots are polished by Newton steps on p as in
solveRealPolynomialRoots(). Returns the number of roots written to @p roots, in ascending order.
*/
int solveNearlyRealPolynomialRoots(const double* coeffs, int degree, double* roots, double nearlyRealTolerance);

} // namespace tripose

#endif // OPENCV_TRIPOSE_POLYNOMIAL_ROOTS_HPP
