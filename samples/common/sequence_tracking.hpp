// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Tracking a camera along a sequence with cv::tripose::estimatePoseMultiView*: the first two frames
// have given poses (they fix the world frame and the scale); every later frame is registered
// against a sliding window of the keyframes before it (frames with a pose and parallax) that see its
// features.

#ifndef TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP
#define TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP

#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

namespace tripose_samples {

//! A sequence's observations: per frame, the same N points (Nx2) and M segments (Mx4), NaN rows where
//! the frame does not see the feature; per frame K; the given poses of frames 0 and 1.
struct SequenceObservations
{
    std::vector<cv::Mat> cameraMatrices, points, lines;
    cv::Mat R0, t0, R1, t1;
};

struct TrackOptions
{
    int window = 5;                      //!< Keyframes a new frame is registered against (>= 2).
    bool robust = true;                  //!< estimatePoseMultiViewRansac (else the linear estimate alone).
    cv::tripose::RansacParams ransac;    //!< With robust: threshold, refinement, seed.
    /** Local adjustment after each registration: the registered frames of the window, the new one
    included, and the structure refined together (adjustPosesMultiView, Huber loss at the RANSAC
    threshold) against every earlier keyframe, held fixed (frames 0 and 1 among them). */
    bool localAdjustment = false;
    /** Track checks with robust registration, at the RANSAC threshold: before a frame is registered, each feature's
    observations in the window are measured against the window's poses (triangulateMultiView()) and
    the furthest dropped while it is off by more than the threshold (a feature left in fewer than two
    window frames is not used); after it is registered, its observations of the
    features the registration rejected start new tracks, so that a wrong link does not carry on into
    the next frames' windows. */
    bool checkTracks = true;
    /** A frame is registered only when at least this many features agree with its pose (robust: its
    inliers; linear: its features), else it is lost. The estimators return a pose with one feature
    more than a minimal sample, and chance matches reach that: an image of noise inside a sequence
    was registered with 5 inliers of 7 features, and random features gave poses with up to 7
    inliers (doc/conventions.md). The least support of a true frame over the VGG sequences is 51
    (Model House's own correspondences, window 2). */
    int minInliers = 15;
    /** A registered frame becomes a keyframe, one that later frames are registered against, when
    the median angle its inlier structure subtends between it and the last keyframe of its window is
    at least this (degrees; 0: every registered frame). A camera that stands still adds views
    without a baseline: a window of them registers the next frame as from one view (Merton College I
    with its second image repeated four times: the third image, registered next, off by 33 % of the
    path). The consecutive frames of the VGG sequences are 0.51 deg apart at the least (Corridor,
    moving forward), the others' 5.7 deg, so all their frames are keyframes. */
    double keyframeParallaxDeg = 0.1;
};

enum FrameStatus
{
    FRAME_GIVEN = 0,      //!< Frames 0 and 1: the pose came with the sequence.
    FRAME_REGISTERED = 1, //!< Registered against the window.
    FRAME_LOST = 2,       //!< Too few features shared with the window, no pose found, or one with too
                          //!< few inliers (TrackOptions::minInliers): no pose.
};

struct TrackedFrame
{
    FrameStatus status = FRAME_LOST;
    cv::Mat R, t;           //!< 3x3, 3x1 CV_64F; empty when lost.
    int features = 0;       //!< Features seen by the frame and at least two window frames.
    int inliers = 0;        //!< Robust: inlier features; linear: every feature.
    int knownViews = 0;     //!< Window frames used.
    //! Later frames are registered against it: frames 0 and 1, and registered frames with enough
    //! parallax (TrackOptions::keyframeParallaxDeg).
    bool keyframe = false;
    double milliseconds = 0; //!< Time of the registration (selection of features included).
};

/** Registration data of frame @p frame against the frames @p known (which must have poses): the
features it sees with at least two of them, as estimatePoseMultiView() takes them (one array per
known frame, then the frame's own; their K and poses). False when they are fewer than four.
*/
bool registrationViews(const SequenceObservations& sequence, const std::vector<TrackedFrame>& frames, int frame,
                       const std::vector<int>& known, std::vector<cv::Mat>& points, std::vector<cv::Mat>& lines,
                       std::vector<cv::Mat>& cameraMatrices, std::vector<cv::Mat>& Rs, std::vector<cv::Mat>& ts,
                       int& features);

/** Refines frames @p free and the structure together (adjustPosesMultiView) with frames @p fixed held,
on the features seen by at least two of these frames, one of them free. Returns the RMS error (px);
+inf, frames unchanged, when the refinement fails or fewer than four features qualify.
@p fixed must hold two frames at distinct centres.
*/
double adjustFrames(const SequenceObservations& sequence, std::vector<TrackedFrame>& frames,
                    const std::vector<int>& free, const std::vector<int>& fixed, const cv::tripose::RefineParams& params);

/** Tracks the whole sequence. A lost frame gets no pose and is left out of later windows: the window
holds the last @p options.window frames that have a pose, so tracking resumes as soon as a frame
shares four features with them. Frames 0 and 1 are given. With TrackOptions::checkTracks the tracks
of @p sequence are split where a registration rejects them (rows appended to every frame).
@throws cv::Exception when the observations are inconsistent (from the module, naming the argument).
*/
std::vector<TrackedFrame> trackSequence(SequenceObservations& sequence, const TrackOptions& options);

//! The top-level keys of tripose_track's result file (poses: one row per frame, R row-major then t),
//! which tools that read the file back check its keys against.
std::vector<std::string> trackResultKeys();

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP
