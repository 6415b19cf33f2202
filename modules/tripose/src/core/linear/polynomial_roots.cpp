// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <Eigen/Eigenvalues>

#include "polynomial_roots.hpp"

namespace tripose {

namespace {

constexpr int kMaxDegree = 16;

//! Newton steps on p from x, keeping a step only if it lowers |p(x)|.
double polishRoot(const double* c, int degree, double x)
{
    double value = evaluatePolynomial(c, degree, x);
    for (int iteration = 0; iteration < 4 && value != 0; ++iteration)
    {
        double derivative = degree * c[degree];
        for (int i = degree - 1; i >= 1; --i)
            derivative = derivative * x + i * c[i];
        if (derivative == 0)
            break;
        const double next = x - value / derivative;
        const double nextValue = evaluatePolynomial(c, degree, next);
        if (!(std::abs(nextValue) < std::abs(value)))
            break;
        x = next;
        value = nextValue;
    }
    return x;
}

} // namespace

int solveRealPolynomialRoots(const double* coeffs, int degree, double* roots, double imaginaryTolerance)
{
    TRIPOSE_ASSERT(degree >= 0 && degree <= kMaxDegree);
    double largest = 0;
    for (int i = 0; i <= degree; ++i)
    {
        if (!std::isfinite(coeffs[i]))
            return 0;
        largest = std::max(largest, std::abs(coeffs[i]));
    }
    if (largest == 0)
        return 0;
    // Only exact zeros lower the degree: a relative threshold would depend on the scale of the
    // roots. A leading coefficient that is merely tiny yields a huge root, which the caller rejects.
    int n = degree;
    while (n > 0 && coeffs[n] == 0)
        --n;
    // Roots at zero: factor them out so the scaling below is well defined.
    int zeros = 0;
    while (zeros < n && coeffs[zeros] == 0)
        ++zeros;
    const double* c = coeffs + zeros;
    const int m = n - zeros;

    int count = 0;
    if (zeros > 0)
        roots[count++] = 0.0;
    if (m == 1)
        roots[count++] = -c[0] / c[1];
    else if (m > 1)
    {
        // x = s y with s the geometric mean of the root magnitudes balances the companion matrix.
        const double s = std::pow(std::abs(c[0] / c[m]), 1.0 / m);
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree, kMaxDegree> companion(m, m);
        companion.setZero();
        double sPower = 1.0;
        const double leading = c[m] * std::pow(s, m);
        for (int i = 0; i < m; ++i)
        {
            companion(i, m - 1) = -c[i] * sPower / leading;
            if (i + 1 < m)
                companion(i + 1, i) = 1.0;
            sPower *= s;
        }
        Eigen::EigenSolver<decltype(companion)> solver(companion, false);
        if (solver.info() != Eigen::Success)
            return 0;
        for (int i = 0; i < m; ++i)
        {
            const std::complex<double> y = solver.eigenvalues()(i);
            // A complex pair is reported once (its member with positive imaginary part).
            if (std::abs(y.imag()) <= imaginaryTolerance * std::max(1.0, std::abs(y)) && y.imag() >= 0)
                roots[count++] = polishRoot(c, m, s * y.real());
        }
    }
    std::sort(roots, roots + count);
    return count;
}

} // namespace tripose
