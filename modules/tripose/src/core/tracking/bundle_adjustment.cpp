// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "bundle_adjustment.hpp"

#include <algorithm>
#include <cmath>

#include "../problem/view_set_builder.hpp"
#include "../pipeline/pose_pipelines.hpp"
#include "window_problem.hpp"

namespace tripose {

namespace {

/** The Cauchy loss scale of matched tracks, as a fraction of the RANSAC threshold (0.5 px at 2 px).
They are linked by matching, not by a consensus on these poses: under a Huber loss at the threshold
a wrong link pulls by its whole residual up to the threshold, under a Cauchy loss its pull fades
beyond the scale. Tracks the caller links keep the Huber loss at the threshold: the caller checks
its links, and the video mode's followed points drift under the Cauchy loss
(doc/studies/front_end_and_tracker.md, "Against COLMAP"). */
const double kMatchedLossScaleOfThreshold = 0.25;

//! The tracks of kind @p kind seen by at least two of @p frames, at least one of them in @p among.
std::vector<int> tracksSeenTwice(const TrackStore& store, FeatureKind kind, const std::vector<int>& among,
                                 const std::vector<int>& frames)
{
    std::vector<int> candidates, out;
    for (int f : among)
        for (int track : kind == FeatureKind::Point ? store.frames[f].pointTrack : store.frames[f].lineTrack)
            if (track >= 0)
                candidates.push_back(track);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (int track : candidates)
    {
        int count = 0;
        for (int f : frames)
            count += store.rowIn(kind, track, f) >= 0 ? 1 : 0;
        if (count >= 2)
            out.push_back(track);
    }
    return out;
}

} // namespace

bool adjustFrames(TrackStore& store, const std::vector<int>& free, const std::vector<int>& fixed,
                  const TrackerOptions& options, TrackLinks links)
{
    std::vector<int> all = fixed;
    all.insert(all.end(), free.begin(), free.end());
    std::vector<int> features[2];
    for (int kind = 0; kind < 2; ++kind)
        features[kind] = tracksSeenTwice(store, kKinds[kind], free, all);
    if ((int)(features[0].size() + features[1].size()) < kMinFeatures)
        return false;
    const WindowProblem problem(store, all, features, (int)all.size());
    std::vector<int> fixedFlags(all.size(), 0), poseOfView;
    std::fill(fixedFlags.begin(), fixedFlags.begin() + fixed.size(), 1);
    std::vector<CameraPose> poses;
    const ViewSet set =
        buildSeveralPosesSet(problem.arguments, problem.Rs, problem.ts, fixedFlags, "fixed", poseOfView, poses);
    RefineOptions refine;
    const bool matched = links == TrackLinks::Matched;
    refine.loss = matched ? Loss::Cauchy : Loss::Huber;
    refine.lossScale = (matched ? kMatchedLossScaleOfThreshold : 1.0) * options.ransac.threshold;
    const double rms = refineSeveralPoses(set, poseOfView, poses, refine);
    if (!std::isfinite(rms))
        return false;
    for (const CameraPose& pose : poses)
        if (!pose.allFinite())
            return false;
    const std::vector<CameraPose> refined = allViewPoses(set, poseOfView, poses);
    for (size_t v = fixed.size(); v < all.size(); ++v)
        store.frames[all[v]].pose = refined[v];
    return true;
}

int splitDisagreeingObservations(TrackStore& store, const std::vector<int>& among, const std::vector<int>& frames,
                                 double threshold)
{
    std::vector<bool> splittable(frames.size(), false);
    for (size_t v = 0; v < frames.size(); ++v)
        splittable[v] = std::find(among.begin(), among.end(), frames[v]) != among.end();
    std::vector<int> features[2];
    for (int kind = 0; kind < 2; ++kind)
        features[kind] = tracksSeenTwice(store, kKinds[kind], among, frames);
    if (features[0].empty() && features[1].empty())
        return 0;
    const WindowProblem problem(store, frames, features, (int)frames.size());
    const PosedStructure structure = problem.triangulate(frames.size());
    int count = 0;
    for (int kind = 0; kind < 2; ++kind)
    {
        const std::vector<double>& errors = kind == 0 ? structure.pointErrors : structure.lineErrors;
        for (size_t i = 0; i < features[kind].size(); ++i)
            for (size_t v = 0; v < frames.size(); ++v)
            {
                if (!splittable[v])
                    continue;
                const double e = errors[i * frames.size() + v];
                // +inf: no structure to judge by; NaN: not seen.
                if (std::isfinite(e) && e > threshold)
                {
                    store.split(kKinds[kind], frames[v], store.rowIn(kKinds[kind], features[kind][i], frames[v]));
                    ++count;
                }
            }
    }
    return count;
}

bool adjustAndSplitOutliers(TrackStore& store, const std::vector<int>& free, const std::vector<int>& fixed,
                            const std::vector<int>& splitIn, const TrackerOptions& options, TrackLinks links,
                            int rounds)
{
    std::vector<int> all = fixed;
    all.insert(all.end(), free.begin(), free.end());
    bool adjusted = false;
    for (int round = 0; round < rounds; ++round)
    {
        if (!adjustFrames(store, free, fixed, options, links))
            return adjusted;
        adjusted = true;
        if (splitDisagreeingObservations(store, splitIn, all, options.ransac.threshold) == 0)
            break;
    }
    return adjusted;
}

} // namespace tripose
