// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_LOOP_CORRECTION_HPP
#define TRIPOSE_CORE_TRACKING_LOOP_CORRECTION_HPP

#include "track_store.hpp"

namespace tripose {

/** Whether a frame's pose through a place, @p loopPose, and its tracked pose @p tracked differ enough
to close a loop: by more than 0.1 deg of rotation, or a shift of more than 0.2 % of the distance
from the frame to the place's keyframe at @p keyframePose. Nearer poses are the same pose within
the registrations' errors, and moving the trajectory for them would only add the place's noise. */
bool closesLoop(const CameraPose& tracked, const CameraPose& loopPose, const CameraPose& keyframePose);

/** The keyframes strictly between frames @p first and @p last. */
int keyframesBetween(const TrackStore& store, int first, int last);

/** Whether a place of keyframe @p keyframe seen again from frame @p frame may close a loop: more than
@p span keyframes lie between them, and at least @p rest since frame @p lastLoop (-1: none) closed
the last loop. A nearer place is the window's neighbourhood seen from a little farther, and the
frames that follow a closed loop see its place again: their tracks join the place's, the
adjustments hold them, and correcting the trajectory for each would only add the registrations'
noise to it. */
bool mayCloseLoop(const TrackStore& store, int keyframe, int frame, int span, int lastLoop, int rest);

/** Corrects the poses of the frames after keyframe @p keyframe up to frame @p frame (a loop closed:
the frame registered through the keyframe's place at @p loopPose) by a pose graph. The frame is put
at @p loopPose; the frames in between registered in the keyframe's map are first given a share of
that correction (frame k the share (k - keyframe) / (frame - keyframe) of the rotation and
translation that takes the frame's tracked pose onto @p loopPose), then moved by the graph
(optimizePoseGraph(), a radian weighed as the mean step between the frames): its edges are the
tracked relative poses of consecutive frames and of keyframes at most @p span keyframes apart that
share @p minShared tracks (farther ones may share only the tracks the loop just joined), between the
keyframe and the frame, both held, as are given frames. A graph that cannot be solved leaves the
shares. */
void correctLoop(TrackStore& store, int keyframe, int frame, const CameraPose& loopPose, int minShared, int span);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_LOOP_CORRECTION_HPP
