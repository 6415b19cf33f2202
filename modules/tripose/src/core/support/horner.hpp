// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Polynomials given by ascending coefficients c[0] + c[1] x + ... + c[degree] x^degree, evaluated by
// Horner's rule: the root finders of the linear solver and of the minimal solvers share them.
#ifndef TRIPOSE_CORE_SUPPORT_HORNER_HPP
#define TRIPOSE_CORE_SUPPORT_HORNER_HPP

namespace tripose {

//! p(x).
inline double evaluatePolynomial(const double* coeffs, int degree, double x)
{
    double value = coeffs[degree];
    for (int i = degree - 1; i >= 0; --i)
        value = value * x + coeffs[i];
    return value;
}

//! p(x) and p'(x) in one pass.
inline void evaluateWithDerivative(const double* coeffs, int degree, double x, double& value, double& derivative)
{
    value = coeffs[degree];
    derivative = 0;
    for (int i = degree - 1; i >= 0; --i)
    {
        derivative = derivative * x + value;
        value = value * x + coeffs[i];
    }
}

} // namespace tripose

#endif // TRIPOSE_CORE_SUPPORT_HORNER_HPP
