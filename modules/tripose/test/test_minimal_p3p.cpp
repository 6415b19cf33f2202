// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <Eigen/Geometry>

#include "../src/core/minimal/p3p.hpp"
#include "minimal_instances.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::solveP3P;

using minimal_instances::randomPose;

//! Three world points in front of @p pose (depths 2..10), with their bearings in its frame.
void randomInstance(RNG& rng, const CameraPose& pose, Eigen::Vector3d bearings[3], Eigen::Vector3d points[3])
{
    for (int i = 0; i < 3; ++i)
    {
        const double y = rng.uniform(-1.0, 1.0);
        const double x = rng.uniform(-1.0, 1.0);
        const Eigen::Vector3d inCamera(x, y, 1.0);
        const Eigen::Vector3d Xc = rng.uniform(2.0, 10.0) * inCamera;
        points[i] = pose.R.transpose() * (Xc - pose.t);
        bearings[i] = Xc.normalized();
    }
}

bool containsPose(const std::vector<CameraPose>& poses, const CameraPose& truth, double tolerance)
{
    for (const CameraPose& p : poses)
        if ((p.R - truth.R).norm() < tolerance && (p.t - truth.t).norm() < tolerance * (1.0 + truth.t.norm()))
            return true;
    return false;
}

TEST(Tripose_MinimalP3P, true_pose_among_solutions_noise_free)
{
    RNG rng(301);
    const int trials = 10000;
    int found = 0;
    for (int trial = 0; trial < trials; ++trial)
    {
        const CameraPose truth = randomPose(rng);
        Eigen::Vector3d bearings[3], points[3];
        randomInstance(rng, truth, bearings, points);
        std::vector<CameraPose> poses;
        const int n = solveP3P(bearings, points, poses);
        ASSERT_EQ(n, (int)poses.size());
        ASSERT_LE(n, 4);
        for (const CameraPose& p : poses)
        {
            ASSERT_TRUE(p.allFinite());
            EXPECT_LT((p.R * p.R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9);
            EXPECT_GT(p.R.determinant(), 0);
        }
        found += containsPose(poses, truth, 1e-6);
    }
    EXPECT_GE(found, trials - trials / 1000) << found << " of " << trials;
}

TEST(Tripose_MinimalP3P, every_solution_reprojects_exactly)
{
    RNG rng(302);
    for (int trial = 0; trial < 1000; ++trial)
    {
        const CameraPose truth = randomPose(rng);
        Eigen::Vector3d bearings[3], points[3];
        randomInstance(rng, truth, bearings, points);
        std::vector<CameraPose> poses;
        solveP3P(bearings, points, poses);
        for (const CameraPose& p : poses)
            for (int i = 0; i < 3; ++i)
            {
                const Eigen::Vector3d x = p.toCamera(points[i]);
                EXPECT_GT(x.z(), 0);
                EXPECT_LT((x.normalized() - bearings[i]).norm(), 1e-6) << "trial " << trial;
            }
    }
}

TEST(Tripose_MinimalP3P, degenerate_input_gives_no_solution)
{
    RNG rng(303);
    const CameraPose truth = randomPose(rng);
    Eigen::Vector3d bearings[3], points[3];
    randomInstance(rng, truth, bearings, points);
    std::vector<CameraPose> poses;

    // Collinear world points.
    Eigen::Vector3d collinear[3] = { points[0], points[1], 0.3 * points[0] + 0.7 * points[1] };
    EXPECT_EQ(0, solveP3P(bearings, collinear, poses));
    // Two coincident world points.
    Eigen::Vector3d coincident[3] = { points[0], points[0], points[2] };
    EXPECT_EQ(0, solveP3P(bearings, coincident, poses));
    // Two identical bearings.
    Eigen::Vector3d sameRay[3] = { bearings[0], bearings[0], bearings[2] };
    EXPECT_EQ(0, solveP3P(sameRay, points, poses));
    // Non-finite input.
    Eigen::Vector3d nan[3] = { bearings[0], Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()),
                               bearings[2] };
    EXPECT_EQ(0, solveP3P(nan, points, poses));
    Eigen::Vector3d zero[3] = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() };
    EXPECT_EQ(0, solveP3P(bearings, zero, poses));
    EXPECT_TRUE(poses.empty());
}

} // namespace
} // namespace opencv_test
