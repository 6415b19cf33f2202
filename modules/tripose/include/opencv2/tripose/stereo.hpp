// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_STEREO_HPP
#define OPENCV_TRIPOSE_STEREO_HPP

#include "opencv2/core.hpp"
#include "opencv2/tripose/detail/cv_nd.hpp"
#include "opencv2/tripose/params.hpp"
#include "opencv2/tripose/pose.hpp"
#include "opencv2/tripose/refine.hpp"
#include "opencv2/tripose/robust.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

/** @brief Estimates the motion of a calibrated stereo rig between two times from point and line
correspondences (the four-view extension of @cite QadirNeubert2017).

The four views: view 1 is the left camera at time A, \f$[I|0]\f$ (the world frame); view 2 the right
camera at time A, \f$[R_{12}|t_{12}]\f$, the rig (e.g. from cv::stereoCalibrate); view 3 the left
camera at time B, \f$[R|t]\f$, estimated; view 4 the right camera at time B,
\f$[R_{12} R | R_{12} t + t_{12}]\f$. The rig fixes the metric scale of \f$t\f$.

Every feature is seen by both cameras at time A and by view 3, view 4 or both. In points3, points4,
lines3 and lines4 a row of NaN marks a feature the view does not see; an empty array means the view
sees none of that kind.

Each observation at time B adds rows to the paper's linear system in \f$v = [r_1; r_2; r_3; t]\f$:
view 3 the homogeneous rows of estimatePoseLinePoint(), view 4 rows that are affine in \f$v\f$ (the
rig's translation enters as a constant), so the system is \f$A v = b\f$ and the scale comes from
\f$b\f$. With too few constraints for a unique solution, the kernel of \f$A\f$ is combined so that
\f$R\f$ is a rotation. Three features seen in both time-B views (3 points, 3 lines, 2 points + 1 line,
1 point + 2 lines) determine the motion; two lines, or one point and one line, seen in both give up
to a few candidates. Candidates that put most of the structure (triangulated from views 1-2) behind
view 3 or 4 are dropped and the rest are ranked by their RMS reprojection error in views 3 and 4;
with POSE_LINEAR_REFINE each is refined over the four views, together with further starts as for
estimatePoseLinePoint(), and the distinct minima are ranked by their refined error.

@param points1 Points in view 1: Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F, pixels. N may be 0.
@param points2 The same N points in view 2 (all seen).
@param points3 The N points in view 3, a row of NaN where view 3 does not see the point; or empty.
@param points4 The N points in view 4, likewise.
@param lines1 Lines in view 1: Mx4 segments \f$(x_0, y_0, x_1, y_1)\f$ or Mx3 homogeneous lines
\f$(a, b, c)\f$, CV_32F or CV_64F, pixels, as in estimatePoseLinePoint(). M may be 0.
@param lines2 The same M lines in view 2 (all seen), same kind.
@param lines3 The M lines in view 3, a row of NaN where view 3 does not see the line; or empty.
@param lines4 The M lines in view 4, likewise.
@param cameraMatrix One 3x3 intrinsic matrix shared by the four views, or a vector of four (left,
right, left, right for a rig with two different cameras).
@param distCoeffs Distortion coefficients (4, 5, 8, 12 or 14 values), one vector or four; empty for none.
@param R12 Rotation of the right camera w.r.t. the left: 3x3 matrix or Rodrigues vector, CV_32F/CV_64F.
@param t12 Translation of the right camera w.r.t. the left (the rig's baseline), 3 elements, non-zero.
@param R Output rotation of view 3 (3x3, CV_64F): the best candidate; empty when there is none.
@param t Output translation of view 3 (3x1, CV_64F), metric.
@param method POSE_LINEAR or POSE_LINEAR_REFINE.
@param candidateRs Optional output: every candidate rotation (3x3 CV_64F), best first.
@param candidateTs Optional output: the matching translations (3x1 CV_64F).
@param reprojectionErrors Optional output: per candidate, the RMS reprojection error (px) in views 3
and 4 (POSE_LINEAR) or over the four views after refinement (POSE_LINEAR_REFINE).
@param covariance Optional output: the best candidate's 6x6 covariance, as estimatePoseLinePoint() gives it.
@param noiseVariance Optional output: the noise variance estimate, as estimatePoseLinePoint() gives it.
@return The number of candidate poses (0 when the features do not determine the motion).

@throws cv::Exception naming the argument for the input errors of estimatePoseLinePoint(), for a
feature missing in both views 3 and 4, a partly NaN row, or fewer than two features.
*/
CV_EXPORTS_W int estimatePoseLinePointStereo(
    InputArray points1, InputArray points2, InputArray points3, InputArray points4,
    InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    OutputArray R, OutputArray t,
    int method = POSE_LINEAR,
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

/** @brief Robust motion of a stereo rig from point and line correspondences with outliers.

The problem of estimatePoseLinePointStereo() with RANSAC as in estimatePoseLinePointRansac():
samples of three features; hypotheses scored (MSAC) on their residuals in views 3 and 4 against the
structure triangulated from views 1-2, truncated at 2 x RansacParams::threshold; local optimisation,
adaptive stopping; then maximum-likelihood refinement over the four views on the inliers. A feature
is an inlier when its RMS reprojection error over every view that sees it, re-triangulated from
all of them with the returned pose, is below RansacParams::threshold.

Arguments as in estimatePoseLinePointStereo(); at least three features (the sample size) are required.
@param params See RansacParams.
@param pointInliers Optional output: Nx1 CV_8U mask of inlier points.
@param lineInliers Optional output: Mx1 CV_8U mask of inlier lines.
@param candidateRs Optional output: with RansacParams::refine, the returned rotation (3x3 CV_64F), as
estimatePoseLinePointRansac() gives its first candidate; empty without refinement or when no pose
was found. The rig's refinement descends from the estimator's pose alone (its samples, scored with
the known structure free to slide in depth, find the basin), so no other minimum is reported: the
vector holds one entry.
@param candidateTs Optional output: the matching translation (3x1 CV_64F).
@param reprojectionErrors Optional output: per entry of @p candidateRs, the RMS reprojection error
(px, CV_64F) over the inliers in the four views after refinement.
@param covariance Optional output: the returned pose's 6x6 covariance, as estimatePoseLinePointRansac() gives it.
@param noiseVariance Optional output: the noise variance estimate, as estimatePoseLinePointRansac() gives it.
@return The number of inliers (points + lines), four at least (one more than a sample of three; all
three where only three features are given); 0 when no pose was found (R and t empty, masks zero).

@throws cv::Exception naming the argument or the field as estimatePoseLinePointRansac() does.
*/
CV_EXPORTS_W int estimatePoseLinePointStereoRansac(
    InputArray points1, InputArray points2, InputArray points3, InputArray points4,
    InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    OutputArray R, OutputArray t,
    const RansacParams& params = RansacParams(),
    OutputArray pointInliers = noArray(), OutputArray lineInliers = noArray(),
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

/** @brief Maximum-likelihood refinement of a stereo rig's motion and the structure.

As refinePoseLinePoint(), over the four views of estimatePoseLinePointStereo(): the pose of view 3
and the structure are estimated, view 4 moves with view 3 (the rig is kept rigid), views 1 and 2 are
fixed; each feature contributes its residuals in the views that see it.

Arguments as in estimatePoseLinePointStereo() and refinePoseLinePoint().
@param R Input: initial rotation of view 3 (3x3 or Rodrigues). Output: the refined rotation, 3x3 CV_64F.
@param t Input: initial translation of view 3. Output: 3x1 CV_64F.
@param params See RefineParams.
@param points3d Optional output: Nx3 CV_64F refined points in the frame of view 1.
@param lines3d Optional output: Mx6 CV_64F, two points of each refined line: those closest to the
rays of the view-1 end points.
@param covariance Optional output: 6x6 CV_64F covariance of the refined pose for 1 px image noise,
as in refinePoseLinePoint().
@param noiseVariance Optional output: 1x1 CV_64F estimate of the image noise variance (px\f$^2\f$), as
in refinePoseLinePoint().
@return The RMS reprojection error (px) at the refined estimate over every residual of the
features that enter the cost; +inf when none does (R, t then unchanged).
*/
CV_EXPORTS_W double refinePoseLinePointStereo(
    InputArray points1, InputArray points2, InputArray points3, InputArray points4,
    InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    InputOutputArray R, InputOutputArray t,
    const RefineParams& params = RefineParams(),
    OutputArray points3d = noArray(), OutputArray lines3d = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_STEREO_HPP
