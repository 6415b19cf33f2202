// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The command-line options of cv::tripose::TrackerParams that the tracking programs share.
#ifndef TRIPOSE_SAMPLES_TRACKER_ARGUMENTS_HPP
#define TRIPOSE_SAMPLES_TRACKER_ARGUMENTS_HPP

#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

namespace tripose_samples {

//! --window, --min-inliers, --threshold, --keyframe-parallax, --seed, --loop-closure (0|1) and
//! @p localAdjustmentOption (0|1).
std::vector<std::string> trackerOptionNames(const std::string& localAdjustmentOption);

/** Reads option @p arg (one of trackerOptionNames()) with @p value into @p params; false for any
other option. Throws argumentError() naming the option on a value out of range. */
bool readTrackerOption(const std::string& arg, const std::string& value, const std::string& localAdjustmentOption,
                       cv::tripose::TrackerParams& params);

//! A 0|1 option's value.
bool parseSwitch(const std::string& arg, const std::string& value);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_TRACKER_ARGUMENTS_HPP
