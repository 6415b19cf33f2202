// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"


#include "core/tracking/tracker.hpp"
#include "opencv/core_calls.hpp"
#include "opencv/feature_reading.hpp"
#include "opencv/opencv_compat.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/tracker_conversion.hpp"

namespace cv {
namespace tripose {

TrackerParams::TrackerParams()
{
    const detail::core::TrackerOptions defaults;
    window = defaults.window;
    minInliers = defaults.minInliers;
    keyframeParallaxDeg = defaults.keyframeParallaxDeg;
    checkTracks = defaults.checkTracks;
    localAdjustment = defaults.localAdjustment;
    loopClosure = defaults.loopClosure;
    globalAdjustmentInterval = defaults.globalAdjustmentInterval;
    robust = defaults.robust;
    maxFrameGap = defaults.maxFrameGap;
    covariance = defaults.covariance;
}

Tracker::~Tracker() {}

namespace {

namespace core = detail::core;

//! The optional pose and camera matrix of a frame.
struct FrameExtras
{
    bool hasPose = false, hasK = false;
    core::CameraPose pose;
    Eigen::Matrix3d K;

    FrameExtras(InputArray R, InputArray t, InputArray cameraMatrix)
    {
        hasPose = detail::readFramePose(R, t, pose);
        if (!cameraMatrix.empty())
        {
            K = detail::readMatrix3(cameraMatrix, "cameraMatrix");
            hasK = true;
        }
    }
    const core::CameraPose* posePtr() const { return hasPose ? &pose : nullptr; }
    const Eigen::Matrix3d* KPtr() const { return hasK ? &K : nullptr; }
};

using detail::toTrackedFrame;

class TrackerImpl : public Tracker
{
public:
    TrackerImpl(InputArray cameraMatrix, InputArray distCoeffs, const TrackerParams& params)
        : tracker_(TRIPOSE_CALL_CORE([&] {
              return core::Tracker(detail::readMatrix3(cameraMatrix, "cameraMatrix"), detail::readDistortion(distCoeffs),
                                   detail::toCoreOptions(params));
          }))
    {
    }

    TrackedFrame addFeatures(InputArray points, InputArray pointDescriptors, InputArray segments,
                             InputArray lineDescriptors, InputArray R, InputArray t, InputArray cameraMatrix) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const core::FrameFeatures f = detail::readFrameFeatures(points, pointDescriptors, segments, lineDescriptors);
        const FrameExtras extras(R, t, cameraMatrix);
        return toTrackedFrame(
            TRIPOSE_CALL_CORE([&] { return tracker_.addFeatures(f, extras.posePtr(), extras.KPtr()); }));
    }

    TrackedFrame addObservations(InputArray points, InputArray pointIds, InputArray segments, InputArray lineIds,
                                 InputArray R, InputArray t, InputArray cameraMatrix) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const std::vector<Eigen::Vector2d> p = detail::vectors<2>(detail::readRows(points, 2, "points"));
        const std::vector<Eigen::Vector4d> s = detail::vectors<4>(detail::readRows(segments, 4, "segments"));
        const std::vector<int64_t> pi = detail::readIds(pointIds, (int)p.size(), "pointIds");
        const std::vector<int64_t> li = detail::readIds(lineIds, (int)s.size(), "lineIds");
        const FrameExtras extras(R, t, cameraMatrix);
        return toTrackedFrame(
            TRIPOSE_CALL_CORE([&] { return tracker_.addObservations(p, pi, s, li, extras.posePtr(), extras.KPtr()); }));
    }

    int numFrames() const CV_OVERRIDE { return tracker_.numFrames(); }

    bool getPose(int frame, OutputArray R, OutputArray t) const CV_OVERRIDE
    {
        detail::checkFrameIndex(frame, tracker_.numFrames());
        return detail::writeFramePose(tracker_.frame(frame), R, t);
    }

    void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks) const CV_OVERRIDE
    {
        detail::checkFrameIndex(frame, tracker_.numFrames());
        const core::StoredFrame& f = tracker_.frame(frame);
        Mat(f.pointTrack, true).copyTo(pointTracks);
        Mat(f.lineTrack, true).copyTo(lineTracks);
    }

    Vec2i givenPairAgreement() const CV_OVERRIDE
    {
        return Vec2i(tracker_.givenPairAgreement().matches, tracker_.givenPairAgreement().agreeing);
    }

private:
    core::Tracker tracker_;
};

} // namespace

Ptr<Tracker> Tracker::create(InputArray cameraMatrix, InputArray distCoeffs, const TrackerParams& params)
{
    CV_INSTRUMENT_REGION();
    return makePtr<TrackerImpl>(cameraMatrix, distCoeffs, params);
}

} // namespace tripose
} // namespace cv
