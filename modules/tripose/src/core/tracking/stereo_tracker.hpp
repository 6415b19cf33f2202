// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_STEREO_TRACKER_HPP
#define TRIPOSE_CORE_TRACKING_STEREO_TRACKER_HPP

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "../geometry/distortion.hpp"
#include "frame_features.hpp"
#include "keyframe_retrieval.hpp"
#include "track_store.hpp"
#include "tracker_options.hpp"

namespace tripose {

/** A calibrated stereo rig tracked frame by frame. Each frame is the features of the left and the
right image (positions in pixels, descriptors), optionally with the left camera's pose. No pose is
needed: the first frame's left camera is the world's origin unless it comes with a pose, and the
rig's baseline gives every pose its metric scale.

Each frame:
- its left and right features are matched under the rig's epipolar geometry (the stereo matches);
- its left features are linked to the left features of the frame before, as Tracker links frames
  (matchUnknownPose(); past a frame that shares too few matches for their geometry, to the nearest
  of the TrackerOptions::maxFrameGap frames before it that does, else to the newest of the last
  TrackerOptions::window keyframes that does, so that a longer run of lost frames does not end
  tracking): a track is one feature of the scene seen by the left camera, and the right camera
  sees it through the stereo match;
- it is registered with the stereo-rig estimator (estimateRobustRig(); the linear rig solver with
  TrackerOptions::robust off) against a keyframe A, on the features that both cameras of A see
  (A's stereo matches) and the new frame's left camera sees (and its right camera, where the new
  frame has a stereo match): views {left A, right A, left B, right B} in the frame of left A, left B
  estimated, then composed with A's pose to the world. The keyframe is the newest of the last
  TrackerOptions::window keyframes that shares at least TrackerOptions::minInliers such features
  and gives a pose with that many inliers; a frame that none gives a pose to is lost, and the next
  frame looks back over the same keyframes.

A frame that no window keyframe registers is tried against the places of the older keyframes: the
keyframes whose descriptors look most like the frame's (KeyframeRetrieval) are matched to it under
their fundamental matrix, and a keyframe registers it with twice TrackerOptions::minInliers inliers,
at least half of the features it shares agreeing (FrameResult::recognisedKeyframe).

A rig lost for more than TrackerOptions::maxFrameGap frames in a row, at a place no keyframe shows,
starts again: the next such frame with twice TrackerOptions::minInliers stereo matches, against whose
stereo pair the frame before it registers (chance matches of unrelated images do not), begins a new
map (FrameStatus::Restarted), placed at the last pose known, and the frames after it are tracked in
that map. While more than one map holds frames, each new keyframe looks for a place of another map;
when one registers it, the two maps are joined: the newer map's poses are moved by the rigid motion
that takes the frame's pose in it to its pose through the place, and its frames take the older
map's index (FrameResult::map).

A registered frame becomes a keyframe when the median angle its inlier structure (triangulated from
A's stereo pair) subtends between A's left camera and its own is at least
TrackerOptions::keyframeParallaxDeg, or when A's stereo pair sees less than half of its own stereo
matches: a rig that stands still adds no keyframes, so its error does not grow, and one that turns
on the spot adds them before its view leaves A's. Frames given a pose are keyframes. With TrackerOptions::checkTracks (and robust), the features a
registration rejects start new tracks. TrackerOptions::localAdjustment is not used.

Poses follow the library: x_cam = R X + t, X in the world frame; the pose of a frame is its left
camera's, the right camera is at the rig composed with it.
*/
/** One stereo frame's observations of tracks the caller linked: the left image's points and segments
with their ids (an id seen in several frames is one feature of the scene), and per point and segment
its position in the right image, NaN where the right camera does not see it. */
struct StereoObservations
{
    std::vector<Eigen::Vector2d> points;
    std::vector<int64_t> pointIds;
    std::vector<Eigen::Vector4d> segments; //!< x0 y0 x1 y1.
    std::vector<int64_t> lineIds;
    std::vector<Eigen::Vector2d> rightPoints;   //!< One per point.
    std::vector<Eigen::Vector4d> rightSegments; //!< One per segment: the same line's end points, any pair.
};

class StereoTracker
{
public:
    /** @p KLeft, @p KRight the cameras' matrices, @p distortionLeft, @p distortionRight their
    coefficients in OpenCV's model (empty: none; the features given are undistorted with them).
    @p rig the right camera's pose relative to the left (x_right = R x_left + t), t non-zero.
    Throws Error naming "K_left", "dist_left", "K_right", "dist_right", "R", "t" or "options". */
    StereoTracker(const Eigen::Matrix3d& KLeft, const std::vector<double>& distortionLeft, const Eigen::Matrix3d& KRight,
                  const std::vector<double>& distortionRight, const CameraPose& rig, const TrackerOptions& options);

