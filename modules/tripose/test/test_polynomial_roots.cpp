// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_polynomials.hpp"

#include "../src/core/linear/polynomial_roots.hpp"

namespace opencv_test {
namespace {

using ::tripose::solveRealPolynomialRoots;

TEST(Tripose_PolynomialRoots, finds_all_real_roots_of_random_degree_11)
{
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
        const int n = solveRealPolynomialRoots(c.data(), 11, found);
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

TEST(Tripose_PolynomialRoots, handles_zero_roots_and_vanishing_leading_coefficients)
{
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

TEST(Tripose_PolynomialRoots, scale_of_roots_does_not_matter)
{
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

}} // namespace
