// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Time per call of each generated coefficient kernel. One cycle runs the kernel on a batch of
// kCallsPerCycle prepared random inputs, so the reported median time per cycle in microseconds is
// the time per call in nanoseconds when the parameter is 1000.

#include "perf_precomp.hpp"

#include <vector>

#include "../src/core/generated/beta_constraints.hpp"
#include "../src/core/generated/beta_n4.hpp"
#include "../src/core/generated/line_rows.hpp"
#include "../src/core/generated/point_rows.hpp"

namespace opencv_test {
namespace {

using namespace ::tripose::generated;

typedef perf::TestBaseWithParam<int> Tripose_GeneratedKernel;

const int kInputs = 64; // Distinct inputs, cycled through within a batch.

//! kInputs random input sets of @p size doubles each (non-degenerate with probability 1).
std::vector<double> randomInputs(int size, uint64 seed)
{
    cv::RNG rng(seed);
    std::vector<double> x((size_t)size * kInputs);
    for (double& e : x)
    {
        // One draw per statement, as C++ leaves the order of operands unspecified: the magnitude
        // before the sign is the order the seeded inputs were drawn in so far (GCC's).
        const double magnitude = rng.uniform(0.5, 2.0);
        e = magnitude * (rng.uniform(0, 2) ? 1 : -1);
    }
    return x;
}

//! Keeps the results observable so that the calls cannot be optimized away.
volatile double g_sink = 0;
void observe(const std::vector<double>& out)
{
    double s = 0;
    for (double e : out)
        s += e;
    g_sink = s;
}

PERF_TEST_P(Tripose_GeneratedKernel, lineNullSpace, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(18, 1);
    std::vector<double> out(8 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            const double* x = &in[18 * i];
            lineNullSpace(x, x + 3, x + 6, x + 15, &out[8 * i], &out[8 * i + 4]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, lineRows, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(11, 2);
    std::vector<double> out(24 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            const double* x = &in[11 * i];
            lineRows(x, x + 4, x + 8, &out[24 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, pointRows, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(27, 3);
    std::vector<double> out(48 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            const double* x = &in[27 * i];
            pointRows(x, x + 2, x + 4, x + 6, x + 9, x + 12, x + 15, x + 24, &out[48 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, betaConstraintsN2, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(24, 4);
    std::vector<double> out(15 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            betaConstraintsN2(&in[24 * i], &in[24 * i + 12], &out[15 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, betaConstraintsN3, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(36, 5);
    std::vector<double> out(36 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            betaConstraintsN3(&in[36 * i], &in[36 * i + 12], &in[36 * i + 24], &out[36 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, betaN4NullVector, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(48, 6);
    std::vector<double> out(26 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            betaN4NullVector(&in[48 * i], &out[26 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_GeneratedKernel, betaN4Polynomial, testing::Values(1000))
{
    const int calls = GetParam();
    const std::vector<double> in = randomInputs(26, 7);
    std::vector<double> out(12 * kInputs);
    TEST_CYCLE()
    {
        for (int c = 0; c < calls; ++c)
        {
            const int i = c % kInputs;
            betaN4Polynomial(&in[26 * i], &out[12 * i]);
        }
    }
    observe(out);
    SANITY_CHECK_NOTHING();
}

}} // namespace
