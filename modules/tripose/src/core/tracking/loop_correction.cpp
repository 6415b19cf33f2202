// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "loop_correction.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "../support/error.hpp"
#include "place_registration.hpp"
#include "pose_graph.hpp"

namespace tripose {

bool closesLoop(const CameraPose& tracked, const CameraPose& loopPose, const CameraPose& keyframePose)
{
    const double maxAngle = 0.1 * M_PI / 180.0, maxShiftOfReach = 0.002;
    const double angle = Eigen::AngleAxisd(loopPose.R * tracked.R.transpose()).angle();
    const double shift = (loopPose.centre() - tracked.centre()).norm();
    const double reach = (keyframePose.centre() - tracked.centre()).norm();
    return angle > maxAngle || shift > maxShiftOfReach * reach;
}

int keyframesBetween(const TrackStore& store, int first, int last)
{
    int count = 0;
    for (int k = first + 1; k < last; ++k)
        count += store.frames[k].keyframe ? 1 : 0;
    return count;
}

bool mayCloseLoop(const TrackStore& store, int keyframe, int frame, int span, int lastLoop, int rest)
{
    return keyframesBetween(store, keyframe, frame) > span &&
           (lastLoop < 0 || keyframesBetween(store, lastLoop, frame) >= rest);
}

void correctLoop(TrackStore& store, int keyframe, int frame, const CameraPose& loopPose, int minShared, int span)
{
    const int map = store.frames[keyframe].map;
    std::vector<int> nodes, nodeOf(frame + 1, -1);
    std::vector<CameraPose> poses;
    std::vector<bool> held;
    for (int k = keyframe; k <= frame; ++k)
    {
        const StoredFrame& f = store.frames[k];
        if (k != keyframe && k != frame && !(f.hasPose() && f.map == map))
            continue;
        nodeOf[k] = (int)nodes.size();
        nodes.push_back(k);
        poses.push_back(f.pose);
        held.push_back(k == keyframe || f.status == FrameStatus::Given);
    }
    std::vector<PoseGraphEdge> edges;
    auto addEdge = [&](int a, int b, const CameraPose& relative) {
        PoseGraphEdge edge;
        edge.from = nodeOf[a];
        edge.to = nodeOf[b];
        edge.relative = relative;
        edges.push_back(edge);
    };
    double steps = 0;
    int stepCount = 0;
    for (size_t n = 1; n < nodes.size(); ++n)
    {
        // A restarted frame was placed, not registered: its pose says nothing of the step to it.
        if (store.frames[nodes[n]].status == FrameStatus::Restarted)
            continue;
        addEdge(nodes[n - 1], nodes[n], poseRelativeTo(poses[n], poses[n - 1]));
        steps += (poses[n].centre() - poses[n - 1].centre()).norm();
        ++stepCount;
    }
    // Per node, the keyframes among the nodes up to it: how far apart two keyframes are.
    std::vector<int> keyframeRank(nodes.size(), 0);
    for (size_t n = 1; n < nodes.size(); ++n)
        keyframeRank[n] = keyframeRank[n - 1] + (store.frames[nodes[n]].keyframe ? 1 : 0);
    for (int k : nodes)
        if (k != frame && store.frames[k].keyframe)
            for (const auto& shared : keyframesSharingTracks(store, k, minShared))
            {
                const int other = shared.first;
                if (other > k && other < frame && nodeOf[other] > nodeOf[k] + 1 &&
                    keyframeRank[nodeOf[other]] - keyframeRank[nodeOf[k]] <= span)
                    addEdge(k, other, poseRelativeTo(poses[nodeOf[other]], poses[nodeOf[k]]));
            }

    // The world moved by G maps the frame's tracked pose onto its pose through the loop:
    // T_loop = T_frame * G^-1, so G = T_loop^-1 * T_frame.
    const CameraPose& tracked = store.frames[frame].pose;
    const Eigen::Matrix3d RG = loopPose.R.transpose() * tracked.R;
    const Eigen::Vector3d tG = loopPose.R.transpose() * (tracked.t - loopPose.t);
    const Eigen::AngleAxisd rotation(RG);
    for (size_t n = 1; n < nodes.size(); ++n)
    {
        if (held[n])
            continue;
        const double share = double(nodes[n] - keyframe) / double(frame - keyframe);
        const Eigen::Matrix3d Ra = Eigen::AngleAxisd(share * rotation.angle(), rotation.axis()).toRotationMatrix();
        poses[n].t = poses[n].t - poses[n].R * Ra.transpose() * (share * tG);
        poses[n].R = poses[n].R * Ra.transpose();
    }
    // The place puts the frame where the spread does: it stays there, and the graph moves the frames
    // in between.
    poses.back() = loopPose;
    held.back() = true;
    const double scale = steps > 0 ? steps / stepCount : 1.0;
    runCatchingInputErrors([&] { optimizePoseGraph(poses, held, edges, scale); });
    for (size_t n = 1; n < nodes.size(); ++n)
        if (store.frames[nodes[n]].status != FrameStatus::Given)
            store.frames[nodes[n]].pose = poses[n];
}

} // namespace tripose
