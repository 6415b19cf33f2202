// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_PLACE_REGISTRATION_HPP
#define TRIPOSE_CORE_TRACKING_PLACE_REGISTRATION_HPP

#include <utility>
#include <vector>

#include "frame_features.hpp"
#include "frame_matching.hpp"
#include "track_store.hpp"
#include "tracker_options.hpp"
#include "window_registration.hpp"

namespace tripose {

/** Joins each matched feature of frame @p frame to the track of its match in keyframe @p keyframe
(@p points and @p segments: (keyframe row, frame row)), merging the two tracks where the frame's
feature already had one and they share no frame. */
void joinToKeyframeTracks(TrackStore& store, int keyframe, int frame, const Matches& points, const Matches& segments);

/** The posed keyframes other than @p frame that observe at least @p minShared of the tracks frame
@p frame observes, as (keyframe, shared tracks), most shared first. */
std::vector<std::pair<int, int>> keyframesSharingTracks(const TrackStore& store, int frame, int minShared);

/** Keyframe @p keyframe and the keyframes that share most tracks with it, @p count in all, in frame
order: the neighbourhood a frame that sees the keyframe's place is registered against. */
std::vector<int> covisibleKeyframes(const TrackStore& store, int keyframe, int count);

/** Registers frame @p frame against a place seen before, keyframe @p keyframe and @p neighbours (a
loop, or a lost camera found again): the frame's features are matched to the keyframe's under their
fundamental matrix (matchUnderFundamental()); each match joins the frame's feature to the keyframe
feature's track, the two tracks merged where the frame's feature already had one and they share no
frame; then registerAgainstWindow() on @p neighbours with @p minInliers, and at least half of the features
agreeing with the pose. Registered: the store keeps
the links (the frame's pose is left to the caller); else the store is as it was. */
Registration registerAgainstPlace(TrackStore& store, int frame, const FrameFeatures& features, int keyframe,
                                  const FrameFeatures& keyframeFeatures, const std::vector<int>& neighbours,
                                  const TrackerOptions& options, int minInliers);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_PLACE_REGISTRATION_HPP
