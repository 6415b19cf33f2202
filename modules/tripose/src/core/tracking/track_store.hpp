// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_TRACK_STORE_HPP
#define TRIPOSE_CORE_TRACKING_TRACK_STORE_HPP

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "tracker_options.hpp"

namespace tripose {

//! One frame as the tracker keeps it: its camera, pose and features' positions, and each
//! feature's track.
struct StoredFrame
{
    Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
    FrameStatus status = FrameStatus::Lost;
    CameraPose pose; //!< Meaningful unless lost.
    bool keyframe = false;
    int map = 0; //!< The map the pose is in (FrameResult::map).
    std::vector<Eigen::Vector2d> points;
    std::vector<Eigen::Vector4d> segments;
    std::vector<int> pointTrack, lineTrack; //!< Per feature, its track (-1: none).

    bool hasPose() const { return status != FrameStatus::Lost; }
};

//! @p result's status, pose, keyframe flag and tracks from frame @p f as it stands.
void describeFrame(const StoredFrame& f, FrameResult& result);

enum class FeatureKind
{
    Point = 0,
    Line = 1
};

/** The frames and the tracks that link their features: a track is one feature of the scene, with at
most one observation per frame. */
class TrackStore
{
public:
    std::vector<StoredFrame> frames;

    int numTracks(FeatureKind kind) const { return (int)tracks(kind).size(); }
    //! A new empty track.
    int newTrack(FeatureKind kind);
    //! Feature @p row of frame @p frame joins @p track (it must be in no track yet).
    void observe(FeatureKind kind, int track, int frame, int row);
    //! The row of @p track's observation in frame @p frame, -1 when it has none there.
    int rowIn(FeatureKind kind, int track, int frame) const;
    //! Feature @p row of frame @p frame leaves its track and starts a new one, returned.
    int split(FeatureKind kind, int frame, int row);
    /** Joins track @p drop into @p keep (one feature of the scene seen as two): false, both unchanged,
    when they are seen in a common frame; else @p drop is left empty. */
    bool merge(FeatureKind kind, int keep, int drop);
    //! The (frame, row) observations of @p track, in frame order.
    const std::vector<std::pair<int, int>>& observationsOf(FeatureKind kind, int track) const
    {
        return tracks(kind)[track];
    }
    //! The observation of @p track in frame @p frame: 2 (point) or 4 (segment) values, or NaN.
    void observation(FeatureKind kind, int track, int frame, double* out) const;

private:
    using Track = std::vector<std::pair<int, int>>; //!< (frame, row), by frame.
    std::vector<Track>& tracks(FeatureKind kind) { return kind == FeatureKind::Point ? pointTracks_ : lineTracks_; }
    const std::vector<Track>& tracks(FeatureKind kind) const
    {
        return kind == FeatureKind::Point ? pointTracks_ : lineTracks_;
    }
    std::vector<int>& trackOf(FeatureKind kind, int frame)
    {
        return kind == FeatureKind::Point ? frames[frame].pointTrack : frames[frame].lineTrack;
    }

    std::vector<Track> pointTracks_, lineTracks_;
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_TRACK_STORE_HPP
