// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tracker_options.hpp"

#include <cmath>
#include <string>

#include "../support/error.hpp"

namespace tripose {

void checkMatchOptions(const MatchOptions& m, const char* name)
{
    const std::string prefix = std::string(name) + ".";
    if (!(m.epipolarDistance > 0 && std::isfinite(m.epipolarDistance)))
        fail(ErrorCode::BadArgument, "%sepipolar_distance must be positive and finite, got %g", prefix.c_str(),
             m.epipolarDistance);
    if (!(m.pointRatio > 0 && m.pointRatio <= 1) || !(m.lineRatio > 0 && m.lineRatio <= 1))
        fail(ErrorCode::BadArgument, "%spoint_ratio and %sline_ratio must be in (0, 1], got %g and %g", prefix.c_str(),
             prefix.c_str(), m.pointRatio, m.lineRatio);
    if (!(m.minBandOverlap >= 0 && m.minBandOverlap <= 1))
        fail(ErrorCode::BadArgument, "%smin_band_overlap must be in [0, 1], got %g", prefix.c_str(), m.minBandOverlap);
    if (!(m.minEpipolarAngleDeg >= 0 && m.minEpipolarAngleDeg < 90))
        fail(ErrorCode::BadArgument, "%smin_epipolar_angle_deg must be in [0, 90), got %g", prefix.c_str(),
             m.minEpipolarAngleDeg);
    if (m.minFundamentalInliers < 8)
        fail(ErrorCode::BadArgument, "%smin_fundamental_inliers must be at least 8, got %d", prefix.c_str(),
             m.minFundamentalInliers);
}

void checkTrackerOptions(const TrackerOptions& options, const char* name)
{
    const std::string prefix = std::string(name) + ".";
    if (options.window < 2)
        fail(ErrorCode::BadArgument, "%swindow must be at least 2 (keyframes a frame is registered against), got %d",
             prefix.c_str(), options.window);
    if (options.minInliers < 1)
        fail(ErrorCode::BadArgument, "%smin_inliers must be at least 1, got %d", prefix.c_str(), options.minInliers);
    if (!(options.keyframeParallaxDeg >= 0 && options.keyframeParallaxDeg < 180))
        fail(ErrorCode::BadArgument, "%skeyframe_parallax_deg must be in [0, 180) degrees, got %g", prefix.c_str(),
             options.keyframeParallaxDeg);
    if (options.maxFrameGap < 1)
        fail(ErrorCode::BadArgument, "%smax_frame_gap must be at least 1, got %d", prefix.c_str(), options.maxFrameGap);
    if (options.globalAdjustmentInterval < 0)
        fail(ErrorCode::BadArgument, "%sglobal_adjustment_interval must be at least 0, got %d", prefix.c_str(),
             options.globalAdjustmentInterval);
    checkMatchOptions(options.matching, (prefix + "matching").c_str());
    checkRansacOptions(options.ransac, (prefix + "ransac").c_str());
}

} // namespace tripose
