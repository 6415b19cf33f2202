// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <cstring>

#include "core/tracking/tracker.hpp"
#include "opencv/core_calls.hpp"
#include "opencv/feature_reading.hpp"
#include "opencv/opencv_compat.hpp"
#include "opencv/options_conversion.hpp"

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
    robust = defaults.robust;
    maxFrameGap = defaults.maxFrameGap;
}

Tracker::~Tracker() {}

namespace {

namespace core = detail::core;

core::TrackerOptions toCoreOptions(const TrackerParams& params)
{
    core::TrackerOptions o;
    o.window = params.window;
    o.minInliers = params.minInliers;
    o.keyframeParallaxDeg = params.keyframeParallaxDeg;
    o.checkTracks = params.checkTracks;
    o.localAdjustment = params.localAdjustment;
    o.robust = params.robust;
    o.ransac = detail::toCoreOptions(params.ransac);
    o.matching = detail::toCoreOptions(params.matching);
    o.maxFrameGap = params.maxFrameGap;
    core::checkTrackerOptions(o, "params");
    return o;
}

//! The optional pose and camera matrix of a frame.
struct FrameExtras
{
    bool hasPose = false, hasK = false;
    core::CameraPose pose;
    Eigen::Matrix3d K;

    FrameExtras(InputArray R, InputArray t, InputArray cameraMatrix)
    {
        if (R.empty() != t.empty())
            CV_Error(Error::StsBadArg, "R and t must be given together (the frame's pose), or neither");
        if (!R.empty())
        {
            Mat r;
            R.getMat().convertTo(r, CV_64F);
            if (r.total() == 3)
                Rodrigues(r.reshape(1, 3), r);
            pose.R = detail::readMatrix3(r, "R");
            Mat tv = t.getMat();
            if (tv.total() != 3 || tv.channels() != 1)
                CV_Error(Error::StsBadSize, "t must hold 3 elements");
            tv.reshape(1, 3).convertTo(tv, CV_64F);
            for (int i = 0; i < 3; ++i)
                pose.t[i] = tv.at<double>(i);
            hasPose = true;
        }
        if (!cameraMatrix.empty())
        {
            K = detail::readMatrix3(cameraMatrix, "cameraMatrix");
            hasK = true;
        }
    }
    const core::CameraPose* posePtr() const { return hasPose ? &pose : nullptr; }
    const Eigen::Matrix3d* KPtr() const { return hasK ? &K : nullptr; }
};

Mat matOf(const Eigen::Matrix3d& R)
{
    Mat out(3, 3, CV_64F);
    for (int i = 0; i < 9; ++i)
        out.at<double>(i / 3, i % 3) = R(i / 3, i % 3);
    return out;
}

Mat matOf(const Eigen::Vector3d& t)
{
    return (Mat_<double>(3, 1) << t[0], t[1], t[2]);
}

TrackedFrame toTrackedFrame(const core::FrameResult& r)
{
    TrackedFrame out;
    out.frame = r.frame;
    out.status = (int)r.status;
    if (r.status != core::FrameStatus::Lost)
    {
        out.R = matOf(r.pose.R);
        out.t = matOf(r.pose.t);
    }
    out.features = r.features;
    out.inliers = r.inliers;
    out.knownViews = r.knownViews;
    out.keyframe = r.keyframe;
    out.milliseconds = r.milliseconds;
    out.reason = r.reason;
    out.pointTracks = r.pointTracks;
    out.lineTracks = r.lineTracks;
    return out;
}

std::vector<int64_t> readIds(InputArray array, int count, const char* name)
{
    std::vector<int64_t> ids;
    if (array.empty())
    {
        if (count > 0)
            CV_Error_(Error::StsBadSize, ("%s is empty: one id per feature is needed", name));
        return ids;
    }
    Mat m = array.getMat();
    if (m.channels() != 1 || (int)m.total() != count || !(m.depth() == CV_32S || m.depth() == CV_64F))
        CV_Error_(Error::StsBadSize, ("%s must hold one integer (CV_32S) per feature (%d)", name, count));
    Mat d;
    m.reshape(1, 1).convertTo(d, CV_64F);
    for (int i = 0; i < count; ++i)
        ids.push_back((int64_t)d.at<double>(i));
    return ids;
}

class TrackerImpl : public Tracker
{
public:
    TrackerImpl(InputArray cameraMatrix, InputArray distCoeffs, const TrackerParams& params)
        : tracker_(TRIPOSE_CALL_CORE([&] {
              std::vector<double> dist;
              if (!distCoeffs.empty())
              {
                  Mat d;
                  distCoeffs.getMat().convertTo(d, CV_64F);
                  dist.assign(d.ptr<double>(), d.ptr<double>() + d.total());
              }
              return core::Tracker(detail::readMatrix3(cameraMatrix, "cameraMatrix"), dist, toCoreOptions(params));
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
        const std::vector<int64_t> pi = readIds(pointIds, (int)p.size(), "pointIds");
        const std::vector<int64_t> li = readIds(lineIds, (int)s.size(), "lineIds");
        const FrameExtras extras(R, t, cameraMatrix);
        return toTrackedFrame(
            TRIPOSE_CALL_CORE([&] { return tracker_.addObservations(p, pi, s, li, extras.posePtr(), extras.KPtr()); }));
    }

    int numFrames() const CV_OVERRIDE { return tracker_.numFrames(); }

    bool getPose(int frame, OutputArray R, OutputArray t) const CV_OVERRIDE
    {
        if (frame < 0 || frame >= tracker_.numFrames())
            CV_Error_(Error::StsOutOfRange, ("frame %d is not one of the %d frames tracked", frame, tracker_.numFrames()));
        const core::StoredFrame& f = tracker_.frame(frame);
        if (!f.hasPose())
            return false;
        matOf(f.pose.R).copyTo(R);
        matOf(f.pose.t).copyTo(t);
        return true;
    }

    void getTracks(int frame, OutputArray pointTracks, OutputArray lineTracks) const CV_OVERRIDE
    {
        if (frame < 0 || frame >= tracker_.numFrames())
            CV_Error_(Error::StsOutOfRange, ("frame %d is not one of the %d frames tracked", frame, tracker_.numFrames()));
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
