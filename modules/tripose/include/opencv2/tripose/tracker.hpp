// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TRACKER_HPP
#define OPENCV_TRIPOSE_TRACKER_HPP

#include <string>
#include <vector>

#include "opencv2/core.hpp"
#include "opencv2/tripose/features.hpp"
#include "opencv2/tripose/params.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

//! Parameters of Tracker.
struct CV_EXPORTS TrackerParams
{
    TrackerParams();
    int window; //!< Keyframes a new frame is registered against (default 5, at least 2).
    //! A frame is registered only when at least this many features agree with its pose (default 15):
    //! chance matches give poses with a handful of inliers.
    int minInliers;
    /** A registered frame becomes a keyframe, one later frames are registered against, when the
    median angle its inlier structure subtends between it and the window's last keyframe is at
    least this (degrees, default 0.1; 0: every registered frame). */
    double keyframeParallaxDeg;
    /** Before a registration, the window's observations that disagree with its poses by more than
    the RANSAC threshold are dropped; after it, the features it rejects start new tracks (default true). */
    bool checkTracks;
    //! After each registration, refine the window's registered frames and their structure against the
    //! earlier keyframes, splitting off the features matched by the tracker that disagree with the
    //! result (default true; off, frames take less time and drift more).
    bool localAdjustment;
    /** After each new keyframe, look for a place seen before among the keyframes older than the
    window (by their descriptors); when the frame registers against one, its tracks join theirs, and
    when they did not reach it yet or the frame's two poses disagree, a pose graph corrects the frames
    since (their tracked relative poses against the frame's pose through the place) and every
    registered frame is adjusted with the structure, the given frames held. A place with at most
    twice window keyframes between it and the frame, or seen within window keyframes of the last
    closed loop, is only joined;
    keyframes sharing minInliers tracks with a frame join its window (default false: it costs a
    place check per keyframe). Frames given as features only. A frame lost against the window is
    looked for among every keyframe's places whatever this says. */
    bool loopClosure;
    /** Every this many new keyframes, adjust every registered frame and the structure together, the
    given frames held, and split off the observations that disagree with the result, except those
    linked by id in addObservations() (default 0: only when a loop closes). */
    int globalAdjustmentInterval;
    bool robust; //!< Register with estimatePoseMultiViewRansac()'s estimator (default true), else the linear one.
    RansacParams ransac; //!< Of the registration; ransac.threshold is also the track checks' distance.
    MatchParams matching; //!< Of consecutive frames' features.
    //! A frame that shares too few matches with the one before for their epipolar geometry is matched
    //! to the nearest of the frames up to this many back that does (default 3).
    int maxFrameGap;
    //! Also the covariance of each registered frame's pose, TrackedFrame::covariance (default false;
    //! it costs one more refinement per frame).
    bool covariance;
};

//! What Tracker made of a frame.
enum TrackedFrameStatus
{
    FRAME_GIVEN = 0,      //!< The pose came with the frame.
    FRAME_REGISTERED = 1, //!< Registered against the window of keyframes.
    FRAME_LOST = 2,       //!< No pose: too little support (TrackedFrame::reason says which).
    //! A StereoTracker lost for longer than TrackerParams::maxFrameGap began a new map at this frame
    //! (TrackedFrame::map), placed at the last pose known until a place of an earlier map joins them.
    FRAME_RESTARTED = 3
};

//! The result of one frame.
struct CV_EXPORTS TrackedFrame
{
    int frame = -1;              //!< The frame's index, in the order given.
    int status = FRAME_LOST;     //!< A TrackedFrameStatus.
    Mat R, t;                    //!< 3x3 and 3x1 CV_64F, x_cam = R X + t; empty when lost.
    int features = 0;            //!< Features the frame shares with at least two window keyframes.
    int inliers = 0;             //!< Of them, those that agree with the pose.
    int knownViews = 0;          //!< Window keyframes registered against.
    bool keyframe = false;       //!< Later frames are registered against it.
    double milliseconds = 0;     //!< Time of matching and registration.
    //! The keyframe of a place seen before through which the frame was registered: a loop it closed
    //! or a link to an older place, or where a lost camera was found again; -1 for neither.
    int recognisedKeyframe = -1;
    //! The map the pose is in: 0 (the world of the given poses) unless a StereoTracker restarted and has
    //! not yet joined its new map to an earlier one; then the new map's poses move into the earlier one
    //! (StereoTracker::getPose() and getMap() give them as they are now).
    int map = 0;
    std::string reason;          //!< Why the frame is lost; empty otherwise.
    std::vector<int> pointTracks, lineTracks; //!< Per point and segment of the frame: its track, -1 for none.
    /** With TrackerParams::covariance, for a registered frame whose pose is determined: 6x6 CV_64F, the
    covariance of the pose for 1 px image noise, order [rotation; translation], the structure
    marginalised and the window's poses held (as estimatePoseLinePointRansac()'s); multiply it by
    noiseVariance (px^2, estimated from the inliers' residuals). Empty otherwise. */
    Mat covariance;
    double noiseVariance = 0;
};

