// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_HPP
#define OPENCV_TRIPOSE_ROBUST_HPP

#include "opencv2/core.hpp"
#include "opencv2/tripose/detail/cv_nd.hpp"
#include "opencv2/tripose/params.hpp"
#include "opencv2/tripose/refine.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

/** @brief Robust pose of a third view from point and line triplets with outliers.

RANSAC over minimal samples, with:
- where views 1 and 2 triangulate the features well, samples of three features solved as
  absolute-pose problems on the structure triangulated from views 1 and 2: three points (P3P), two
  points and a line, a point and two lines, or three lines, each kind drawn in proportion to the
  probability that it is all inliers (from the inlier ratios of points and of lines of the best
  model so far; lines whose planes in views 1 and 2 meet at a grazing angle are not drawn), the
  stopping rule counting the samples of every kind; on small sets, three points where the points
  with structure allow it. Every feature votes in every score and takes part in the local
  optimisation and the refinement;
- otherwise (a narrow baseline of views 1-2, small sets with few points) samples of four features
  (any mix of points and lines: the smallest set the linear solver of estimatePoseLinePoint()
  handles), which need no triangulated structure;
- hypotheses scored by truncated least squares (MSAC) on their residuals in view 3, in pixels,
  against the structure triangulated from views 1 and 2: for a point the distance of its
  reprojection, for a line the RMS of the distances of its two observed end points to the
  reprojected 3D line, truncated at 2 x RansacParams::threshold (see there);
- local optimisation: the linear solver re-run on the inliers of each new best model;
- adaptive stopping from the inlier ratios at the requested confidence;
- where the features admit few enough distinct samples to enumerate (and no more than
  RansacParams::maxIterations), every distinct sample drawn once instead, in an order set by the
  seed; when none has support, the linear solution over all features goes on to the inlier test;
- final maximum-likelihood refinement (as refinePoseLinePoint(), with RansacParams::refineParams) on
  the inliers, the inliers then re-classified and the refinement repeated until they settle. Where
  the cost may have several basins (a narrow baseline of views 1-2, planar structure, few points
  among the features where samples of four features are drawn), where a single refinement can
  leave the pose in another local minimum (doc/studies/accuracy.md), the refinement also starts
  from further poses (the linear solutions on the inliers and on subsets of them, as
  estimatePoseLinePoint() with #POSE_LINEAR_REFINE, and poses that keep the rotation and move view
  3's centre around view 1), each re-triangulated until it settles, and keeps the lowest cost (on
  large inlier sets only where the baseline of views 1-2 is narrow); on sets that are not large it
  is also run from all features, and the lower truncated cost of the two wins. The other minima it
  reaches that the noise cannot tell from the returned one are reported in @p candidateRs.

Arguments as in estimatePoseLinePoint().
@param params See RansacParams.
@param pointInliers Optional output: Nx1 CV_8U mask, 1 for inlier point triplets (RansacParams::threshold).
@param lineInliers Optional output: Mx1 CV_8U mask, 1 for inlier line triplets.
@param candidateRs Optional output: with RansacParams::refine, the returned rotation first, then
those of the other minima of the cost that the final refinement reached and that the data cannot
tell apart from it (3x3 CV_64F each, lowest cost first): their sum of squared residuals over the
inliers exceeds the returned pose's by less than 12.59 (the 95 % quantile of chi-square with 6
degrees of freedom) times the noise variance estimated at it, so they lie inside the pose's 95 %
likelihood-ratio confidence region (doc/conventions.md, "Several minima"). More than one: the pose
is ambiguous, as with a narrow baseline of views 1-2, and a tracker should wait for more parallax
rather than trust the first. Only the returned pose where the refinement searched one basin (see
above: a wide baseline, or a large inlier set); empty without refinement or when no pose was found.
@param candidateTs Optional output: the matching translations (3x1 CV_64F).
@param reprojectionErrors Optional output: per entry of @p candidateRs, the RMS reprojection error
(px, CV_64F) over the inliers in the three views after refinement.
@param covariance Optional output: with RansacParams::refine, the 6x6 CV_64F covariance of the
returned pose for 1 px image noise, as refinePoseLinePoint() reports it at that pose over the
inliers with RansacParams::refineParams. Released without refinement (the sample's or local
optimisation's pose is not the maximum-likelihood estimate that the covariance describes), when no
pose was found and when the pose is not determined.
@param noiseVariance Optional output: 1x1 CV_64F estimate of the image noise variance (px\f$^2\f$)
from the inliers' residuals, as in refinePoseLinePoint(); released together with @p covariance.
@return The number of inliers (points + lines) of the returned pose: one more than a sample holds at
least (four, or five with the samples of four features; a sample fits wrong matches too), or all
features where there are no more; 0 when no pose was found (then R and t are empty and the masks
all zero).

@throws cv::Exception naming the argument for the input errors of estimatePoseLinePoint(), when
@p candidateRs or @p candidateTs is not a std::vector<Mat> or @p reprojectionErrors, @p covariance or
@p noiseVariance is a vector of arrays, and naming the field when a field of @p params (or of
params.refineParams, when refine is set) is out of range.
*/
CV_EXPORTS_W int estimatePoseLinePointRansac(
    InputArray points1, InputArray points2, InputArray points3,
    InputArray lines1, InputArray lines2, InputArray lines3,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    OutputArray R, OutputArray t,
    const RansacParams& params = RansacParams(),
    OutputArray pointInliers = noArray(), OutputArray lineInliers = noArray(),
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_ROBUST_HPP
