// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What the samples add to the library's matching (cv::tripose::matchFeatureTriplets, Tracker): the
// pixel tolerances of features detected in reduced images, and the words of their warnings.
#ifndef TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP
#define TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP

#include <string>

#include <opencv2/tripose.hpp>

namespace tripose_samples {

//! @p params with its pixel tolerance multiplied by @p pixelScale (detectionScale(): features detected
//! in reduced images are placed that much less precisely in the images' pixels).
cv::tripose::MatchParams withPixelScale(cv::tripose::MatchParams params, double pixelScale);

//! Whether FeatureTriplets::pairAgreement or Tracker::givenPairAgreement() says that the given poses
//! are not the images': under 30 % of 20 or more descriptor matches on their epipolar lines.
bool contradicts(const cv::Vec2i& agreement);

//! "of N point matches found without the poses, k (p %) lie on their epipolar lines (73-88 % ...)".
std::string agreementSummary(const cv::Vec2i& agreement);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP
