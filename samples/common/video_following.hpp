// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The video mode's front end: points (and optionally segments) of a video followed from frame to
// frame by pyramidal Lucas-Kanade optical flow, each keeping its id, and detected afresh only where
// the tracker asks, for cv::tripose::Tracker::addObservations() and
// cv::tripose::StereoTracker::addObservations(). python/tripose/video.py is its Python twin.

#ifndef TRIPOSE_SAMPLES_VIDEO_FOLLOWING_HPP
#define TRIPOSE_SAMPLES_VIDEO_FOLLOWING_HPP

#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

//! How a VideoFrontEnd follows and renews its features (the defaults of python/tripose/video.py).
struct FollowOptions
{
    int maxPoints = 200;         //!< Points followed at most; a detection tops the followed ones up to it.
    int minPoints = 120;         //!< Fewer followed points than this start a detection in the next frame.
    double minDistance = 10;     //!< px between detected points, and from a new point to any followed one.
    double qualityLevel = 0.01;  //!< goodFeaturesToTrack's corner quality, relative to the strongest corner.
    int windowSize = 15;         //!< The Lucas-Kanade window's side (px, odd).
    int pyramidLevels = 3;       //!< Pyramid levels above the image the flow is searched in.
    double maxFlowError = 1;     //!< px between a point and its position followed forward and back; farther: lost.
    bool segments = false;       //!< Also detect EDLines segments and follow their end points.
    int maxSegments = 100;       //!< The longest segments kept at a detection.
    double minSegmentLength = 30; //!< Shorter segments are neither detected nor kept (px).
    double maxLengthChange = 0.2; //!< A segment whose length changes by more than this fraction is dropped.
};

//! A stereo rig as VideoFrontEnd finds the left camera's features in the right image.
struct VideoRig
{
    cv::Matx33d K[2];
    cv::Mat dist[2];  //!< Either may be empty.
    cv::Matx33d R;    //!< The right camera's pose relative to the left: x_right = R x_left + t.
    cv::Vec3d t;
};

//! One frame's observations, as the trackers' addObservations() take them (CV_64F rows, CV_32S ids).
struct VideoObservations
{
    cv::Mat points, pointIds, segments, lineIds;
    //! With a rig: per point (segment) its position in the right image, NaN where it is not found.
    cv::Mat rightPoints, rightSegments;
    bool detected = false; //!< New features were looked for in this frame.
};

//! Milliseconds spent in each stage, summed over the frames.
struct VideoStageTimes
{
    double flow = 0, detection = 0, stereo = 0;
};

/** Follows a video's features from frame to frame. Each next() moves the followed points and
segment ends into the new image (a point is kept when the flow back returns within
FollowOptions::maxFlowError px of where it was; a segment when both its ends are kept and its length
changes by at most FollowOptions::maxLengthChange), then, in the frame after a keyframe (keyframeDone())
or when fewer than FollowOptions::minPoints points survive, detects new points (goodFeaturesToTrack,
FollowOptions::minDistance away from the followed ones) and segments, each with a new id. With a rig,
each left feature is looked for in the right image by the same flow there and back, and kept when it
lies within 2 px of its epipolar line. */
class VideoFrontEnd
{
public:
    explicit VideoFrontEnd(const FollowOptions& options = FollowOptions());
    VideoFrontEnd(const FollowOptions& options, const VideoRig& rig);

    /** The next frame's observations from its 8-bit left image (grey or BGR) and, with a rig, its
    right image; an empty left image (not read) gives none and the features are followed on into the
    next image; an empty right image gives NaN right positions. Throws std::runtime_error when an
    image's size differs from the first's. */
    VideoObservations next(const cv::Mat& left, const cv::Mat& right = cv::Mat());

    /** Whether the tracker made the frame just given a keyframe (call it after each frame): the next
    image is then detected afresh. A frame whose image was not read leaves that as it was. */
    void keyframeDone(bool keyframe);

    const VideoStageTimes& times() const { return times_; }

private:
    void follow(const cv::Mat& grey);
    void detect(const cv::Mat& grey);
    cv::Mat inRight(const cv::Mat& grey, const cv::Mat& right, const std::vector<cv::Point2f>& pixels) const;

    FollowOptions options_;
    bool stereo_ = false;
    VideoRig rig_;
    cv::Matx33d fundamental_;
    cv::Mat previous_;
    std::vector<cv::Point2f> points_;
    std::vector<int> pointIds_;
    std::vector<cv::Vec4f> segments_;
    std::vector<int> lineIds_;
    int nextId_ = 0;
    bool renew_ = true;
    bool read_ = false; //!< Whether the last frame's image was read.
    VideoStageTimes times_;
};

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_VIDEO_FOLLOWING_HPP
