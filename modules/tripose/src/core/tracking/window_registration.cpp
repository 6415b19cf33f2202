// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "window_registration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../linear/multiview_pose_solver.hpp"
#include "../pipeline/pose_pipelines.hpp"
#include "../pipeline/posed_structure.hpp"
#include "../problem/view_set_builder.hpp"
#include "../support/error.hpp"
#include "window_problem.hpp"

namespace tripose {

namespace {

/** Drops, feature by feature, the observation of the first @p views views furthest from the
structure triangulated from them while it is more than @p threshold px off. */
void dropInconsistentObservations(WindowProblem& problem, size_t views, double threshold)
{
    // Each round drops at most one observation per feature; a feature has at most one per view.
    for (size_t round = 0; round < views; ++round)
    {
        const PosedStructure structure = problem.triangulate(views);
        bool dropped = false;
        for (int kind = 0; kind < 2; ++kind)
        {
            const std::vector<double>& errors = kind == 0 ? structure.pointErrors : structure.lineErrors;
            for (int i = 0; i < (int)problem.tracks[kind].size(); ++i)
            {
                double worst = 0;
                int at = -1;
                for (size_t v = 0; v < views; ++v)
                {
                    const double e = errors[(size_t)i * views + v];
                    if (!std::isnan(e) && e > worst)
                    {
                        worst = e;
                        at = (int)v;
                    }
                }
                if (at >= 0 && worst > threshold)
                {
                    ArgumentMatrix& m = problem.rows(kind, at);
                    std::fill(m.values.begin() + (size_t)i * m.cols, m.values.begin() + (size_t)(i + 1) * m.cols,
                              std::numeric_limits<double>::quiet_NaN());
                    dropped = true;
                }
            }
        }
        if (!dropped)
            break;
    }
}

/** The median, over the inlier points and the end points of the inlier lines triangulated from the
first @p views views, of the angle (deg) between the rays from the last of them and from @p pose:
how far the frame moved for that structure. +inf without structure. */
double medianParallaxDeg(const WindowProblem& problem, size_t views, const CameraPose& pose,
                         const std::vector<unsigned char>& pointInliers, const std::vector<unsigned char>& lineInliers)
{
    const PosedStructure structure = problem.triangulate(views);
    Eigen::Matrix3d R;
    const ArgumentMatrix& lastR = problem.Rs[views - 1];
    for (int i = 0; i < 9; ++i)
        R(i / 3, i % 3) = lastR.values[i];
    const Eigen::Vector3d lastT(problem.ts[views - 1].values.data());
    const Eigen::Vector3d last = -R.transpose() * lastT, current = pose.centre();
    std::vector<double> angles;
    const auto add = [&](const std::vector<Eigen::Vector3d>& X, int perFeature, const std::vector<unsigned char>& inliers) {
        for (size_t k = 0; k < X.size(); ++k)
        {
            const size_t feature = k / perFeature;
            if (!inliers.empty() && !inliers[feature])
                continue;
            const Eigen::Vector3d a = X[k] - last, b = X[k] - current;
            const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
            if (std::isfinite(angle))
                angles.push_back(angle * 180.0 / M_PI);
        }
    };
    add(structure.points, 1, pointInliers);
    add(structure.lineEnds, 2, lineInliers);
    if (angles.empty())
        return std::numeric_limits<double>::infinity();
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    return angles[angles.size() / 2];
}

//! The tracks of kind @p kind that frame @p frame sees with at least @p minOthers of @p others.
std::vector<int> sharedTracks(const TrackStore& store, FeatureKind kind, int frame, const std::vector<int>& others,
                              int minOthers)
{
    std::vector<int> shared;
    const StoredFrame& f = store.frames[frame];
    for (int track : kind == FeatureKind::Point ? f.pointTrack : f.lineTrack)
    {
        if (track < 0)
            continue;
        int count = 0;
        for (int o : others)
            count += store.rowIn(kind, track, o) >= 0 ? 1 : 0;
        if (count >= minOthers)
            shared.push_back(track);
    }
    std::sort(shared.begin(), shared.end());
    return shared;
}

} // namespace

Registration registerAgainstWindow(const TrackStore& store, int frame, const std::vector<int>& window,
                                   const TrackerOptions& options)
{
    Registration out;
    std::vector<int> features[2] = { sharedTracks(store, FeatureKind::Point, frame, window, 2),
                                      sharedTracks(store, FeatureKind::Line, frame, window, 2) };
    std::vector<int> views = window;
    views.push_back(frame);
    WindowProblem problem(store, views, features, (int)window.size());
    const bool check = options.checkTracks && options.robust;
    if (check && problem.numFeatures() >= kMinFeatures)
    {
        dropInconsistentObservations(problem, window.size(), options.ransac.threshold);
        problem.keepSeenTwice(window.size());
    }
    out.features = problem.numFeatures();
    // Fewer features than the inliers a pose needs: no estimate could be kept, so none is made.
    if (out.features < std::max(kMinFeatures, options.minInliers))
    {
        out.reason = formatString("shares %d features with the window of %d keyframes; at least %d are needed",
                                  out.features, (int)window.size(), std::max(kMinFeatures, options.minInliers));
        return out;
    }
    const ViewSet set = buildMultiViewSet(problem.arguments, problem.Rs, problem.ts, kMinFeatures);
    const MultiViewPoseSolver linear(set);
    std::vector<unsigned char> pointInliers, lineInliers;
    if (options.robust)
    {
        // The tracker's floor is the one that decides: the estimate's own is set to it.
        RansacOptions ransac = options.ransac;
        ransac.minInliers = options.minInliers;
        RobustEstimate estimate;
        if (estimateRobustOnKnownStructure(set, linear, ransac, estimate, BasinSearch::EstimateOnly))
        {
            out.pose = estimate.pose;
            out.inliers = estimate.numInliers;
            pointInliers = estimate.pointInliers;
            lineInliers = estimate.lineInliers;
        }
    }
    else
    {
        const std::vector<ScoredPose> candidates = estimateCandidates(set, linear, false);
        if (!candidates.empty())
        {
            out.pose = candidates.front().pose;
            out.inliers = out.features;
        }
    }
    if (out.inliers < options.minInliers || !out.pose.allFinite())
    {
        out.reason = formatString("%d of its %d features agree with the best pose; at least %d must", out.inliers,
                                  out.features, options.minInliers);
        out.inliers = 0;
        return out;
    }
    out.registered = true;
    if (options.covariance && options.robust)
        out.covariance = covarianceOfEstimate(set, out.pose, options.ransac.refineOptions, &pointInliers, &lineInliers);
    else if (options.covariance)
        out.covariance = covarianceOfEstimate(set, out.pose, options.ransac.refineOptions);
    // Judged on the registration's own poses, which a local adjustment moves by a small fraction of
    // any parallax that matters here.
    out.keyframe = !(medianParallaxDeg(problem, window.size(), out.pose, pointInliers, lineInliers) <
                     options.keyframeParallaxDeg);
    if (check)
        for (int kind = 0; kind < 2; ++kind)
        {
            const std::vector<unsigned char>& inliers = kind == 0 ? pointInliers : lineInliers;
            std::vector<int>& rejected = kind == 0 ? out.rejectedPoints : out.rejectedLines;
            for (size_t i = 0; i < inliers.size(); ++i)
                if (!inliers[i])
                    rejected.push_back(problem.tracks[kind][i]);
        }
    return out;
}

} // namespace tripose
