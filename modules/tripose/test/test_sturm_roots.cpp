// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_polynomials.hpp"

#include "../src/core/minimal/sturm_roots.hpp"

namespace opencv_test {
namespace {

using ::tripose::solveRealRootsSturm;

TEST(Tripose_SturmRoots, finds_the_real_roots_of_random_octics)
{
    RNG rng(8);
    const int trials = 2000;
    int exact = 0;
    for (int trial = 0; trial < trials; ++trial)
    {
        const int numReal = 2 * rng.uniform(0, 5); // 0, 2, ..., 8; the rest complex pairs
        std::vector<double> roots(numReal);
        for (double& r : roots)
            r = std::tan(rng.uniform(-1.55, 1.55)); // the distribution of tan(alpha / 2)
        std::sort(roots.begin(), roots.end());
        std::vector<Vec2d> pairs((8 - numReal) / 2);
        for (Vec2d& z : pairs)
        {
            // One draw per statement, as C++ leaves the order of arguments unspecified: the imaginary
            // part before the real one is the order the seeded polynomials were drawn in so far (GCC's,
            // right to left).
            const double imaginary = rng.uniform(0.05, 3.0);
            const double real = rng.uniform(-3.0, 3.0);
            z = Vec2d(real, imaginary);
        }
        const std::vector<double> c = polynomialFromRoots(roots, pairs, rng.uniform(0.1, 10.0));
        double found[8];
        const int n = solveRealRootsSturm(c.data(), 8, found);
        bool ok = n == numReal;
        for (int i = 0; ok && i < n; ++i)
            ok = std::abs(found[i] - roots[i]) < 1e-6 * std::max(1.0, std::abs(roots[i]));
        exact += ok;
    }
    std::cout << exact << " of " << trials << " octics solved to 1e-6" << std::endl;
    // Random real roots can fall closer together than the coefficients' rounding resolves.
    EXPECT_GE(exact, trials - trials / 100) << exact << " of " << trials;
}

TEST(Tripose_SturmRoots, lower_degree_large_roots_and_multiple_roots)
{
    double found[8];
    // Degree 3 given as degree 8 with zero leading coefficients.
    std::vector<double> c = polynomialFromRoots({ -2.0, 0.5, 3.0 }, {}, 2.0);
    c.resize(9, 0.0);
    ASSERT_EQ(3, solveRealRootsSturm(c.data(), 8, found));
    EXPECT_NEAR(-2.0, found[0], 1e-12);
    EXPECT_NEAR(0.5, found[1], 1e-12);
    EXPECT_NEAR(3.0, found[2], 1e-12);
    // A root far out (a nearly vanishing leading coefficient: alpha near pi).
    c = polynomialFromRoots({ -1.0, 1e5 }, { Vec2d(0.0, 1.0), Vec2d(1.0, 2.0), Vec2d(-1.0, 0.5) }, 1.0);
    ASSERT_EQ(2, solveRealRootsSturm(c.data(), 8, found));
    EXPECT_NEAR(-1.0, found[0], 1e-10);
    EXPECT_NEAR(1e5, found[1], 1e-6);
    // A double root counts once.
    c = polynomialFromRoots({ 0.25, 0.25, -0.5, 2.0 }, { Vec2d(0.0, 1.0), Vec2d(2.0, 1.0) }, 1.0);
    ASSERT_EQ(3, solveRealRootsSturm(c.data(), 8, found));
    EXPECT_NEAR(0.25, found[1], 1e-6);
    // No real root; a constant; non-finite coefficients.
    c = polynomialFromRoots({}, { Vec2d(0.0, 1.0), Vec2d(1.0, 2.0), Vec2d(-1.0, 0.5), Vec2d(3.0, 0.1) }, 1.0);
    EXPECT_EQ(0, solveRealRootsSturm(c.data(), 8, found));
    const double constant[9] = { 1.0, 0, 0, 0, 0, 0, 0, 0, 0 };
    EXPECT_EQ(0, solveRealRootsSturm(constant, 8, found));
    double nan[9] = { 1.0, 2.0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0, 0, 0, 1.0 };
    EXPECT_EQ(0, solveRealRootsSturm(nan, 8, found));
}

} // namespace
} // namespace opencv_test
