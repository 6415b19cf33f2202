// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_matching.hpp"

namespace tripose_samples {

cv::tripose::MatchParams withPixelScale(cv::tripose::MatchParams params, double pixelScale)
{
    params.epipolarDistance *= pixelScale;
    return params;
}

bool contradicts(const cv::Vec2i& agreement)
{
    return agreement[0] >= 20 && agreement[1] < 0.3 * agreement[0];
}

std::string agreementSummary(const cv::Vec2i& agreement)
{
    return cv::format("of %d point matches found without the poses, %d (%.0f %%) lie on their epipolar lines "
                      "(73-88 %% where the poses are right)",
                      agreement[0], agreement[1], agreement[0] > 0 ? 100.0 * agreement[1] / agreement[0] : 0.0);
}

} // namespace tripose_samples