    /** The next stereo frame from the features of its left and right images. @p pose, when given,
    is the left camera's pose (status Given). */
    FrameResult addFrame(const FrameFeatures& left, const FrameFeatures& right, const CameraPose* pose = nullptr);

    /** The next stereo frame from observations of tracks the caller linked (a video's points
    followed by optical flow): no matching and no descriptors, so no place is recognised and a rig
    lost for longer than TrackerOptions::maxFrameGap restarts without joining its maps. A tracker
    takes either features or observations. Throws Error naming "point_ids", "line_ids",
    "right_points", "right_segments", "points" or "segments". */
    FrameResult addObservations(const StereoObservations& observations, const CameraPose* pose = nullptr);

    int numFrames() const { return (int)store_.frames.size(); }
    //! Frame @p frame's left camera: its pose, status, features and their tracks.
    const StoredFrame& frame(int frame) const { return store_.frames.at(frame); }
    //! Per left point (segment) of frame @p frame, the row of its stereo match in the right image, -1 for none.
    const std::vector<int>& stereoPoints(int frame) const { return stereo_.at(frame).pointRight; }
    const std::vector<int>& stereoSegments(int frame) const { return stereo_.at(frame).lineRight; }
    const TrackerOptions& options() const { return options_; }
    const CameraPose& rig() const { return rig_; }

private:
    //! The right image of a frame and its stereo matches.
    struct StereoFrame
    {
        std::vector<Eigen::Vector2d> points;
        std::vector<Eigen::Vector4d> segments;
        std::vector<int> pointRight, lineRight;
    };
    struct Attempt;

    //! A frame's status and pose before registration: given (@p pose, or the first frame) or not.
    StoredFrame newFrame(const CameraPose* pose) const;

    void link(FeatureKind kind, int from, int to, const std::vector<std::pair<int, int>>& matches);
    void linkToRecent(int frame, const FrameFeatures& left);
    Attempt registerAgainst(int keyframe, int frame) const;
    //! The registration of @p frame through the place of a keyframe for which @p eligible holds;
    //! @p keyframe is set to that keyframe. The store keeps the links of a registration only.
    Attempt registerAtPlace(int frame, const FrameFeatures& left, const std::function<bool(int)>& eligible,
                            int& keyframe);
    //! Frame @p frame begins a new map at the last pose known.
    void restart(int frame);
    //! Joins the map of frame @p frame and the map of @p keyframe, whose place gave the frame @p placePose.
    void joinMaps(int frame, int keyframe, const CameraPose& placePose);
    FrameResult finishFrame(int frame, const FrameFeatures& left, double startSeconds);

    TrackerOptions options_;
    Eigen::Matrix3d K_[2];
    Distortion distortion_[2];
    bool distorted_[2] = { false, false };
    CameraPose rig_;
    Eigen::Matrix3d F_; //!< Of the rig: x_right^T F x_left = 0.
    TrackStore store_;
    std::vector<StereoFrame> stereo_;
    //! The left features of the last frames, for linking the next ones (at most maxFrameGap).
    std::deque<std::pair<int, FrameFeatures>> recent_;
    //! The left features of the last keyframes (at most window), linked to past a longer gap.
    std::deque<std::pair<int, FrameFeatures>> keyframeFeatures_;
    //! Every keyframe's left features and their retrieval sample, for finding its place again.
    std::map<int, FrameFeatures> placeFeatures_;
    KeyframeRetrieval retrieval_;
    //! The tracks of the caller's ids (addObservations()), and which kind of input the tracker takes.
    std::map<int64_t, int> pointIdTrack_, lineIdTrack_;
    bool byFeatures_ = false, byIds_ = false;
    int lostRun_ = 0;            //!< Frames lost in a row up to the newest.
    int numMaps_ = 1;            //!< Maps begun, the first included.
    std::set<int> liveMaps_{ 0 }; //!< Maps that hold frames (not joined into another).
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_STEREO_TRACKER_HPP
