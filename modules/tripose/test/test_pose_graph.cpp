// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The loop closure's pose graph: edges that agree with the true poses bring perturbed poses back to
// them; a chain whose steps carry a bias, closed by one true loop edge, ends far nearer the truth at
// every pose than the chain alone; held poses never move; bad graphs are refused naming the argument;
// the rotation vector of its errors is exact near the identity.

#include "test_precomp.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "../src/core/geometry/rotation.hpp"
#include "../src/core/support/error.hpp"
#include "../src/core/tracking/pose_graph.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::PoseGraphEdge;

const int kPoses = 24;

//! Cameras on a circle of radius 5 looking at its centre: pose k after k / kPoses of a turn.
std::vector<CameraPose> ringPoses()
{
    std::vector<CameraPose> poses(kPoses);
    for (int k = 0; k < kPoses; ++k)
    {
        const double a = 2 * M_PI * k / kPoses;
        const Eigen::Vector3d centre(5 * std::sin(a), 0.3 * std::sin(3 * a), -5 * std::cos(a));
        poses[k].R = Eigen::AngleAxisd(-a, Eigen::Vector3d::UnitY()).toRotationMatrix();
        poses[k].t = -poses[k].R * centre;
    }
    return poses;
}

//! The pose of @p b relative to @p a: the edge from a to b that agrees with them.
CameraPose relative(const CameraPose& a, const CameraPose& b)
{
    return ::tripose::poseRelativeTo(b, a);
}

PoseGraphEdge edge(int from, int to, const CameraPose& relativePose)
{
    PoseGraphEdge e;
    e.from = from;
    e.to = to;
    e.relative = relativePose;
    return e;
}

double angleDeg(const CameraPose& a, const CameraPose& b)
{
    return Eigen::AngleAxisd(a.R * b.R.transpose()).angle() * 180 / M_PI;
}

double shift(const CameraPose& a, const CameraPose& b)
{
    return (a.centre() - b.centre()).norm();
}

