// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The fundamental matrix of frames of unknown relative pose: found among pairs of which a third are
// random, the same when the caller wants fewer inliers than the scene gives (the sampling may then
// stop early, short of them), and not found among random pairs.

#include "test_precomp.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "../src/core/tracking/fundamental_estimation.hpp"

namespace opencv_test {
namespace {

struct Pairs
{
    std::vector<Eigen::Vector2d> a, b;
};

//! @p seen pairs of one scene in two cameras (K: 500 px, 640x480), then @p random pairs of nothing.
Pairs scenePairs(int seen, int random)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1, 1), image(0, 640);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.1, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
    const Eigen::Vector3d t(-0.5, 0.05, 0.1);
    const auto pixel = [](const Eigen::Vector3d& x) {
        return Eigen::Vector2d(320 + 500 * x.x() / x.z(), 240 + 500 * x.y() / x.z());
    };
    Pairs p;
    for (int i = 0; i < seen; ++i)
    {
        const Eigen::Vector3d X(2 * unit(rng), 1.5 * unit(rng), 5 + 2 * unit(rng));
        p.a.push_back(pixel(X));
        p.b.push_back(pixel(R * X + t));
    }
    for (int i = 0; i < random; ++i)
    {
        p.a.emplace_back(image(rng), 0.75 * image(rng));
        p.b.emplace_back(image(rng), 0.75 * image(rng));
    }
    return p;
}

double largestEpipolarResidual(const Pairs& p, int count, const Eigen::Matrix3d& F)
{
    double largest = 0;
    for (int i = 0; i < count; ++i)
    {
        const Eigen::Vector3d line = F * p.a[i].homogeneous();
        largest = std::max(largest, std::abs(p.b[i].homogeneous().dot(line)) / line.head<2>().norm());
    }
    return largest;
}

TEST(Tripose_FundamentalEstimation, finds_the_geometry_among_random_pairs_with_or_without_a_wanted_count)
{
    const Pairs p = scenePairs(60, 30);
    Eigen::Matrix3d F, wanted;
    std::vector<unsigned char> inliers, wantedInliers;
    const int found = ::tripose::estimateFundamentalRansac(p.a, p.b, 1.0, 0.999, F, inliers);
    EXPECT_GE(found, 60);
    EXPECT_LT(found, 64); // A random pair lies on its epipolar line by chance at most now and then.
    EXPECT_LT(largestEpipolarResidual(p, 60, F), 1.0);
    EXPECT_EQ(::tripose::estimateFundamentalRansac(p.a, p.b, 1.0, 0.999, wanted, wantedInliers, 50), found);
    EXPECT_EQ(wantedInliers, inliers);
    EXPECT_LT((wanted - F).norm(), 1e-12 * F.norm());
}

TEST(Tripose_FundamentalEstimation, random_pairs_do_not_reach_the_wanted_count)
{
    const Pairs p = scenePairs(0, 60);
    Eigen::Matrix3d F;
    std::vector<unsigned char> inliers;
    EXPECT_LT(::tripose::estimateFundamentalRansac(p.a, p.b, 1.0, 0.999, F, inliers, 30), 30);
    EXPECT_LT(::tripose::estimateFundamentalRansac(p.a, p.b, 1.0, 0.999, F, inliers, 50), 50);
    // Every pair wanted: sampled as without a count.
    EXPECT_LT(::tripose::estimateFundamentalRansac(p.a, p.b, 1.0, 0.999, F, inliers, 60), 60);
}

} // namespace
} // namespace opencv_test
