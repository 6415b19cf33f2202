// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The robust estimate's settings for features found in images by the front end (image_features.hpp).
#ifndef TRIPOSE_SAMPLES_IMAGE_ESTIMATION_HPP
#define TRIPOSE_SAMPLES_IMAGE_ESTIMATION_HPP

#include <opencv2/tripose.hpp>

namespace tripose_samples {

/** Scale (px) of the Cauchy loss of the final refinement on image features. Detected features are
not Gaussian: on the VGG sequences the point tracks that fit the sequence's cameras to 0.15-0.2 px
(median) sit beside a tail of 1-2 px (large SIFT key points, whose position moves with the
viewpoint, and features far from the centre), which least squares over the RANSAC inliers (2 px)
follows: the estimate then lies 10-14 standard deviations of its own covariance from the camera
(doc/studies/real_images.md, "Where the error came from"). A Cauchy loss a few times the core's spread keeps
the tail from pulling; 0.3-1 px give the same picture there. */
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