/** @brief A monocular camera tracked frame by frame from points and line segments.

Feed it one frame at a time, as features (points and segments with descriptors, from any detector)
or as observations of tracks the caller already linked, optionally with the frame's pose. The first
two frames need their poses: they fix the world frame and the scale. Every later frame is matched to
the one before it (under their epipolar geometry, estimated from the descriptors; past a frame that
matches too poorly, to an earlier one) and registered against a window of the keyframes before it
with the multi-view estimator. A frame with too little support is lost (FRAME_LOST), never given a
wrong pose, and tracking goes on with the next frame.

Poses follow the module: x ~ K (R X + t), X in the world frame. Bad input throws cv::Exception naming
the argument.
*/
class CV_EXPORTS Tracker
{
public:
    virtual ~Tracker();

    /** @param cameraMatrix 3x3 intrinsics.
    @param distCoeffs OpenCV's distortion coefficients, or empty; the features are undistorted with them.
    @param params The tracker's parameters.
    */
    static Ptr<Tracker> create(InputArray cameraMatrix, InputArray distCoeffs = noArray(),
                               const TrackerParams& params = TrackerParams());

    /** @brief The next frame from its features.
    @param points Nx2 (or Nx1 2-channel, or a vector of Point2f/Point2d) positions in pixels.
    @param pointDescriptors N rows: CV_32F (compared by L2 distance, e.g. SIFT) or CV_8U (Hamming, e.g. ORB).
    @param segments Mx4 segments x0 y0 x1 y1 in pixels (or empty).
    @param lineDescriptors M rows, CV_32F or CV_8U (e.g. LBD).
    @param R, t The frame's pose when known (the first two frames need it), else empty.
    @param cameraMatrix This frame's intrinsics when they differ from the tracker's, else empty.
    */
    virtual TrackedFrame addFeatures(InputArray points, InputArray pointDescriptors, InputArray segments,
                                     InputArray lineDescriptors, InputArray R = noArray(), InputArray t = noArray(),
                                     InputArray cameraMatrix = noArray()) = 0;

    //! addFeatures() with the features of one image, as detected by a front end.
    TrackedFrame addFeatures(const ImageFeatures& features, InputArray R = noArray(), InputArray t = noArray(),
                             InputArray cameraMatrix = noArray())
    {
        return addFeatures(features.points, features.pointDescriptors, features.segments, features.lineDescriptors, R,
                           t, cameraMatrix);
    }

    /** @brief The next frame from observations of tracks the caller linked.
    @param points Nx2 positions; @p pointIds N integers (CV_32S), the same id naming the same feature
    in every frame. @p segments Mx4, @p lineIds M integers. The other parameters as addFeatures().
    */
    virtual TrackedFrame addObservations(InputArray points, InputArray pointIds, InputArray segments,
                                         InputArray lineIds, InputArray R = noArray(), InputArray t = noArray(),
                                         InputArray cameraMatrix = noArray()) = 0;

    //! Frames given so far.
    virtual int numFrames() const = 0;

    /** The current pose of frame @p frame (a local adjustment may have moved it since its result);
    false, outputs untouched, when the frame is lost. */
    virtual bool getPose(int frame, OutputArray R, OutputArray t) const = 0;

    /** The current track of each point and segment of frame @p frame (CV_32S columns, -1: in no
    track). A frame's features join tracks as later frames are matched to it, and a registration
    that rejects a feature moves it to a track of its own. */
    virtual void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks) const = 0;

    /** How far the points of the first two frames agree with their given poses, judged without them:
    (points matched by descriptor alone, of them lying within the epipolar distance of their
    epipolar lines). A small share of many matches says that the images are not in the poses' order
    or the calibration is not theirs (doc/usage.md gives the samples' rule). (0, 0) before frame 1,
    or from observations. */
    virtual Vec2i givenPairAgreement() const = 0;
};

