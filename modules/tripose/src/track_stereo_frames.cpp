// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/tracking/stereo_tracker.hpp"
#include "opencv/core_calls.hpp"
#include "opencv/feature_reading.hpp"
#include "opencv/opencv_compat.hpp"
#include "opencv/tracker_conversion.hpp"

namespace cv {
namespace tripose {

StereoTracker::~StereoTracker() {}

namespace {

namespace core = detail::core;

//! The rig from R (3x3 or a rotation vector) and t (3 elements), both required.
core::CameraPose readRig(InputArray R, InputArray t)
{
    if (R.empty() || t.empty())
        CV_Error(Error::StsBadArg, "R and t (the rig: the right camera's pose relative to the left) are required");
    core::CameraPose rig;
    detail::readFramePose(R, t, rig);
    return rig;
}

class StereoTrackerImpl : public StereoTracker
{
public:
    StereoTrackerImpl(InputArray leftCameraMatrix, InputArray leftDist, InputArray rightCameraMatrix,
                      InputArray rightDist, InputArray R, InputArray t, const TrackerParams& params)
        : tracker_(TRIPOSE_CALL_CORE([&] {
              const Eigen::Matrix3d KLeft = detail::readMatrix3(leftCameraMatrix, "leftCameraMatrix");
              const Eigen::Matrix3d KRight = detail::readMatrix3(rightCameraMatrix, "rightCameraMatrix");
              return core::StereoTracker(KLeft, detail::readDistortion(leftDist), KRight, detail::readDistortion(rightDist),
                                         readRig(R, t), detail::toCoreOptions(params));
          }))
    {
    }

    TrackedFrame addFrame(const ImageFeatures& left, const ImageFeatures& right, InputArray R,
                          InputArray t) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const core::FrameFeatures l = detail::readFrameFeatures(left, "left");
        const core::FrameFeatures r = detail::readFrameFeatures(right, "right");
        core::CameraPose pose;
        const bool hasPose = detail::readFramePose(R, t, pose);
        return detail::toTrackedFrame(
            TRIPOSE_CALL_CORE([&] { return tracker_.addFrame(l, r, hasPose ? &pose : nullptr); }));
    }

    int numFrames() const CV_OVERRIDE { return tracker_.numFrames(); }

    bool getPose(int frame, OutputArray R, OutputArray t) const CV_OVERRIDE
    {
        detail::checkFrameIndex(frame, tracker_.numFrames());
        return detail::writeFramePose(tracker_.frame(frame), R, t);
    }

    int getMap(int frame) const CV_OVERRIDE
    {
        detail::checkFrameIndex(frame, tracker_.numFrames());
        const core::StoredFrame& f = tracker_.frame(frame);
        return f.hasPose() ? f.map : -1;
    }

    void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks, OutputArray pointStereoMatches,
                   OutputArray lineStereoMatches) const CV_OVERRIDE
    {
        detail::checkFrameIndex(frame, tracker_.numFrames());
        const core::StoredFrame& f = tracker_.frame(frame);
        Mat(f.pointTrack, true).copyTo(pointTracks);
        Mat(f.lineTrack, true).copyTo(lineTracks);
        if (pointStereoMatches.needed())
            Mat(tracker_.stereoPoints(frame), true).copyTo(pointStereoMatches);
        if (lineStereoMatches.needed())
            Mat(tracker_.stereoSegments(frame), true).copyTo(lineStereoMatches);
    }

private:
    core::StereoTracker tracker_;
};

} // namespace

Ptr<StereoTracker> StereoTracker::create(InputArray leftCameraMatrix, InputArray leftDist,
                                         InputArray rightCameraMatrix, InputArray rightDist, InputArray R,
                                         InputArray t, const TrackerParams& params)
{
    CV_INSTRUMENT_REGION();
    return makePtr<StereoTrackerImpl>(leftCameraMatrix, leftDist, rightCameraMatrix, rightDist, R, t, params);
}

} // namespace tripose
} // namespace cv
