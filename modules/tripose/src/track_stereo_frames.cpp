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

//! The right image's rows of @p count features (NaN rows: not seen); cv::Exception naming @p name otherwise.
Mat readRightRows(InputArray array, int width, size_t count, const char* name)
{
    const Mat rows = detail::readRows(array, width, name);
    if ((size_t)rows.rows != count)
        CV_Error_(Error::StsBadSize, ("%s must hold one row per feature of the left image (%d; NaN: not seen), "
                                      "got %d", name, (int)count, rows.rows));
    return rows;
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

    TrackedFrame addObservations(InputArray points, InputArray pointIds, InputArray rightPoints, InputArray segments,
                                 InputArray lineIds, InputArray rightSegments, InputArray R, InputArray t) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        core::StereoObservations o;
        o.points = detail::vectors<2>(detail::readRows(points, 2, "points"));
        o.segments = detail::vectors<4>(detail::readRows(segments, 4, "segments"));
        o.pointIds = detail::readIds(pointIds, (int)o.points.size(), "pointIds");
        o.lineIds = detail::readIds(lineIds, (int)o.segments.size(), "lineIds");
        o.rightPoints = detail::vectors<2>(readRightRows(rightPoints, 2, o.points.size(), "rightPoints"));
        o.rightSegments = detail::vectors<4>(readRightRows(rightSegments, 4, o.segments.size(), "rightSegments"));
        core::CameraPose pose;
        const bool hasPose = detail::readFramePose(R, t, pose);
        return detail::toTrackedFrame(
            TRIPOSE_CALL_CORE([&] { return tracker_.addObservations(o, hasPose ? &pose : nullptr); }));
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
