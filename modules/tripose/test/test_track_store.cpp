// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The tracker's TrackStore: merging two tracks of one scene feature moves every observation of the
// dropped track into the kept one, in frame order, and leaves the dropped track empty; two tracks
// seen in a common frame are two features and stay as they were.

#include "test_precomp.hpp"

#include <utility>
#include <vector>

#include "../src/core/tracking/track_store.hpp"

namespace opencv_test {
namespace {

using ::tripose::FeatureKind;
using ::tripose::TrackStore;

using TrackObservations = std::vector<std::pair<int, int>>;

//! @p frames frames of @p features points and segments each, in no track.
TrackStore storeOfFrames(int frames, int features)
{
    TrackStore store;
    store.frames.resize(frames);
    for (auto& f : store.frames)
    {
        f.points.assign(features, Eigen::Vector2d(1, 2));
        f.segments.assign(features, Eigen::Vector4d(1, 2, 3, 4));
        f.pointTrack.assign(features, -1);
        f.lineTrack.assign(features, -1);
    }
    return store;
}

//! A new track of @p kind observed at the (frame, row) pairs given.
int trackOf(TrackStore& store, FeatureKind kind, const TrackObservations& observations)
{
    const int track = store.newTrack(kind);
    for (const auto& o : observations)
        store.observe(kind, track, o.first, o.second);
    return track;
}

//! The frames' record of each feature's track, for one kind.
std::vector<std::vector<int>> featureTracks(const TrackStore& store, FeatureKind kind)
{
    std::vector<std::vector<int>> out;
    for (const auto& f : store.frames)
        out.push_back(kind == FeatureKind::Point ? f.pointTrack : f.lineTrack);
    return out;
}

TEST(Tripose_TrackStore, merge_of_tracks_in_different_frames_moves_every_observation)
{
    for (const FeatureKind kind : { FeatureKind::Point, FeatureKind::Line })
    {
        TrackStore store = storeOfFrames(6, 4);
        // The kept track in frames 0, 2 and 5, the dropped one in frames 1, 3 and 4: the merged track
        // interleaves them and must still be in frame order.
        const int keep = trackOf(store, kind, { { 0, 1 }, { 2, 3 }, { 5, 0 } });
        const int drop = trackOf(store, kind, { { 1, 2 }, { 3, 1 }, { 4, 0 } });
        const int other = trackOf(store, kind, { { 1, 0 }, { 2, 0 } });

        ASSERT_TRUE(store.merge(kind, keep, drop));

        const TrackObservations merged = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 1 }, { 4, 0 }, { 5, 0 } };
        EXPECT_EQ(merged, store.observationsOf(kind, keep));
        EXPECT_TRUE(store.observationsOf(kind, drop).empty());
        EXPECT_EQ(3, store.numTracks(kind)); // the dropped track stays, empty: track ids do not move
        for (const auto& o : merged)
        {
            EXPECT_EQ(keep, kind == FeatureKind::Point ? store.frames[o.first].pointTrack[o.second]
                                                       : store.frames[o.first].lineTrack[o.second])
                << "frame " << o.first << ", row " << o.second;
            EXPECT_EQ(o.second, store.rowIn(kind, keep, o.first));
            EXPECT_EQ(-1, store.rowIn(kind, drop, o.first));
        }
        const TrackObservations untouched = { { 1, 0 }, { 2, 0 } };
        EXPECT_EQ(untouched, store.observationsOf(kind, other));
        // The other kind is not touched.
        const FeatureKind otherKind = kind == FeatureKind::Point ? FeatureKind::Line : FeatureKind::Point;
        EXPECT_EQ(0, store.numTracks(otherKind));
        // A track merged into itself is unchanged.
        EXPECT_TRUE(store.merge(kind, keep, keep));
        EXPECT_EQ(merged, store.observationsOf(kind, keep));
    }
}

TEST(Tripose_TrackStore, tracks_seen_in_a_common_frame_are_not_merged)
{
    for (const FeatureKind kind : { FeatureKind::Point, FeatureKind::Line })
    {
        TrackStore store = storeOfFrames(5, 3);
        // Both tracks are seen in frame 2 (at different rows: two features of that frame).
        const TrackObservations first = { { 0, 0 }, { 2, 1 }, { 4, 2 } };
        const TrackObservations second = { { 1, 1 }, { 2, 2 }, { 3, 0 } };
        const int a = trackOf(store, kind, first);
        const int b = trackOf(store, kind, second);
        const std::vector<std::vector<int>> before = featureTracks(store, kind);

        EXPECT_FALSE(store.merge(kind, a, b));
        EXPECT_FALSE(store.merge(kind, b, a));

        EXPECT_EQ(first, store.observationsOf(kind, a));
        EXPECT_EQ(second, store.observationsOf(kind, b));
        EXPECT_EQ(before, featureTracks(store, kind));
        EXPECT_EQ(2, store.numTracks(kind));
    }
}

} // namespace
} // namespace opencv_test
