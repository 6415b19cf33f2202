// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_TRACKER_HPP
#define TRIPOSE_CORE_TRACKING_TRACKER_HPP

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "../geometry/distortion.hpp"
#include "bundle_adjustment.hpp"
#include "frame_features.hpp"
#include "frame_matching.hpp"
#include "keyframe_retrieval.hpp"
#include "track_store.hpp"
#include "tracker_options.hpp"
#include "window_registration.hpp"

namespace tripose {

/** A monocular camera tracked frame by frame. Each frame is given as features (positions in the
image's pixels, descriptors) or as observations of tracks the caller already linked, optionally with
its pose. The first two frames need poses: they fix the world frame and the scale. Every later frame
without a pose is matched to the frame before it (under their epipolar geometry, estimated from the
descriptors) and registered against a window of the keyframes before it.

Poses follow the library: x_cam = R X + t, X in the world frame.
*/
class Tracker
{
public:
    /** @p K the camera matrix, @p distortion its coefficients in OpenCV's model (empty: none); the
    features given are undistorted with them. Throws Error naming "K", "dist" or "options". */
    Tracker(const Eigen::Matrix3d& K, const std::vector<double>& distortion, const TrackerOptions& options);

    /** The next frame from its features. @p pose, when given, is the frame's pose (status Given).
    @p K, when given, replaces the tracker's camera matrix for this frame. */
    FrameResult addFeatures(const FrameFeatures& features, const CameraPose* pose = nullptr,
                            const Eigen::Matrix3d* K = nullptr);

    /** The next frame from observations of tracks the caller linked: point @p i at @p points[i] is
    feature @p pointIds[i] of the caller's, and the same for segments; a caller's id names the same
    feature in every frame. */
    FrameResult addObservations(const std::vector<Eigen::Vector2d>& points, const std::vector<int64_t>& pointIds,
                                const std::vector<Eigen::Vector4d>& segments, const std::vector<int64_t>& lineIds,
                                const CameraPose* pose = nullptr, const Eigen::Matrix3d* K = nullptr);

    int numFrames() const { return (int)store_.frames.size(); }
    //! Frame @p frame's current pose (a local adjustment may have moved it since its result) and status.
    const StoredFrame& frame(int frame) const { return store_.frames.at(frame); }
    const TrackerOptions& options() const { return options_; }
    /** How far the points of the first two frames agree with their given poses, judged from their
    descriptors alone: a contradiction means images out of the poses' order or a wrong calibration.
    Zero matches before frame 1 or without descriptors. */
    const EpipolarAgreement& givenPairAgreement() const { return givenPairAgreement_; }

private:
    int startFrame(const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector4d>& segments,
                   const CameraPose* pose, const Eigen::Matrix3d* K);
    FrameResult finishFrame(int frame, double startSeconds, const FrameFeatures* features);
    /** Registers frame @p frame against the window of the latest keyframes (and, with loop closure,
    the older keyframes that share its tracks), or, that failing and with @p features, against the
    place of any keyframe it sees; @p oldestRecent receives the oldest of the latest keyframes. */
    void registerFrame(int frame, const FrameFeatures* features, FrameResult& result, int& oldestRecent);
    /** Keeps keyframe @p frame's features for recognising its place, first checking, with loop
    closure, whether it sees a place of the keyframes older than @p oldestRecent (a loop when its
    pose through the place disagrees with its tracked pose). True when it closed a loop. */
    bool keepKeyframe(int frame, const FrameFeatures& features, int oldestRecent, FrameResult& result);
    /** Registers the frame against the best of the keyframes for which @p eligible holds, as retrieved
    by descriptors, and their neighbours (registerAgainstPlace()); @p keyframe the one that did. */
    Registration recognisePlace(int frame, const FrameFeatures& features, const std::function<bool(int)>& eligible,
                                int minInliers, int& keyframe);
    /** Moves the frames after @p keyframe towards the frame's pose @p loopPose through the place it
    recognised, by a share of the correction growing along them, then adjusts them (the loop's
    frames), the frames up to the keyframe held. */
    void closeLoop(int frame, int keyframe, const CameraPose& loopPose);
    //! The registered frames after frame @p first and the structure adjusted together, the given
    //! frames and the frames up to @p first held (-1: every registered frame).
    void adjustFramesAfter(int first);
    //! Frames @p free and their structure adjusted against @p fixed (adjustAndSplitOutliers()),
    //! splitting off the matched links the result contradicts, never the caller's.
    void adjust(const std::vector<int>& free, const std::vector<int>& fixed);
    //! Who linked the tracks' observations: the caller (observations by id) or the matching.
    TrackLinks links() const { return byIds_ ? TrackLinks::ByCaller : TrackLinks::Matched; }
    void associateByMatching(int frame, const FrameFeatures& features);
    void link(FeatureKind kind, int from, int to, const Matches& matches);

    TrackerOptions options_;
    Eigen::Matrix3d K_;
    Distortion distortion_;
    bool distorted_ = false;
    TrackStore store_;
    //! The features of the last frames, for matching the next ones (at most maxFrameGap).
    std::deque<std::pair<int, FrameFeatures>> recent_;
    //! The caller's feature ids and the tracks they continue.
    std::map<int64_t, int> pointIdTrack_, lineIdTrack_;
    std::vector<std::vector<int64_t>> pointIdsOfFrame_, lineIdsOfFrame_;
    bool byIds_ = false, byFeatures_ = false;
    EpipolarAgreement givenPairAgreement_;
    //! The keyframes' features, for recognising their places.
    KeyframeRetrieval retrieval_;
    std::map<int, FrameFeatures> keyframeFeatures_;
    int keyframesSinceAdjustment_ = 0;
    int lastLoopFrame_ = -1; //!< The frame that closed the last loop (-1: none yet).
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_TRACKER_HPP
