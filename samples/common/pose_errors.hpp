// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// How far an estimated pose is from a reference one, as the samples report it.
#ifndef TRIPOSE_SAMPLES_POSE_ERRORS_HPP
#define TRIPOSE_SAMPLES_POSE_ERRORS_HPP

#include <opencv2/core.hpp>

namespace tripose_samples {

//! Angle of the rotation A B^T in degrees, from |A - B|_F = 2 sqrt(2) sin(angle / 2) (accurate near 0).
double rotationErrorDegrees(const cv::Mat& A, const cv::Mat& B);

//! |t - reference| / |reference|.
double relativeTranslationError(const cv::Mat& t, const cv::Mat& reference);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_POSE_ERRORS_HPP
