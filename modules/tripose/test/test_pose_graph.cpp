// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The loop closure's pose graph: edges that agree with the true poses bring perturbed poses back to
// them; a chain whose steps carry a bias, closed by one true loop edge, ends far nearer the truth at
// every pose than the chain alone; held poses never move; bad graphs are refused naming the argument;
// the rotation vector of its errors is exact near the identity. The tracker's loop correction on that
// graph puts the loop's frame at its pose through the place and corrects the frames in between, the
// keyframe and given frames held and lost frames left as they were.

#include "test_precomp.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "../src/core/geometry/rotation.hpp"
#include "../src/core/support/error.hpp"
#include "../src/core/tracking/loop_correction.hpp"
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
    // Every step of the chain turns 0.2 deg less than the truth about the ring's axis and moves 1 %
    // too far: the chain's poses drift away from the truth as a tracker's do, 4.6 deg at the end.
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
    // edge, the loop's too, about a 24th of that: 4.6 / 24 = 0.19 deg at most (0.188 measured, the
    // last pose; the data hold no noise, so the bound is as tight as the optimum).
    EXPECT_GT(chainWorst, 4.5);
    EXPECT_LT(graphWorst, 0.2);
    EXPECT_LT(shift(poses[kPoses - 1], truth[kPoses - 1]), shift(chain[kPoses - 1], truth[kPoses - 1]) / 5);
    EXPECT_GT(cost, 1e-6); // the biased edges cannot all hold
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

TEST(Tripose_PoseGraph, loop_correction_puts_the_frame_at_the_place_and_corrects_the_frames_between)
{
    using ::tripose::FrameStatus;
    const std::vector<CameraPose> truth = ringPoses();
    const Eigen::Matrix3d bias = Eigen::AngleAxisd(0.2 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
    ::tripose::TrackStore store;
    store.frames.resize(kPoses);
    for (int k = 0; k < kPoses; ++k)
    {
        ::tripose::StoredFrame& f = store.frames[k];
        f.keyframe = true;
        f.status = k < 2 ? FrameStatus::Given : k == 12 ? FrameStatus::Lost : FrameStatus::Registered;
        if (k < 2)
        {
            f.pose = truth[k];
            continue;
        }
        // Tracked from the frame before (frame 12, lost, from frame 11): each step 0.2 deg short.
        const int from = k == 13 ? 11 : k - 1;
        CameraPose step = relative(truth[from], truth[k]);
        step.R = bias * step.R;
        const CameraPose& before = store.frames[from].pose;
        f.pose.R = step.R * before.R;
        f.pose.t = step.R * before.t + step.t;
    }
    const CameraPose lost = store.frames[12].pose;
    const int last = kPoses - 1;
    double before = 0;
    for (int k = 0; k < kPoses; ++k)
        before = std::max(before, angleDeg(store.frames[k].pose, truth[k]));
    ::tripose::correctLoop(store, 0, last, truth[last], 15, 10);

    EXPECT_EQ(store.frames[0].pose.R, truth[0].R);
    EXPECT_EQ(store.frames[1].pose.t, truth[1].t);
    EXPECT_EQ(store.frames[12].pose.R, lost.R);
    EXPECT_LT(angleDeg(store.frames[last].pose, truth[last]), 1e-9);
    EXPECT_LT(shift(store.frames[last].pose, truth[last]), 1e-9);
    double after = 0;
    for (int k = 0; k < kPoses; ++k)
        if (k != 12)
            after = std::max(after, angleDeg(store.frames[k].pose, truth[k]));
    // 21 tracked steps of 0.2 deg short from frame 1 (frame 12 skipped): 4.2 deg at the end. Each
    // step short by the same angle, least squares gives each the same share back and every frame
    // returns to the truth, frames 13 on too, which shares by frame number would leave off.
    EXPECT_GT(before, 4.0);
    EXPECT_LT(after, 1e-6);
}

TEST(Tripose_PoseGraph, a_loop_closes_only_beyond_the_span_and_once_per_loop)
{
    // Frames 0-39, every other one a keyframe (0, 2, ..., 38).
    ::tripose::TrackStore store;
    store.frames.resize(40);
    for (int k = 0; k < 40; ++k)
        store.frames[k].keyframe = k % 2 == 0;
    EXPECT_EQ(::tripose::keyframesBetween(store, 0, 10), 4);
    EXPECT_EQ(::tripose::keyframesBetween(store, 1, 2), 0);
    // Span 10: keyframe 16 has 10 keyframes (18..36) before frame 38, keyframe 14 has 11.
    EXPECT_FALSE(::tripose::mayCloseLoop(store, 16, 38, 10, -1, 5));
    EXPECT_TRUE(::tripose::mayCloseLoop(store, 14, 38, 10, -1, 5));
    // The rest after a loop, 5 keyframes: closed at frame 30 or 28, frame 38 has 3 or 4 keyframes since;
    // at 26 or 27, 5.
    EXPECT_FALSE(::tripose::mayCloseLoop(store, 0, 38, 10, 30, 5));
    EXPECT_TRUE(::tripose::mayCloseLoop(store, 0, 38, 10, 26, 5));
    EXPECT_TRUE(::tripose::mayCloseLoop(store, 0, 38, 10, 27, 5));
    EXPECT_FALSE(::tripose::mayCloseLoop(store, 0, 38, 10, 28, 5));
}

} // namespace
} // namespace opencv_test
