// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_polynomials.hpp"

#include "../src/core/linear/polynomial_roots.hpp"

namespace opencv_test {
namespace {

using ::tripose::solveNearlyRealPolynomialRoots;
using ::tripose::solveRealPolynomialRoots;

//! The derivative-bracketing finder with the companion matrix's default tolerance, for the shared tests.
int bracketedRoots(const double* coeffs, int degree, double* roots)
{
    return solveNearlyRealPolynomialRoots(coeffs, degree, roots, 1e-6);
}

typedef int (*RootFinder)(const double*, int, double*);
const RootFinder kFinders[2] = { [](const double* c, int d, double* r) { return solveRealPolynomialRoots(c, d, r); },
                                 bracketedRoots };
const char* const kFinderNames[2] = { "companion matrix", "derivative brackets" };

TEST(Tripose_PolynomialRoots, finds_all_real_roots_of_random_degree_11)
{
  for (int f = 0; f < 2; ++f)
  {
    SCOPED_TRACE(kFinderNames[f]);
    RNG rng(11);
    int exact = 0;
    const int trials = 500;
    for (int trial = 0; trial < trials; ++trial)
    {
        const int numReal = 1 + 2 * rng.uniform(0, 6); // odd count, rest complex pairs
        std::vector<double> roots(numReal);
        for (double& r : roots)
            r = rng.uniform(-10.0, 10.0);
        std::sort(roots.begin(), roots.end());
        const std::vector<double> c = polynomialFromRoots(roots, std::vector<Vec2d>((11 - numReal) / 2, Vec2d(0.0, 1.0)), rng.uniform(0.1, 10.0));
        double found[16];
        const int n = kFinders[f](c.data(), 11, found);
        if (n != numReal)
            continue;
        double worst = 0;
        for (int i = 0; i < n; ++i)
            worst = std::max(worst, std::abs(found[i] - roots[i]));
        // Well-separated roots of moderate size are recovered to a few ulps of their magnitude
        // after polishing; 1e-7 leaves room for the rare close pair.
        exact += worst < 1e-7;
    }
    EXPECT_GE(exact, trials * 99 / 100);
  }
}

TEST(Tripose_PolynomialRoots, handles_zero_roots_and_vanishing_leading_coefficients)
{
  for (int f = 0; f < 2; ++f)
  {
    SCOPED_TRACE(kFinderNames[f]);
    const RootFinder solveRealPolynomialRoots = kFinders[f];
    // x^2 (x - 3) with two zero leading coefficients above it: the degree drops to 3.
    const double c[6] = { 0, 0, -3, 1, 0, 0 };
    double roots[5];
    const int n = solveRealPolynomialRoots(c, 5, roots);
    ASSERT_EQ(n, 2);
    EXPECT_EQ(roots[0], 0.0);
    EXPECT_NEAR(roots[1], 3.0, 1e-12);

    const double none[3] = { 1, 0, 1 }; // x^2 + 1
    EXPECT_EQ(solveRealPolynomialRoots(none, 2, roots), 0);
    const double zero[3] = { 0, 0, 0 };
    EXPECT_EQ(solveRealPolynomialRoots(zero, 2, roots), 0);
    const double nan[2] = { std::numeric_limits<double>::quiet_NaN(), 1 };
    EXPECT_EQ(solveRealPolynomialRoots(nan, 1, roots), 0);
  }
}

TEST(Tripose_PolynomialRoots, scale_of_roots_does_not_matter)
{
  for (int f = 0; f < 2; ++f)
  {
    SCOPED_TRACE(kFinderNames[f]);
    const RootFinder solveRealPolynomialRoots = kFinders[f];
    for (double scale : { 1e-6, 1e-3, 1.0, 1e3, 1e6 })
    {
        const std::vector<double> expected = { -2.5 * scale, 0.5 * scale, 4.0 * scale };
        const std::vector<double> c = polynomialFromRoots(expected, { Vec2d(0.0, 1.0) }, 1.0);
        double roots[5];
        ASSERT_EQ(solveRealPolynomialRoots(c.data(), 5, roots), 3) << "scale " << scale;
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(roots[i], expected[i], 1e-10 * scale) << "scale " << scale;
    }
  }
}

/** The N = 4 kernel's use: real roots and the real parts of complex pairs within 1e-2 (relative, in
the balanced variable) of the axis, the same from both finders; pairs further off are no roots.
Degree 11, three real roots, a pair at relative distance 1e-5 to 3e-3 (kept) and pairs at 0.3 to
1 (dropped), roots scaled by 1e-3 to 1e3. */
TEST(Tripose_PolynomialRoots, nearly_real_pairs_are_kept_by_both_finders)
{
    RNG rng(4);
    const int trials = 300;
    int agree = 0;
    for (int trial = 0; trial < trials; ++trial)
    {
        const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
        std::vector<double> real = { -3.1 * scale, 0.7 * scale, 2.2 * scale };
        const double a = rng.uniform(1.2, 1.7) * scale; // between two real roots
        const double near = std::pow(10.0, rng.uniform(-5.0, -2.5)) * std::max(std::abs(a), scale);
        std::vector<Vec2d> pairs = { Vec2d(a, near) };
        for (int k = 0; k < 3; ++k)
        {
            // One draw per statement, as C++ leaves the order of arguments unspecified: the imaginary
            // part before the real one is the order the seeded polynomials were drawn in so far (GCC's,
            // right to left).
            const double im = rng.uniform(0.3, 1.0) * 4 * scale;
            const double re = rng.uniform(-3.0, 3.0) * scale;
            pairs.push_back(Vec2d(re, im));
        }
        const std::vector<double> c = polynomialFromRoots(real, pairs, rng.uniform(0.1, 10.0));
        double companion[11], bracketed[11];
        const int nc = solveRealPolynomialRoots(c.data(), 11, companion, 1e-2);
        const int nb = solveNearlyRealPolynomialRoots(c.data(), 11, bracketed, 1e-2);
        real.push_back(a);
        std::sort(real.begin(), real.end());
        ASSERT_EQ(4, nb) << "trial " << trial;
        double worst = 0;
        for (int i = 0; i < 4; ++i)
            worst = std::max(worst, std::abs(bracketed[i] - real[i]) / scale);
        // The real part of the pair: to about its imaginary part squared over the neighbours' distance.
        EXPECT_LT(worst, 1e-4) << "trial " << trial;
        if (nc == nb)
        {
            double apart = 0;
            for (int i = 0; i < nb; ++i)
                apart = std::max(apart, std::abs(companion[i] - bracketed[i]) / scale);
            agree += apart < 1e-4;
        }
    }
    EXPECT_EQ(trials, agree);
}

}} // namespace
