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

/** The root of @p c (degree @p degree), monotone on [lo, hi] with values @p flo, @p fhi of opposite
signs there: Newton's method from the midpoint, a bisection step wherever Newton would leave the
bracket or would not halve the step before last (Numerical Recipes' rtsafe), so that the bracket
shrinks at least as fast as by bisection. */
double bracketedRoot(const double* c, int degree, double lo, double hi, double flo, double tolerance)
{
    // Orient the bracket: f(negative) < 0 < f(positive).
    double negative = flo < 0 ? lo : hi, positive = flo < 0 ? hi : lo;
    double y = 0.5 * (lo + hi);
    double step = std::abs(hi - lo), stepBefore = step;
    double f, df;
    evaluateWithDerivative(c, degree, y, f, df);
    for (int iteration = 0; iteration < 100 && f != 0; ++iteration)
    {
        if ((((y - positive) * df - f) * ((y - negative) * df - f) > 0) || std::abs(2 * f) > std::abs(stepBefore * df))
        {
            stepBefore = step;
            step = 0.5 * (positive - negative);
            y = negative + step;
        }
        else
        {
            stepBefore = step;
            step = f / df;
            y -= step;
        }
        if (std::abs(step) <= tolerance * std::max(1.0, std::abs(y)))
            break;
        evaluateWithDerivative(c, degree, y, f, df);
        if (f < 0)
            negative = y;
        else
            positive = y;
    }
    return y;
}

/** Relative accuracy of the roots of the derivatives: they only bracket the roots of the level
below (and the last, p's critical points, judge nearly real pairs, whose imaginary part is compared
with 1e-2 of the root), and Newton's last step from here takes them to about 1e-12 anyway. */
constexpr double kBracketTolerance = 1e-6;
/** Relative accuracy of p's roots before the Newton polish on the unscaled polynomial: a step this
small leaves an error of its square, and near a root the rounding of p can keep a demand for a
few ulps from being met (the iteration then runs to its limit). */
constexpr double kRootTolerance = 1e-12;

/** Real roots of @p c (degree @p degree >= 1) in [-bound, bound], given the sorted real roots
@p critical of its derivative: one per interval between them over which it changes sign, to the
relative accuracy @p tolerance. */
int rootsBetween(const double* c, int degree, const double* critical, int numCritical, double bound, double* roots,
                 double tolerance)
{
    int count = 0;
    double lo = -bound;
    double flo = evaluatePolynomial(c, degree, lo);
    for (int j = 0; j <= numCritical; ++j)
    {
        const double hi = j < numCritical ? std::min(std::max(critical[j], lo), bound) : bound;
        const double fhi = evaluatePolynomial(c, degree, hi);
        if (flo == 0)
        {
            if (count == 0 || roots[count - 1] != lo)
                roots[count++] = lo;
        }
        else if (fhi != 0 && (flo < 0) != (fhi < 0))
            roots[count++] = bracketedRoot(c, degree, lo, hi, flo, tolerance);
        lo = hi;
        flo = fhi;
    }
    if (flo == 0 && (count == 0 || roots[count - 1] != lo))
        roots[count++] = lo;
    return count;
}

/** Starts both root finders. The roots at zero and the vanishing leading coefficients come off:
c[0..m] with c[0] and c[m] non-zero, so that the scaling by the geometric mean of the root magnitudes
is defined. A root at zero, and the root of a linear remainder, go to @p roots (@p count of them).
Only exact zeros lower the degree: a relative threshold would depend on the scale of the roots, and
a leading coefficient that is merely tiny yields a huge root, which the caller rejects. False where
a coefficient is not finite or every one is zero: no roots to report. */
bool reduceToNonZeroRoots(const double* coeffs, int degree, double* roots, const double*& c, int& m, int& count)
{
    TRIPOSE_ASSERT(degree >= 0 && degree <= kMaxDegree);
    double largest = 0;
    for (int i = 0; i <= degree; ++i)
    {
        if (!std::isfinite(coeffs[i]))
            return false;
        largest = std::max(largest, std::abs(coeffs[i]));
    }
    if (largest == 0)
        return false;
    int n = degree;
    while (n > 0 && coeffs[n] == 0)
        --n;
    int zeros = 0;
    while (zeros < n && coeffs[zeros] == 0)
        ++zeros;
    c = coeffs + zeros;
    m = n - zeros;
    count = 0;
    if (zeros > 0)
        roots[count++] = 0.0;
    if (m == 1)
        roots[count++] = -c[0] / c[1];
    return true;
}

} // namespace

