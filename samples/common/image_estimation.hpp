// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The robust estimate's settings for features found in images by the front end (image_features.hpp).
#ifndef TRIPOSE_SAMPLES_IMAGE_ESTIMATION_HPP
#define TRIPOSE_SAMPLES_IMAGE_ESTIMATION_HPP

#include <opencv2/tripose.hpp>

namespace tripose_samples {

/** Scale (px) of the Cauchy loss of the final refinement on image features. Detected features are
not Gaussian: a tight core sits beside a tail a few times wider (large SIFT key points, whose
position moves with the viewpoint, and features far from the centre), which least squares over the
RANSAC inliers follows, so the estimate lies many of its own standard deviations from the camera; a
Cauchy loss a few times the core's spread keeps the tail from pulling (doc/studies/real_images.md,
"Where the error came from"). */
const double kImageLossScale = 0.5;

//! RANSAC with refinement, the refinement under the Cauchy loss of kImageLossScale.
inline cv::tripose::RansacParams imageRansacParams()
{
    cv::tripose::RansacParams params;
    params.refine = true;
    params.refineParams.loss = cv::tripose::LOSS_CAUCHY;
    params.refineParams.lossScale = kImageLossScale;
    return params;
}

//! @p params with its pixel threshold and loss scale multiplied by @p pixelScale (detectionScale():
//! features detected in reduced images are placed that much less precisely in the images' pixels).
inline cv::tripose::RansacParams withPixelScale(cv::tripose::RansacParams params, double pixelScale)
{
    params.threshold *= pixelScale;
    params.refineParams.lossScale *= pixelScale;
    return params;
}

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_IMAGE_ESTIMATION_HPP
