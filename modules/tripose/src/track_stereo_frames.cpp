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

std::vector<double> readDistortion(InputArray array)
{
    std::vector<double> out;
    if (!array.empty())
    {
        Mat d;
        array.getMat().convertTo(d, CV_64F);
        d = d.isContinuous() ? d : d.clone();
        out.assign(d.ptr<double>(), d.ptr<double>() + d.total());
    }
    return out;
}

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
              return core::StereoTracker(KLeft, readDistortion(leftDist), KRight, readDistortion(rightDist),
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
        checkFrame(frame);
        const core::StoredFrame& f = tracker_.frame(frame);
        if (!f.hasPose())
            return false;
        detail::matOf(f.pose.R).copyTo(R);
        detail::matOf(f.pose.t).copyTo(t);
        return true;
    }

    void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks, OutputArray pointStereoMatches,
                   OutputArray lineStereoMatches) const CV_OVERRIDE
    {
        checkFrame(frame);
        const core::StoredFrame& f = tracker_.frame(frame);
        Mat(f.pointTrack, true).copyTo(pointTracks);
        Mat(f.lineTrack, true).copyTo(lineTracks);
        if (pointStereoMatches.needed())
            Mat(tracker_.stereoPoints(frame), true).copyTo(pointStereoMatches);
        if (lineStereoMatches.needed())
            Mat(tracker_.stereoSegments(frame), true).copyTo(lineStereoMatches);
    }

private:
    void checkFrame(int frame) const
    {
        if (frame < 0 || frame >= tracker_.numFrames())
            CV_Error_(Error::StsOutOfRange, ("frame %d is not one of the %d frames tracked", frame, tracker_.numFrames()));
    }

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