/** @brief A calibrated stereo rig tracked frame by frame from points and line segments.

Feed it one stereo frame at a time: the features of the left and the right image (points and
segments with descriptors, from any detector), optionally with the left camera's pose. No pose is
needed: the first frame's left camera is the world's origin (FRAME_GIVEN) unless it comes with a
pose, and the rig's baseline gives every pose its metric scale.

Each frame's left and right features are matched under the rig's epipolar geometry (a segment
within MatchParams::minEpipolarAngleDeg of the epipolar lines, horizontal ones for a side-by-side
rig, is not matched); its left features are linked to the left features of the frame before (as
Tracker links frames, looking back up to TrackerParams::maxFrameGap frames, then over the last
TrackerParams::window keyframes, so that a longer run of lost frames does not end tracking); then
it is registered
with the stereo-rig estimator (estimatePoseLinePointStereoRansac()'s; its linear solver with
TrackerParams::robust off) against the stereo pair of a keyframe, on the features that both
cameras of the keyframe and the frame's left camera see (and its right camera, where matched), and
composed with the keyframe's pose. The keyframe is the newest of the last TrackerParams::window
keyframes that gives a pose with at least TrackerParams::minInliers inliers; a frame that none does
is lost (FRAME_LOST, TrackedFrame::reason says why), never given a wrong pose, and tracking goes on
with the next frame. A registered frame becomes a keyframe when its inlier structure subtends at
least TrackerParams::keyframeParallaxDeg between it and the keyframe (a rig standing still adds
none), or when the keyframe's stereo pair sees too few of its own stereo matches (a rig
turning on the spot adds them before its view leaves the keyframe's). TrackerParams::localAdjustment
is not used. TrackedFrame::features counts the features the frame shares with its keyframe's
stereo pair (with the newest keyframe's when lost), and TrackedFrame::knownViews is 1 (one stereo
keyframe) for a registered frame.

A frame that no window keyframe registers is looked for among the older keyframes' places, those
whose descriptors look most like its own (TrackedFrame::recognisedKeyframe). A rig lost for more than
TrackerParams::maxFrameGap frames in a row, at a place no keyframe shows, starts again: the next
frame with twice TrackerParams::minInliers stereo matches, against whose stereo pair the frame before
it registers, begins a new map (FRAME_RESTARTED,
TrackedFrame::map), placed at the last pose known, and the frames after it are tracked in that map.
When a later keyframe recognises a place of an earlier map, the two maps are joined: the newer map's
poses move by one rigid motion into the earlier one.

Poses follow the module: a frame's pose is its left camera's, x ~ K_left (R X + t), X in the world
frame; the right camera is at the rig composed with it. Bad input throws cv::Exception naming the
argument.
*/
class CV_EXPORTS StereoTracker
{
public:
    virtual ~StereoTracker();

    /** @param leftCameraMatrix, rightCameraMatrix 3x3 intrinsics of the two cameras.
    @param leftDist, rightDist their distortion coefficients (OpenCV's model), or empty; the features
    are undistorted with them.
    @param R, t The rig: the right camera's pose relative to the left (x_right = R x_left + t; R 3x3 or
    a rotation vector), t non-zero, in the units the poses are wanted in.
    @param params The tracker's parameters (those of Tracker).
    */
    static Ptr<StereoTracker> create(InputArray leftCameraMatrix, InputArray leftDist, InputArray rightCameraMatrix,
                                     InputArray rightDist, InputArray R, InputArray t,
                                     const TrackerParams& params = TrackerParams());

    /** @brief The next stereo frame from the features of its two images.
    @param left, right The features of the left and the right image (descriptors of one kind and
    length in both, and in every frame).
    @param R, t The left camera's pose when known, else empty.
    */
    virtual TrackedFrame addFrame(const ImageFeatures& left, const ImageFeatures& right, InputArray R = noArray(),
                                  InputArray t = noArray()) = 0;

    /** @brief The next stereo frame from observations of tracks the caller linked (a video's points
    followed by optical flow): no descriptors and no matching, so no place is recognised, and a rig
    lost for longer than TrackerParams::maxFrameGap restarts without joining its maps. A tracker
    takes either features (addFrame()) or observations, not both.
    @param points Nx2 positions in the left image; @p pointIds N integers (CV_32S), the same id naming
    the same feature in every frame.
    @param rightPoints Nx2: each point's position in the right image, NaN where the right camera does
    not see it.
    @param segments Mx4 segments in the left image (or empty); @p lineIds M integers.
    @param rightSegments Mx4: each segment's line in the right image (any two points on it), NaN
    where the right camera does not see it.
    @param R, t The left camera's pose when known, else empty.
    */
    virtual TrackedFrame addObservations(InputArray points, InputArray pointIds, InputArray rightPoints,
                                         InputArray segments, InputArray lineIds, InputArray rightSegments,
                                         InputArray R = noArray(), InputArray t = noArray()) = 0;

    //! Frames given so far.
    virtual int numFrames() const = 0;

    //! The pose of frame @p frame's left camera; false, outputs untouched, when the frame is lost.
    virtual bool getPose(int frame, OutputArray R, OutputArray t) const = 0;

    //! The map frame @p frame's pose is in now (TrackedFrame::map, maps joined since included); -1 when lost.
    virtual int getMap(int frame) const = 0;

    /** The track of each point and segment of frame @p frame's left image (CV_32S columns, -1: in
    no track), and the row of each one's stereo match in the right image (-1: none). */
    virtual void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks,
                           OutputArray pointStereoMatches = noArray(),
                           OutputArray lineStereoMatches = noArray()) const = 0;
};

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_TRACKER_HPP
