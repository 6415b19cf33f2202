// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_TRACKER_OPTIONS_HPP
#define TRIPOSE_CORE_TRACKING_TRACKER_OPTIONS_HPP

#include <string>

#include <Eigen/Core>
#include <vector>

#include "../geometry/camera.hpp"
#include "../support/options.hpp"
#include "epipolar_matching.hpp"

namespace tripose {

//! Options of the Tracker; every adapter binds these fields under its own names.
struct TrackerOptions
{
    int window = 5;     //!< Keyframes a new frame is registered against (>= 2).
    //! A frame is registered only when at least this many features agree with its pose: chance
    //! matches give poses with a handful of inliers (doc/conventions.md, "Support"). It replaces
    //! ransac.minInliers in the registration.
    int minInliers = 15;
    //! A registered frame becomes a keyframe when the median angle its inlier structure subtends
    //! between it and the window's last keyframe is at least this (deg; 0: every registered frame):
    //! a camera that stands still or only turns adds no baseline.
    double keyframeParallaxDeg = 0.1;
    //! Before a registration, observations of the window that disagree with the window's poses by
    //! more than the RANSAC threshold are dropped; after it, the features it rejects start new
    //! tracks, so that a wrong link does not carry on into later windows.
    bool checkTracks = true;
    //! After each registration, the window's registered frames, the new one and their structure are
    //! refined together (Cauchy loss at a quarter of the RANSAC threshold) against the earlier
    //! keyframes, held fixed; the observations that disagree with the result leave their tracks and
    //! the refinement is run again (at most three rounds), as in the global adjustment; observations
    //! the caller linked by id are not split here (only by the registration).
    bool localAdjustment = true;
    /** After each new keyframe, the keyframes older than the window that look most like it (by
    descriptors) are tried as a place seen before: when the frame registers against one of them and
    its neighbours with twice minInliers (and half of the features shared), its tracks join theirs;
    when its pose through the place disagrees with its tracked pose (a loop), a pose graph moves the
    frames since (their tracked relative poses against the frame's pose through the place) and every
    registered frame is adjusted with the structure (given frames held); a place with at most
    2 window keyframes between it and the frame, or seen within window keyframes of the last closed
    loop, is only joined (mayCloseLoop()). Keyframes that share minInliers tracks with a frame then
    join its window. It costs a place check per keyframe (doc/studies/front_end_and_tracker.md),
    hence off by default. Needs descriptors (frames given as features). */
    bool loopClosure = false;
    /** Every this many new keyframes, every registered frame and the structure are adjusted
    together with the given frames held, and the observations that disagree with the result leave
    their tracks, except those the caller linked by id (0: only when a loop closes). */
    int globalAdjustmentInterval = 0;
    bool robust = true; //!< The robust multi-view estimator (else the linear one on every feature).
    RansacOptions ransac; //!< Of the registration; ransac.threshold is also the track checks' distance.
    MatchOptions matching; //!< Of the features of consecutive frames.
    //! A frame that shares too few matches with the one before for their epipolar geometry is matched
    //! to the nearest of the frames up to this many back that does.
    int maxFrameGap = 3;
    //! Also the covariance of each registered frame's pose (one more refinement over its inliers,
    //! with the window's poses held): FrameResult::covariance.
    bool covariance = false;
};

//! Checks @p options: Error(BadArgument) naming "<name>.<field>" for the first field out of range.
void checkMatchOptions(const MatchOptions& options, const char* name = "options");
//! Checks @p options: Error(BadArgument) naming "<name>.<field>" for the first field out of range.
void checkTrackerOptions(const TrackerOptions& options, const char* name = "options");

enum class FrameStatus
{
    Given = 0,      //!< The pose came with the frame.
    Registered = 1, //!< Registered against the window of keyframes.
    Lost = 2,       //!< No pose: too few features shared with the window, or too few agree with a pose.
    /** The stereo tracker, lost for more than TrackerOptions::maxFrameGap frames and finding no
    keyframe's place in the frame, started a new map here: the frame is that map's first keyframe,
    placed at the last pose known until a place of an earlier map joins them. */
    Restarted = 3,
};

//! What the tracker made of one frame.
struct FrameResult
{
    int frame = -1; //!< The frame's index in the order the tracker received them.
    FrameStatus status = FrameStatus::Lost;
    CameraPose pose;        //!< Meaningful unless lost.
    int features = 0;       //!< Features seen by the frame and at least two window keyframes.
    int inliers = 0;        //!< Of them, those that agree with the pose (robust); every one (linear).
    int knownViews = 0;     //!< Window keyframes registered against.
    bool keyframe = false;  //!< Later frames are registered against it.
    double milliseconds = 0; //!< Matching and registration.
    //! The keyframe of a place seen before through which the frame was registered: a loop it closed,
    //! or where a lost camera was found again; -1 for neither.
    int recognisedKeyframe = -1;
    /** The map the pose is in: 0, the world of the given poses, unless a stereo tracker restarted
    (FrameStatus::Restarted) and has not yet joined the new map to an earlier one; when it does, the
    new map's poses move into the earlier map (StereoTracker::frame() holds a frame's poses as they
    are now). */
    int map = 0;
    std::string reason;     //!< Why the frame is lost; empty otherwise.
    //! Per point and per segment of the frame, in the order given: its track (-1: matched to none).
    std::vector<int> pointTracks, lineTracks;
    /** With TrackerOptions::covariance, for a registered frame whose pose is determined: the 6x6
    covariance of its pose for 1 px image noise, order [rotation; translation], the structure
    marginalised and the window's poses held (doc/conventions.md); multiply it by noiseVariance, the
    noise variance (px^2) estimated from the inliers' residuals. */
    bool hasCovariance = false;
    Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
    double noiseVariance = 0;
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_TRACKER_OPTIONS_HPP
