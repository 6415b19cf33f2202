// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tracker_conversion.hpp"

#include "feature_reading.hpp"
#include "opencv_compat.hpp"
#include "options_conversion.hpp"

namespace cv {
namespace tripose {
namespace detail {

::tripose::TrackerOptions toCoreOptions(const TrackerParams& params)
{
    ::tripose::TrackerOptions o;
    o.window = params.window;
    o.minInliers = params.minInliers;
    o.keyframeParallaxDeg = params.keyframeParallaxDeg;
    o.checkTracks = params.checkTracks;
    o.localAdjustment = params.localAdjustment;
    o.loopClosure = params.loopClosure;
    o.globalAdjustmentInterval = params.globalAdjustmentInterval;
    o.robust = params.robust;
    o.ransac = toCoreOptions(params.ransac);
    o.matching = toCoreOptions(params.matching);
    o.maxFrameGap = params.maxFrameGap;
    o.covariance = params.covariance;
    ::tripose::checkTrackerOptions(o, "params");
    return o;
}

bool readFramePose(InputArray R, InputArray t, ::tripose::CameraPose& pose)
{
    if (R.empty() != t.empty())
        CV_Error(Error::StsBadArg, "R and t must be given together (the frame's pose), or neither");
    if (R.empty())
        return false;
    Mat r;
    R.getMat().convertTo(r, CV_64F);
    if (r.total() == 3)
        Rodrigues(r.reshape(1, 3), r);
    pose.R = readMatrix3(r, "R");
    Mat tv = t.getMat();
    if (tv.total() != 3 || tv.channels() != 1)
        CV_Error(Error::StsBadSize, "t must hold 3 elements");
    tv.reshape(1, 3).convertTo(tv, CV_64F);
    for (int i = 0; i < 3; ++i)
        pose.t[i] = tv.at<double>(i);
    return true;
}

std::vector<double> readDistortion(InputArray distCoeffs)
{
    std::vector<double> out;
    if (!distCoeffs.empty())
    {
        Mat d;
        distCoeffs.getMat().convertTo(d, CV_64F);
        d = d.isContinuous() ? d : d.clone();
        out.assign(d.ptr<double>(), d.ptr<double>() + d.total());
    }
    return out;
}

void checkFrameIndex(int frame, int numFrames)
{
    if (frame < 0 || frame >= numFrames)
        CV_Error_(Error::StsOutOfRange, ("frame %d is not one of the %d frames tracked", frame, numFrames));
}

bool writeFramePose(const ::tripose::StoredFrame& frame, OutputArray R, OutputArray t)
{
    if (!frame.hasPose())
        return false;
    matOf(frame.pose.R).copyTo(R);
    matOf(frame.pose.t).copyTo(t);
    return true;
}

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

TrackedFrame toTrackedFrame(const ::tripose::FrameResult& r)
{
    TrackedFrame out;
    out.frame = r.frame;
    out.status = (int)r.status;
    if (r.status != ::tripose::FrameStatus::Lost)
    {
        out.R = matOf(r.pose.R);
        out.t = matOf(r.pose.t);
    }
    out.features = r.features;
    out.inliers = r.inliers;
    out.knownViews = r.knownViews;
    out.recognisedKeyframe = r.recognisedKeyframe;
    out.map = r.map;
    out.keyframe = r.keyframe;
    out.milliseconds = r.milliseconds;
    out.reason = r.reason;
    out.pointTracks = r.pointTracks;
    out.lineTracks = r.lineTracks;
    if (r.hasCovariance)
    {
        out.covariance.create(6, 6, CV_64F);
        for (int i = 0; i < 36; ++i)
            out.covariance.at<double>(i / 6, i % 6) = r.covariance(i / 6, i % 6);
        out.noiseVariance = r.noiseVariance;
    }
    return out;
}

} // namespace detail
} // namespace tripose
} // namespace cv