//! Expects optimizePoseGraph to throw tripose::Error whose message contains @p name.
void expectRefusalNaming(std::vector<CameraPose> poses, const std::vector<bool>& held,
                         const std::vector<PoseGraphEdge>& edges, double scale, const std::string& name)
{
    try
    {
        ::tripose::optimizePoseGraph(poses, held, edges, scale);
        ADD_FAILURE() << "no error, expected one naming " << name;
    }
    catch (const ::tripose::Error& e)
    {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}

TEST(Tripose_PoseGraph, rotation_vector_inverts_the_rotation_from_tiny_angles_to_a_half_turn)
{
    // The graph's rotation error: exact near the identity, where the edges' errors are.
    const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
    for (double angle : { 0.0, 1e-12, 1e-8, 1e-4, 0.1, 1.0, 2.0, 3.0, M_PI - 1e-6 })
    {
        const Eigen::Vector3d w = angle * axis;
        const Eigen::Vector3d back = ::tripose::rotationVector(::tripose::rotationFromVector(w));
        EXPECT_LT((back - w).norm(), 1e-15 + 1e-9 * angle) << "angle " << angle;
    }
}

TEST(Tripose_PoseGraph, consistent_edges_bring_perturbed_poses_back_to_the_truth)
{
    const std::vector<CameraPose> truth = ringPoses();
    std::vector<PoseGraphEdge> edges;
    for (int k = 1; k < kPoses; ++k)
        edges.push_back(edge(k - 1, k, relative(truth[k - 1], truth[k])));
    edges.push_back(edge(0, kPoses - 1, relative(truth[0], truth[kPoses - 1])));
    std::vector<CameraPose> poses = truth;
    cv::RNG rng(7);
    for (int k = 1; k < kPoses; ++k)
    {
        const Eigen::Vector3d w(rng.gaussian(0.05), rng.gaussian(0.05), rng.gaussian(0.05));
        poses[k].R = ::tripose::rotateLeft(w, poses[k].R);
        poses[k].t += Eigen::Vector3d(rng.gaussian(0.3), rng.gaussian(0.3), rng.gaussian(0.3));
    }
    std::vector<bool> held(kPoses, false);
    held[0] = true;
    const double cost = ::tripose::optimizePoseGraph(poses, held, edges, 1.0);
    EXPECT_LT(cost, 1e-16);
    for (int k = 0; k < kPoses; ++k)
    {
        EXPECT_LT(angleDeg(poses[k], truth[k]), 1e-6) << "pose " << k;
        EXPECT_LT(shift(poses[k], truth[k]), 1e-6) << "pose " << k;
    }
}

TEST(Tripose_PoseGraph, a_true_loop_edge_corrects_a_biased_chain_at_every_pose)
{
    const std::vector<CameraPose> truth = ringPoses();
    // Every step of the chain turns 0.2 deg too far about the ring's axis and moves 1 % too far: the
    // chain's poses drift away from the truth as a tracker's do, 4.6 deg at the end.
    const Eigen::Matrix3d bias = Eigen::AngleAxisd(0.2 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
    std::vector<PoseGraphEdge> edges;
    std::vector<CameraPose> chain(kPoses);
    chain[0] = truth[0];
    for (int k = 1; k < kPoses; ++k)
    {
        CameraPose step = relative(truth[k - 1], truth[k]);
        step.R = bias * step.R;
        step.t = 1.01 * step.t;
        edges.push_back(edge(k - 1, k, step));
        chain[k].R = step.R * chain[k - 1].R;
        chain[k].t = step.R * chain[k - 1].t + step.t;
    }
    edges.push_back(edge(0, kPoses - 1, relative(truth[0], truth[kPoses - 1])));
    std::vector<bool> held(kPoses, false);
    held[0] = true;
    std::vector<CameraPose> poses = chain;
    const double step = shift(truth[0], truth[1]);
    const double cost = ::tripose::optimizePoseGraph(poses, held, edges, step);
    EXPECT_EQ(poses[0].R, truth[0].R);
    EXPECT_EQ(poses[0].t, truth[0].t);
    double chainWorst = 0, graphWorst = 0;
    for (int k = 0; k < kPoses; ++k)
    {
        chainWorst = std::max(chainWorst, angleDeg(chain[k], truth[k]));
        graphWorst = std::max(graphWorst, angleDeg(poses[k], truth[k]));
    }
    // The chain ends 23 * 0.2 = 4.6 deg off. Least squares over 24 edges of equal weight leaves each
    // edge, the loop's too, a 24th of that: no pose is off by more than 4.6 / 24 = 0.19 deg.
    EXPECT_GT(chainWorst, 4.5);
    EXPECT_LT(graphWorst, 0.2);
    EXPECT_LT(shift(poses[kPoses - 1], truth[kPoses - 1]), shift(chain[kPoses - 1], truth[kPoses - 1]) / 5);
    EXPECT_GT(cost, 0.0);
}

TEST(Tripose_PoseGraph, bad_graphs_are_refused_naming_the_argument)
{
    const std::vector<CameraPose> poses = ringPoses();
    std::vector<bool> held(kPoses, false);
    held[0] = true;
    std::vector<PoseGraphEdge> chain;
    for (int k = 1; k < kPoses; ++k)
        chain.push_back(edge(k - 1, k, relative(poses[k - 1], poses[k])));

    expectRefusalNaming(poses, std::vector<bool>(3, true), chain, 1.0, "held");
    expectRefusalNaming(poses, held, chain, 0.0, "translationScale");
    std::vector<PoseGraphEdge> bad = chain;
    bad[1].to = kPoses;
    expectRefusalNaming(poses, held, bad, 1.0, "edges[1]");
    bad = chain;
    bad[2].to = bad[2].from;
    expectRefusalNaming(poses, held, bad, 1.0, "edges[2]");
    bad = chain;
    bad[3].weight = -1;
    expectRefusalNaming(poses, held, bad, 1.0, "edges[3].weight");
    bad = chain;
    bad[4].relative.t.x() = std::nan("");
    expectRefusalNaming(poses, held, bad, 1.0, "edges[4].relative");
    // Poses 11 onwards hang together but from no held pose.
    bad = chain;
    bad.erase(bad.begin() + 10);
    expectRefusalNaming(poses, held, bad, 1.0, "linked to no held pose");
}

} // namespace
} // namespace opencv_test
