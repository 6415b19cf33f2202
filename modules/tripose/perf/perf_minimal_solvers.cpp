// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Time per call of the minimal solvers. One cycle solves the same kInstances prepared random
// noise-free instances, so the reported median time per cycle in microseconds divided by the
// parameter (100) is the time per call in microseconds.

#include "perf_precomp.hpp"

#include "../test/minimal_instances.hpp"

namespace opencv_test {
namespace {

using namespace minimal_instances;

typedef perf::TestBaseWithParam<int> Tripose_MinimalSolver;

struct Instance
{
    std::vector<PointObservation> points;
    std::vector<LineObservation> lines;
};

template <typename Make>
std::vector<Instance> randomInstances(Make make, int count)
{
    RNG rng(7);
    std::vector<Instance> instances(count);
    for (Instance& instance : instances)
        make(rng, instance.points, instance.lines);
    return instances;
}

//! Solves every instance once and returns the number of poses found.
template <typename Solve>
size_t solveAll(const std::vector<Instance>& instances, Solve solve, std::vector<CameraPose>& poses)
{
    size_t solutions = 0;
    for (const Instance& instance : instances)
    {
        poses.clear();
        solutions += solve(instance.points, instance.lines, poses);
    }
    return solutions;
}

//! Keeps the results observable so that the calls cannot be optimized away.
volatile size_t g_solutionCount = 0;

PERF_TEST_P(Tripose_MinimalSolver, p3p, testing::Values(100))
{
    const std::vector<Instance> instances = randomInstances(makeP3P, GetParam());
    std::vector<CameraPose> poses;
    TEST_CYCLE() g_solutionCount = solveAll(instances, solveP3PObservations, poses);
    // Every instance is exact and generic: each has at least its true pose among the solutions.
    EXPECT_GE((size_t)g_solutionCount, instances.size());
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_MinimalSolver, p2p1l, testing::Values(100))
{
    const std::vector<Instance> instances = randomInstances(makeP2P1L, GetParam());
    std::vector<CameraPose> poses;
    TEST_CYCLE() g_solutionCount = solveAll(instances, solveP2P1LObservations, poses);
    // Every instance is exact and generic: each has at least its true pose among the solutions.
    EXPECT_GE((size_t)g_solutionCount, instances.size());
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_MinimalSolver, p1p2l, testing::Values(100))
{
    const std::vector<Instance> instances = randomInstances(makeP1P2L, GetParam());
    std::vector<CameraPose> poses;
    TEST_CYCLE() g_solutionCount = solveAll(instances, solveP1P2LObservations, poses);
    // Every instance is exact and generic: each has at least its true pose among the solutions.
    EXPECT_GE((size_t)g_solutionCount, instances.size());
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Tripose_MinimalSolver, p3l, testing::Values(100))
{
    const std::vector<Instance> instances = randomInstances(makeP3L, GetParam());
    std::vector<CameraPose> poses;
    TEST_CYCLE() g_solutionCount = solveAll(instances, solveP3LObservations, poses);
    // Every instance is exact and generic: each has at least its true pose among the solutions.
    EXPECT_GE((size_t)g_solutionCount, instances.size());
    SANITY_CHECK_NOTHING();
}

} // namespace
} // namespace opencv_test