int solveNearlyRealPolynomialRoots(const double* coeffs, int degree, double* roots, double nearlyRealTolerance)
{
    const double* c;
    int m, count;
    if (!reduceToNonZeroRoots(coeffs, degree, roots, c, m, count))
        return 0;
    if (m > 1)
    {
        // The balanced monic polynomial in y = x / s, as for the companion matrix, and its derivatives:
        // d[k] holds the k-th derivative divided by k! ... scaled to be monic again (same roots).
        const double s = std::pow(std::abs(c[0] / c[m]), 1.0 / m);
        double d[kMaxDegree][kMaxDegree + 1];
        double sPower = 1.0;
        const double leading = c[m] * std::pow(s, m);
        for (int i = 0; i < m; ++i)
        {
            d[0][i] = c[i] * sPower / leading;
            sPower *= s;
        }
        d[0][m] = 1.0;
        // Fujiwara's bound on the roots of the monic polynomial, 2 max_i |a_(m-i)|^(1/i) (a_0 halved):
        // within twice the largest root's magnitude, where Cauchy's 1 + max |a_i| can be hundreds of
        // times it. It bounds the roots of the derivatives too (Gauss-Lucas).
        double bound = 0;
        for (int i = 1; i <= m; ++i)
            bound = std::max(bound, std::pow(std::abs(d[0][m - i]) * (i == m ? 0.5 : 1.0), 1.0 / i));
        bound = 2 * bound * (1 + 1e-12) + std::numeric_limits<double>::min();
        for (int k = 1; k < m; ++k)
        {
            const int dk = m - k;
            for (int i = 0; i <= dk; ++i)
                d[k][i] = d[k - 1][i + 1] * (i + 1) / double(dk + 1);
        }
        // From the linear (m-1)-th derivative down to p' (k = 1): each level's roots bracket the next's.
        double critical[kMaxDegree], below[kMaxDegree];
        int numCritical = 1;
        critical[0] = -d[m - 1][0];
        for (int k = m - 2; k >= 1; --k)
        {
            numCritical = rootsBetween(d[k], m - k, critical, numCritical, bound, below, kBracketTolerance);
            std::copy(below, below + numCritical, critical);
        }
        double y[kMaxDegree];
        const int numReal = rootsBetween(d[0], m, critical, numCritical, bound, y, kRootTolerance);
        int numRoots = numReal;
        // Nearly real complex pairs: a minimum of |p| at a root of p' where p keeps its sign
        // (p and p'' alike in sign), its imaginary part about sqrt(2 p / p'').
        for (int j = 0; j < numCritical && numRoots < m; ++j)
        {
            const double yc = critical[j];
            double value, slope, curvature = 0;
            evaluateWithDerivative(d[0], m, yc, value, slope);
            // p'' = m (m - 1) d[2] (d[k] is the k-th derivative over m! / (m - k)!).
            curvature = m >= 2 ? double(m) * (m - 1) * (m >= 3 ? evaluatePolynomial(d[2], m - 2, yc) : 1.0) : 0.0;
            if (value == 0 || !((value > 0) == (curvature > 0)) || curvature == 0)
                continue;
            const double imaginary = std::sqrt(2 * value / curvature);
            if (imaginary <= nearlyRealTolerance * std::max(1.0, std::abs(yc)))
                y[numRoots++] = yc;
        }
        for (int i = 0; i < numRoots; ++i)
            roots[count++] = polishRoot(c, m, s * y[i]);
    }
    std::sort(roots, roots + count);
    return count;
}

int solveRealPolynomialRoots(const double* coeffs, int degree, double* roots, double imaginaryTolerance)
{
    const double* c;
    int m, count;
    if (!reduceToNonZeroRoots(coeffs, degree, roots, c, m, count))
        return 0;
    if (m > 1)
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
