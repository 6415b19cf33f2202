// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tracker_arguments.hpp"

#include "arguments.hpp"

namespace tripose_samples {

std::vector<std::string> trackerOptionNames(const std::string& localAdjustmentOption)
{
    return { "--window", "--min-inliers", "--threshold", "--keyframe-parallax", "--seed", "--loop-closure",
             "--global-adjustment-interval", localAdjustmentOption };
}

bool parseSwitch(const std::string& arg, const std::string& value)
{
    const int on = parseInteger(arg, value, 0.0);
    if (on > 1)
        throw argumentError(arg, "expected 0 or 1, got '" + value + "'");
    return on == 1;
}

bool readTrackerOption(const std::string& arg, const std::string& value, const std::string& localAdjustmentOption,
                       cv::tripose::TrackerParams& params)
{
    if (arg == "--window")
        params.window = parseInteger(arg, value, 2.0);
    else if (arg == "--min-inliers")
        params.minInliers = parseInteger(arg, value, 1.0);
    else if (arg == "--keyframe-parallax")
    {
        params.keyframeParallaxDeg = parseNumber(arg, value);
        if (!(params.keyframeParallaxDeg >= 0 && params.keyframeParallaxDeg < 180))
            throw argumentError(arg, "expected degrees from 0 to below 180, got '" + value + "'");
    }
    else if (arg == "--threshold")
    {
        params.ransac.threshold = parseNumber(arg, value);
        if (!(params.ransac.threshold > 0))
            throw argumentError(arg, "expected a positive number of pixels, got '" + value + "'");
    }
    else if (arg == "--seed")
        params.ransac.seed = parseInteger(arg, value, -2147483647.0);
    else if (arg == "--loop-closure")
        params.loopClosure = parseSwitch(arg, value);
    else if (arg == "--global-adjustment-interval")
        params.globalAdjustmentInterval = parseInteger(arg, value, 0.0);
    else if (arg == localAdjustmentOption)
        params.localAdjustment = parseSwitch(arg, value);
    else
        return false;
    return true;
}

} // namespace tripose_samples
