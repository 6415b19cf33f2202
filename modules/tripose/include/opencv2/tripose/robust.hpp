// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_HPP
#define OPENCV_TRIPOSE_ROBUST_HPP

#include "opencv2/core.hpp"

// OpenCV 4.8+ marks array arguments that Python passes whole (one 3x3 K, not three rows);
// older OpenCV (Debian's 4.6) lacks the marker.
#ifndef CV_ND
#define CV_ND
#endif

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

/** @brief Parameters of estimatePoseLinePointRansac().
*/
struct CV_EXPORTS_W_SIMPLE RansacParams
{
    CV_WRAP RansacParams();
    CV_PROP_RW double threshold;       //!< Inlier threshold (px) on the view-3 residual of a feature (default 2).
    CV_PROP_RW double confidence;      //!< Probability, in (0, 1), of drawing at least one all-inlier sample (default 0.999).
    CV_PROP_RW int maxIterations;      //!< Upper bound on the number of samples (default 10000).
    CV_PROP_RW bool localOptimization; //!< Re-estimate from the inliers of every new best model (default true).
    CV_PROP_RW bool refine;            //!< Finish with refinePoseLinePoint() over the inliers (default true).
    CV_PROP_RW int seed;               //!< Seed of the sampler: the same seed gives the same result (default 0).
};

/** @brief Robust pose of a third view from point and line triplets with outliers.

RANSAC over mixed samples of four features (any mix of points and lines: the smallest sample
the linear solver of estimatePoseLinePoint() handles), with:
- residuals in pixels in view 3, the structure taken from views 1 and 2 (a point: distance of its
  reprojection; a line: the larger distance of the two observed end points to the reprojected
  3D line), scored by truncated least squares (MSAC);
- local optimisation: the linear solver re-run on the inliers of each new best model;
- adaptive stopping from the inlier ratio at the requested confidence;
- final maximum-likelihood refinement over the three views on the inliers (RansacParams::refine),
  after which the inlier masks are recomputed.

Arguments as in estimatePoseLinePoint().
@param inliersPoints Optional output: Nx1 CV_8U mask, 1 for inlier point triplets.
@param inliersLines Optional output: Mx1 CV_8U mask, 1 for inlier line triplets.
@return The number of inliers (points + lines) of the returned pose; 0 when no pose was found
(then R and t are empty).
*/
CV_EXPORTS_W int estimatePoseLinePointRansac(
    InputArray points1, InputArray points2, InputArray points3,
    InputArray lines1, InputArray lines2, InputArray lines3,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    OutputArray R, OutputArray t,
    const RansacParams& params = RansacParams(),
    OutputArray inliersPoints = noArray(), OutputArray inliersLines = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_ROBUST_HPP
