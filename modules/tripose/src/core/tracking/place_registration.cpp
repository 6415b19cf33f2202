// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "place_registration.hpp"

#include <algorithm>
#include <map>

#include "../support/error.hpp"
#include "frame_matching.hpp"

namespace tripose {

namespace {

//! Joins feature @p row of @p frame to the track of feature @p keyRow of @p keyframe.
void join(TrackStore& store, FeatureKind kind, int keyframe, int keyRow, int frame, int row)
{
    const std::vector<int>& keyTracks =
        kind == FeatureKind::Point ? store.frames[keyframe].pointTrack : store.frames[keyframe].lineTrack;
    int track = keyTracks[keyRow];
    if (track < 0)
    {
        track = store.newTrack(kind);
        store.observe(kind, track, keyframe, keyRow);
    }
    const int own = (kind == FeatureKind::Point ? store.frames[frame].pointTrack : store.frames[frame].lineTrack)[row];
    if (own == track)
        return;
    if (own < 0)
    {
        if (store.rowIn(kind, track, frame) < 0)
            store.observe(kind, track, frame, row);
        return;
    }
    store.merge(kind, track, own);
}

} // namespace

void joinToKeyframeTracks(TrackStore& store, int keyframe, int frame, const Matches& points, const Matches& segments)
{
    for (const auto& m : points)
        join(store, FeatureKind::Point, keyframe, m.first, frame, m.second);
    for (const auto& m : segments)
        join(store, FeatureKind::Line, keyframe, m.first, frame, m.second);
}

std::vector<std::pair<int, int>> keyframesSharingTracks(const TrackStore& store, int frame, int minShared)
{
    std::map<int, int> shared;
    const StoredFrame& f = store.frames[frame];
    for (int kind = 0; kind < 2; ++kind)
    {
        const FeatureKind k = kind == 0 ? FeatureKind::Point : FeatureKind::Line;
        for (int track : kind == 0 ? f.pointTrack : f.lineTrack)
            if (track >= 0)
                for (const auto& o : store.observationsOf(k, track))
                    if (o.first != frame && store.frames[o.first].keyframe && store.frames[o.first].hasPose())
                        ++shared[o.first];
    }
    std::vector<std::pair<int, int>> ranked;
    for (const auto& s : shared)
        if (s.second >= minShared)
            ranked.push_back(s);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.second > b.second; });
    return ranked;
}

std::vector<int> covisibleKeyframes(const TrackStore& store, int keyframe, int count)
{
    std::vector<int> out = { keyframe };
    for (const auto& k : keyframesSharingTracks(store, keyframe, 1))
        if ((int)out.size() < count)
            out.push_back(k.first);
    std::sort(out.begin(), out.end());
    return out;
}

Registration registerAgainstPlace(TrackStore& store, int frame, const FrameFeatures& features, int keyframe,
                                  const FrameFeatures& keyframeFeatures, const std::vector<int>& neighbours,
                                  const TrackerOptions& options, int minInliers)
{
    Registration out;
    Matches points, segments;
    if (!matchUnderFundamental(keyframeFeatures, features, options.matching, points, segments))
    {
        out.reason = "too few matches with the keyframe for their epipolar geometry";
        return out;
    }
    TrackStore before = store;
    joinToKeyframeTracks(store, keyframe, frame, points, segments);
    TrackerOptions placeOptions = options;
    placeOptions.minInliers = minInliers;
    runCatchingInputErrors([&] { out = registerAgainstWindow(store, frame, neighbours, placeOptions); }, &out.reason);
    // Matches to a place are checked by no earlier frame: a pose most of them contradict is a
    // coincidence of repeated texture, not the place.
    if (out.registered && 2 * out.inliers < out.features)
    {
        out.registered = false;
        out.reason = formatString("%d of the %d features shared with the place agree with its pose; half must",
                                  out.inliers, out.features);
    }
    if (!out.registered)
        store = std::move(before);
    return out;
}

} // namespace tripose
