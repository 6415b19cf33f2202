// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "pose_errors.hpp"

#include <algorithm>
#include <cmath>

namespace tripose_samples {

double rotationErrorDegrees(const cv::Mat& A, const cv::Mat& B)
{
    const double halfChord = cv::norm(A, B, cv::NORM_L2) / (2.0 * std::sqrt(2.0));
    return 2.0 * std::asin(std::min(1.0, halfChord)) * 180.0 / CV_PI;
}

double relativeTranslationError(const cv::Mat& t, const cv::Mat& reference)
{
    return cv::norm(t, reference, cv::NORM_L2) / cv::norm(reference, cv::NORM_L2);
}

} // namespace tripose_samples
