// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_COVARIANCE_WRITING_HPP
#define OPENCV_TRIPOSE_OPENCV_COVARIANCE_WRITING_HPP

#include <vector>

#include "opencv2/core.hpp"

#include "../core/geometry/view_set.hpp"
#include "../core/refine/ml_refinement.hpp"
#include "core_calls.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! Whether the caller asked for the uncertainty of the pose (either optional output).
bool covarianceWanted(OutputArray covariance, OutputArray noiseVariance);

/** The pose's 6x6 covariance (CV_64F) and the 1x1 noise-variance estimate (CV_64F), where
wanted; both released when @p uncertainty is not valid.
*/
void writeCovariance(const core::PoseCovariance& uncertainty, OutputArray covariance, OutputArray noiseVariance);

/** The uncertainty of @p pose, the maximum-likelihood estimate that an estimator returned, over
the features of the masks (null: all), computed only when wanted; both outputs released when
@p pose is null (no estimate, or one that the refinement did not produce).
*/
void writeEstimateCovariance(const core::ViewSet& views, const core::CameraPose* pose,
                             const core::RefineOptions& options, const std::vector<unsigned char>* pointMask,
                             const std::vector<unsigned char>* lineMask, OutputArray covariance,
                             OutputArray noiseVariance);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_COVARIANCE_WRITING_HPP
