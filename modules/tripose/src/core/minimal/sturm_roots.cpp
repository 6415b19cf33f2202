// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "sturm_roots.hpp"

#include "../support/horner.hpp"

#include <algorithm>
#include <cmath>

namespace tripose {

namespace {

constexpr int kMaxLength = kMaxSturmDegree + 1;
// A remainder coefficient below this fraction of its dividend's largest one is rounding.
constexpr double kRemainderRounding = 1e-13;
// Intervals narrower than this, relative to max(1, |x|), are not split further.
constexpr double kNarrowInterval = 1e-13;
constexpr int kMaxNewtonSteps = 50;

//! Divides by the largest magnitude (a positive factor: signs, hence sign changes, are kept).
void normalise(double* c, int degree)
{
    double largest = 0;
    for (int i = 0; i <= degree; ++i)
        largest = std::max(largest, std::abs(c[i]));
    if (largest > 0)
        for (int i = 0; i <= degree; ++i)
            c[i] /= largest;
}

struct SturmSequence
{
    double c[kMaxLength][kMaxLength];
    int degree[kMaxLength];
    int length = 0;

    //! Sign changes along the sequence at x (zeros skipped).
    int signChanges(double x) const
    {
        int changes = 0;
        double previous = 0;
        for (int k = 0; k < length; ++k)
        {
            const double v = evaluatePolynomial(c[k], degree[k], x);
            if (v == 0)
                continue;
            if (previous != 0 && (v > 0) != (previous > 0))
                ++changes;
            previous = v;
        }
        return changes;
    }
};

//! The sequence of the (normalised) polynomial @p p of degree @p n >= 1.
void buildSequence(const double* p, int n, SturmSequence& s)
{
    std::copy(p, p + n + 1, s.c[0]);
    s.degree[0] = n;
    for (int i = 1; i <= n; ++i)
        s.c[1][i - 1] = i * p[i];
    s.degree[1] = n - 1;
    normalise(s.c[1], n - 1);
    s.length = 2;
    while (s.degree[s.length - 1] > 0)
    {
        const double* divisor = s.c[s.length - 1];
        const int m = s.degree[s.length - 1];
        double remainder[kMaxLength];
        int r = s.degree[s.length - 2];
        std::copy(s.c[s.length - 2], s.c[s.length - 2] + r + 1, remainder);
        double scale = 0;
        for (int i = 0; i <= r; ++i)
            scale = std::max(scale, std::abs(remainder[i]));
        // Long division: cancel the leading term until the degree is below the divisor's.
        for (; r >= m; --r)
        {
            const double q = remainder[r] / divisor[m];
            for (int i = 0; i <= m; ++i)
                remainder[r - m + i] -= q * divisor[i];
        }
        while (r >= 0 && !(std::abs(remainder[r]) > kRemainderRounding * scale))
            --r;
        // A zero remainder: the last element is gcd(p, p') (multiple roots), which ends the sequence.
        if (r < 0)
            break;
        for (int i = 0; i <= r; ++i)
            s.c[s.length][i] = -remainder[i];
        s.degree[s.length] = r;
        normalise(s.c[s.length], r);
        ++s.length;
    }
}

//! The single root of p in (lo, hi], where p changes sign: Newton steps, replaced by bisection
//! whenever they would leave the bracket or would not halve the step before last (far from the root
//! Newton on a polynomial of degree n shrinks the distance only by a factor (n - 1) / n).
double refineBracketedRoot(const double* p, int n, double lo, double hi)
{
    const bool positiveAtLo = evaluatePolynomial(p, n, lo) > 0;
    double x = 0.5 * (lo + hi);
    double step = hi - lo, stepBefore = step;
    for (int iteration = 0; iteration < kMaxNewtonSteps; ++iteration)
    {
        double value, derivative;
        evaluateWithDerivative(p, n, x, value, derivative);
        if (value == 0)
            return x;
        if ((value > 0) == positiveAtLo)
            lo = x;
        else
            hi = x;
        const double newton = x - value / derivative;
        // Converged: rounding may put this last tiny step just outside the bracket.
        if (std::abs(newton - x) <= 4e-16 * std::max(1.0, std::abs(x)))
            return newton;
        const double previous = stepBefore;
        stepBefore = step;
        if (newton > lo && newton < hi && std::abs(newton - x) < 0.5 * previous)
        {
            step = std::abs(newton - x);
            x = newton;
        }
        else
        {
            step = 0.5 * (hi - lo);
            x = lo + step;
        }
        if (step <= 4e-16 * std::max(1.0, std::abs(x)))
            break;
    }
    return x;
}

} // namespace

int solveRealRootsSturm(const double* coeffs, int degree, double* roots)
{
    int n = std::min(degree, kMaxSturmDegree);
    while (n > 0 && coeffs[n] == 0)
        --n;
    if (n <= 0)
        return 0;
    double p[kMaxLength];
    for (int i = 0; i <= n; ++i)
    {
        if (!std::isfinite(coeffs[i]))
            return 0;
        p[i] = coeffs[i] / coeffs[n];
    }
    double bound = 0;
    for (int i = 0; i < n; ++i)
        bound = std::max(bound, std::abs(p[i]));
    bound += 1.0;
    normalise(p, n);

    SturmSequence sequence;
    buildSequence(p, n, sequence);

    struct Interval
    {
        double lo, hi;
        int changesLo, changesHi;
    };
    // Depth-first bisection: each split pushes at most two intervals, and the narrowing limit bounds
    // the depth, so a small fixed stack suffices.
    Interval stack[kMaxSturmDegree * 32];
    int top = 0;
    stack[top++] = Interval{ -bound, bound, sequence.signChanges(-bound), sequence.signChanges(bound) };
    int count = 0;
    while (top > 0 && count < n)
    {
        const Interval in = stack[--top];
        const int inside = in.changesLo - in.changesHi;
        if (inside <= 0)
            continue;
        const double mid = 0.5 * (in.lo + in.hi);
        if (in.hi - in.lo <= kNarrowInterval * std::max(1.0, std::abs(mid)))
        {
            // A multiple root, or roots closer than double precision separates.
            roots[count++] = mid;
            continue;
        }
        if (inside == 1 && (evaluatePolynomial(p, n, in.lo) > 0) != (evaluatePolynomial(p, n, in.hi) > 0))
        {
            roots[count++] = refineBracketedRoot(p, n, in.lo, in.hi);
            continue;
        }
        if (top + 2 > (int)(sizeof(stack) / sizeof(stack[0])))
            break;
        const int changesMid = sequence.signChanges(mid);
        stack[top++] = Interval{ mid, in.hi, changesMid, in.changesHi };
        stack[top++] = Interval{ in.lo, mid, in.changesLo, changesMid };
    }
    std::sort(roots, roots + count);
    return count;
}

} // namespace tripose
