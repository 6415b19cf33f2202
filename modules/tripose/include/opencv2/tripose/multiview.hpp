// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_MULTIVIEW_HPP
#define OPENCV_TRIPOSE_MULTIVIEW_HPP

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

/** @brief Registers a calibrated camera against any number of views with known poses from the
points and lines they share (the general form of estimatePoseLinePoint()).

V >= 2 known views at world poses \f$[R_k | t_k]\f$ (k = 0..V-1) and one new view \f$[R | t]\f$,
each mapping a world point \f$X\f$ to \f$x \sim K(RX + t)\f$. A feature (point or line) is seen by the
new view and by at least two known views; it need not be seen by all of them. The known poses fix
the world frame and the metric scale, so their centres must not all coincide.

Each feature contributes the rows of @cite QadirNeubert2017 from every pair (a, b) of known views
that see it (in a minimal sample of four or five features: from the pair with the widest angle
between its rays, for a point, or back-projected planes, for a line), each written in the frame of
view a, with view b at \f$[R_b R_a^T | t_b - R_b R_a^T t_a]\f$, the unknown
camera's pose relative to view a is linear in the unknown world pose, so the rows of every pair act
on one vector \f$v = [r_1; r_2; r_3; t]\f$. The rest is estimatePoseLinePoint(): kernel,
orthonormality of \f$R\f$, nearest rotation, polish. Candidates that put most of the structure
(triangulated from every known view that sees it) behind the new view are dropped, the rest ranked
by their RMS reprojection error in the new view; with POSE_LINEAR_REFINE each is refined by
refinePoseMultiView() and ranked by its refined error. With the views {[I|0], [R12|t12]} this is the
problem of estimatePoseLinePoint().

@param points One array per view, the V known views then the new view: Nx2 1-channel or 1xN/Nx1
2-channel, CV_32F or CV_64F, pixels, the same N rows in every view; a row of NaN where the view does
not see the point, an empty array where it sees none. An empty vector means no points.
@param lines One array per view likewise: Mx4 segments \f$(x_0, y_0, x_1, y_1)\f$ or Mx3 homogeneous
lines \f$(a, b, c)\f$ (one kind in all views), pixels, NaN rows where unseen. An empty vector: no lines.
@param cameraMatrix One 3x3 intrinsic matrix shared by every view, or a vector of V + 1 (the known
views, then the new view).
@param distCoeffs Distortion coefficients (4, 5, 8, 12 or 14 values), one vector or V + 1; empty for none.
@param Rs The known views' world rotations: a vector of V 3x3 matrices or Rodrigues vectors, CV_32F/CV_64F.
@param ts The known views' world translations: a vector of V 3-element vectors.
@param R Output rotation of the new view (3x3, CV_64F): the best candidate; empty when there is none.
@param t Output translation of the new view (3x1, CV_64F), in the units of @p ts.
@param method POSE_LINEAR or POSE_LINEAR_REFINE.
@param candidateRs Optional output: every candidate rotation, best first.
@param candidateTs Optional output: the matching translations.
@param reprojectionErrors Optional output: per candidate, the RMS reprojection error (px) in the new
view (POSE_LINEAR) or over every view (POSE_LINEAR_REFINE).
@param covariance Optional output: the best candidate's 6x6 covariance, as estimatePoseLinePoint() gives it.
@param noiseVariance Optional output: the noise variance estimate, as estimatePoseLinePoint() gives it.
@return The number of candidate poses (0 when the features do not determine the pose).
@throws cv::Exception naming the argument for the input errors of estimatePoseLinePoint(), for fewer
than two known views, known views all at one centre, a feature the new view does not see or that
fewer than two known views see, or fewer than four features.
*/
CV_EXPORTS_W int estimatePoseMultiView(
    InputArrayOfArrays points, InputArrayOfArrays lines,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArrayOfArrays Rs, InputArrayOfArrays ts,
    OutputArray R, OutputArray t,
    int method = POSE_LINEAR,
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

/** @brief Robust registration against several known views from point and line correspondences with
outliers.

The problem of estimatePoseMultiView() with RANSAC as in estimatePoseLinePointRansac(): where the
known views triangulate the features well (by the widest angle between the rays of the known views
that see each feature), samples of three points and lines mixed, solved on the structure
triangulated from the known views; else samples of four features for the linear solver;
hypotheses scored (MSAC) on their residuals in the new view against the structure triangulated
from the known views that see each feature, truncated at 2 x RansacParams::threshold; local
optimisation, adaptive stopping; then
maximum-likelihood refinement over every view on the inliers (known poses fixed). A feature is an
inlier when its RMS reprojection error over every view that sees it, re-triangulated from all of
them with the returned pose, is below RansacParams::threshold.

Arguments as in estimatePoseMultiView().
@param params See RansacParams.
@param pointInliers Optional output: Nx1 CV_8U mask of inlier points.
@param lineInliers Optional output: Mx1 CV_8U mask of inlier lines.
@param candidateRs Optional output: with RansacParams::refine, the returned rotation first, then
those of the other minima that the final refinement reached and that the data cannot tell apart from
it, lowest cost first (3x3 CV_64F each), by the rule of estimatePoseLinePointRansac()'s candidates
with the residuals over every view. More than one: the pose is ambiguous, as where the known views
triangulate poorly. Only the returned pose where the refinement searched one basin; empty without
refinement or when no pose was found.
@param candidateTs Optional output: the matching translations (3x1 CV_64F).
@param reprojectionErrors Optional output: per entry of @p candidateRs, the RMS reprojection error
(px, CV_64F) over the inliers in every view after refinement.
@param covariance Optional output: the returned pose's 6x6 covariance, as estimatePoseLinePointRansac() gives it.
@param noiseVariance Optional output: the noise variance estimate, as estimatePoseLinePointRansac() gives it.
@return The number of inliers (points + lines), one more than a minimal sample at least (as
estimatePoseLinePointRansac()); 0 when no pose was found (R and t empty, masks zero).

@throws cv::Exception naming the argument or the field as estimatePoseLinePointRansac() does, and
for the input errors of estimatePoseMultiView().
*/
CV_EXPORTS_W int estimatePoseMultiViewRansac(
    InputArrayOfArrays points, InputArrayOfArrays lines,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArrayOfArrays Rs, InputArrayOfArrays ts,
    OutputArray R, OutputArray t,
    const RansacParams& params = RansacParams(),
    OutputArray pointInliers = noArray(), OutputArray lineInliers = noArray(),
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

/** @brief Maximum-likelihood refinement of the new view's pose and the structure over every view.

As refinePoseLinePoint(), over the views of estimatePoseMultiView(): the new view's pose and the
structure are estimated, the known views are fixed; each feature contributes its residuals in every
view that sees it.

Arguments as in estimatePoseMultiView() and refinePoseLinePoint().
@param R Input: initial rotation of the new view (3x3 or Rodrigues). Output: the refined rotation, 3x3 CV_64F.
@param t Input: initial translation of the new view. Output: 3x1 CV_64F.
@param params See RefineParams.
@param points3d Optional output: Nx3 CV_64F refined points in the world frame.
@param lines3d Optional output: Mx6 CV_64F, two points of each refined line: those closest to the
rays of the end points in the first view that sees it.
@param covariance Optional output: 6x6 CV_64F covariance of the refined pose for 1 px image noise,
as in refinePoseLinePoint().
@param noiseVariance Optional output: 1x1 CV_64F estimate of the image noise variance (px\f$^2\f$), as
in refinePoseLinePoint().
@return The RMS reprojection error (px) at the refined estimate over every residual of the
features that enter the cost; +inf when none does (R, t then unchanged).
*/
CV_EXPORTS_W double refinePoseMultiView(
    InputArrayOfArrays points, InputArrayOfArrays lines,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArrayOfArrays Rs, InputArrayOfArrays ts,
    InputOutputArray R, InputOutputArray t,
    const RefineParams& params = RefineParams(),
    OutputArray points3d = noArray(), OutputArray lines3d = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

/** @brief Local adjustment: maximum-likelihood refinement of several views' poses and the structure
together (a bundle adjustment in which some views stay fixed), for the recent frames of a tracker.

V views at world poses \f$[R_k | t_k]\f$ (k = 0..V-1), each mapping a world point \f$X\f$ to
\f$x \sim K_k(R_k X + t_k)\f$. The views whose @p fixedViews entry is zero are refined together with
the points and lines (Levenberg-Marquardt, structure eliminated per feature, as in
refinePoseMultiView()); the others stay where they are. The fixed views fix the world frame and the
metric scale: at least two of them, at distinct centres. Each feature contributes its residuals in
every view that sees it, and must be seen by at least two views.

A free view that sees fewer features than determine its pose (three points, or four features of any
mix in general position) is held near its initial pose by the damping only; give such views as fixed.
The cost is the one of refinePoseMultiView(), so the refined poses of a problem whose only free view
is the last one agree with refinePoseMultiView()'s.

@param points One array per view (Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F, pixels), the
same N rows in every view, NaN rows where a view does not see a point, an empty array where it sees
none. An empty vector means no points.
@param lines One array per view likewise: Mx4 segments or Mx3 homogeneous lines (one kind in all views).
@param cameraMatrix One 3x3 intrinsic matrix shared by every view, or a vector of V.
@param distCoeffs Distortion coefficients, one vector or V; empty for none.
@param fixedViews V values (CV_8U, CV_8S or CV_32S): nonzero where the view's pose is fixed.
@param Rs Input: the V views' world rotations (3x3 or Rodrigues, CV_32F/CV_64F), the free ones' as
initial values. Output: V 3x3 CV_64F rotations, the free views' refined, the fixed views' as given
(as the nearest exact rotation, like every input rotation). A std::vector<Mat>.
@param ts Input: the V views' world translations (3 elements each). Output: V 3x1 CV_64F
translations likewise. A std::vector<Mat>.
@param params See RefineParams.
@param points3d Optional output: Nx3 CV_64F refined points in the world frame.
@param lines3d Optional output: Mx6 CV_64F, two points of each refined line (see refinePoseMultiView()).
@return The RMS reprojection error (px) at the refined estimate over every residual of the features
that enter the cost; +inf when none does (poses then unchanged).
@throws cv::Exception naming the argument for the input errors of refinePoseMultiView(), when every
view is fixed, fewer than two fixed views or fixed views at one centre, or a feature seen by fewer
than two views.
*/
CV_EXPORTS_W double adjustPosesMultiView(
    InputArrayOfArrays points, InputArrayOfArrays lines,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray fixedViews,
    InputOutputArrayOfArrays Rs, InputOutputArrayOfArrays ts,
    const RefineParams& params = RefineParams(),
    OutputArray points3d = noArray(), OutputArray lines3d = noArray());

/** @brief Structure of points and lines seen by views of known pose, and the reprojection error of
every observation: triangulation from posed views, and the check of a tracker's links.

V >= 2 views at world poses \f$[R_k | t_k]\f$, each mapping a world point \f$X\f$ to
\f$x \sim K_k(R_k X + t_k)\f$. Each feature is triangulated from every view that sees it (a point by
least squares whose rows approximate pixel errors, a line from the planes through its image lines),
as the final inlier test of the robust estimators does, and measured in each of those views. A
feature seen by one view (or none) has no structure; neither has a point whose rays are parallel, a
line whose planes coincide, or a feature that lies behind a view that sees it (for a line, the part
of it the view saw).

A wrong observation pulls the structure towards it and shares its error with the feature's other
observations, so the largest error of a feature points to its wrong observation only when the
others agree; to clean a track, drop that observation and triangulate again. A line seen by two
views fits both exactly (two planes always meet): its errors tell something from three views on,
a point's from two.

@param points One array per view (Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F, pixels), the
same N rows in every view, NaN rows where a view does not see a point, an empty array where it sees
none. An empty vector means no points.
@param lines One array per view likewise: Mx4 segments or Mx3 homogeneous lines (one kind in all views).
@param cameraMatrix One 3x3 intrinsic matrix shared by every view, or a vector of V.
@param distCoeffs Distortion coefficients, one vector or V; empty for none. The errors are measured
on the undistorted observations, in pixels of the camera matrix.
@param Rs The V views' world rotations (3x3 or Rodrigues, CV_32F/CV_64F).
@param ts The V views' world translations (3 elements each).
@param points3d Output: Nx3 CV_64F points in the world frame; NaN rows for the points without structure.
@param lines3d Output: Mx6 CV_64F, two points of each line: those closest to the rays of the end
points of the first view that sees it (as refinePoseMultiView() returns them); NaN rows for the lines
without structure.
@param pointErrors Optional output: NxV CV_64F, the distance (px) between each point's projection and
its observation in each view; NaN where the view does not see the point, +inf in every view that
sees a point without structure.
@param lineErrors Optional output: MxV CV_64F, the larger of the distances (px) of the two observed
end points to the line's image in each view; NaN and +inf likewise.
@return The number of features (points + lines) with structure.
@throws cv::Exception naming the argument when the inputs do not fit the description above (as for
adjustPosesMultiView(): fewer than two views, counts that differ between views, an invalid rotation,
a non-finite observation that is not a whole NaN row).
*/
CV_EXPORTS_W int triangulateMultiView(
    InputArrayOfArrays points, InputArrayOfArrays lines,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArrayOfArrays Rs, InputArrayOfArrays ts,
    OutputArray points3d, OutputArray lines3d,
    OutputArray pointErrors = noArray(), OutputArray lineErrors = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_MULTIVIEW_HPP
