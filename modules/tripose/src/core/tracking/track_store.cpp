// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "track_store.hpp"

#include <algorithm>
#include <limits>

#include "../support/error.hpp"

namespace tripose {

void describeFrame(const StoredFrame& f, FrameResult& result)
{
    result.status = f.status;
    result.pose = f.pose;
    result.keyframe = f.keyframe;
    result.map = f.map;
    result.pointTracks = f.pointTrack;
    result.lineTracks = f.lineTrack;
}

int TrackStore::newTrack(FeatureKind kind)
{
    tracks(kind).emplace_back();
    return numTracks(kind) - 1;
}

void TrackStore::observe(FeatureKind kind, int track, int frame, int row)
{
    int& current = trackOf(kind, frame)[row];
    TRIPOSE_ASSERT(current < 0);
    current = track;
    tracks(kind)[track].emplace_back(frame, row);
}

int TrackStore::rowIn(FeatureKind kind, int track, int frame) const
{
    const Track& t = tracks(kind)[track];
    // Observations are kept in frame order: the most recent frames are at the back.
    for (auto it = t.rbegin(); it != t.rend(); ++it)
        if (it->first == frame)
            return it->second;
    return -1;
}

int TrackStore::split(FeatureKind kind, int frame, int row)
{
    int& current = trackOf(kind, frame)[row];
    TRIPOSE_ASSERT(current >= 0);
    Track& old = tracks(kind)[current];
    old.erase(std::remove(old.begin(), old.end(), std::make_pair(frame, row)), old.end());
    current = -1;
    const int track = newTrack(kind);
    observe(kind, track, frame, row);
    return track;
}

bool TrackStore::merge(FeatureKind kind, int keep, int drop)
{
    if (keep == drop)
        return true;
    Track& a = tracks(kind)[keep];
    Track& b = tracks(kind)[drop];
    for (const auto& o : b)
        if (rowIn(kind, keep, o.first) >= 0)
            return false;
    for (const auto& o : b)
        trackOf(kind, o.first)[o.second] = keep;
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end());
    b.clear();
    return true;
}

void TrackStore::observation(FeatureKind kind, int track, int frame, double* out) const
{
    const int row = rowIn(kind, track, frame);
    const int width = kind == FeatureKind::Point ? 2 : 4;
    for (int c = 0; c < width; ++c)
    {
        if (row < 0)
            out[c] = std::numeric_limits<double>::quiet_NaN();
        else
            out[c] = kind == FeatureKind::Point ? frames[frame].points[row][c] : frames[frame].segments[row][c];
    }
}

} // namespace tripose
