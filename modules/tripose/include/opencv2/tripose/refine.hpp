// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_HPP
#define OPENCV_TRIPOSE_REFINE_HPP

#include "opencv2/core.hpp"
#include "opencv2/tripose/detail/cv_nd.hpp"
#include "opencv2/tripose/params.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

/** @brief Refines the pose of the third view and the 3D structure by minimizing the reprojection
error in all three views (maximum likelihood under Gaussian image noise).

Views 1 (\f$[I|0]\f$) and 2 (\f$[R_{12}|t_{12}]\f$) are fixed; the pose \f$[R|t]\f$ of view 3 and every
3D point (3 parameters) and 3D line (4 parameters, orthonormal representation) are estimated. The
residuals, in pixels, are for a point its reprojection minus the observation in each view, and for a
line the signed distances of the two observed segment end points to the projected 3D line in each
view. The structure is initialised by triangulating over the three views with the given pose.

Levenberg-Marquardt with the structure eliminated (Schur complement, one small block per feature),
so a step costs time linear in the number of features. The rotation is updated by a left
multiplicative increment \f$R \leftarrow \exp([\omega]_\times) R\f$, the translation additively. With a
robust loss the problem is solved by iteratively reweighted least squares.

Features that the three views cannot determine (a point on the line through the camera centres,
three coincident planes of a line, a point behind a camera) do not enter the cost; they keep their
initial structure.

This is the final stage of estimatePoseLinePointRansac(); call it directly to polish a pose from
estimatePoseLinePoint() or from elsewhere.

@param points1 Points in view 1: Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F, pixels. N may be 0.
@param points2 The same N points in view 2, same layout.
@param points3 The same N points in view 3, same layout.
@param lines1 Lines in view 1: Mx4 segments \f$(x_0, y_0, x_1, y_1)\f$ or Mx3 homogeneous lines
\f$(a, b, c)\f$, as in estimatePoseLinePoint(). For homogeneous lines two points 50 px either side of
the point of the line closest to the principal point stand in for the end points.
@param lines2 The same M lines in view 2, same layout.
@param lines3 The same M lines in view 3, same layout.
@param cameraMatrix One 3x3 intrinsic matrix shared by the three views, or a vector of three.
@param distCoeffs Distortion coefficients (4, 5, 8, 12 or 14 values), one vector or three; empty for none.
@param R12 Rotation of view 2: 3x3 matrix or 3-element Rodrigues vector, CV_32F or CV_64F.
@param t12 Translation of view 2, 3x1 or 1x3, non-zero.
@param R Input: initial rotation of view 3, 3x3 matrix or 3-element Rodrigues vector, CV_32F or
CV_64F. Output: the refined rotation, 3x3 CV_64F (like every rotation output; a Rodrigues vector
given here comes back as a matrix).
@param t Input: initial translation of view 3, 3 elements, CV_32F or CV_64F. Output: 3x1 CV_64F.
@param params See RefineParams.
@param points3d Optional output: Nx3 CV_64F refined 3D points in the frame of view 1.
@param lines3d Optional output: Mx6 CV_64F, two points \f$(X_0, Y_0, Z_0, X_1, Y_1, Z_1)\f$ of each refined
3D line: the points closest to the back-projected rays of the view-1 end points.
@param covariance Optional output: 6x6 CV_64F covariance of the refined pose for image noise of
standard deviation 1 px (multiply it by the noise variance), the structure marginalised. Order
[rotation; translation]: the rotation error \f$d\f$ with \f$R_{est} = \exp([d]_\times) R_{true}\f$
(radians), the translation error \f$t_{est} - t_{true}\f$ (the units of t). It is the inverse of the
pose block of the Gauss-Newton normal equations at the refined estimate with the 3D structure
eliminated; with a robust loss, of the normal equations weighted by the final IRLS weights. The
convention, and its conversion to the covariance of the camera centre, is written in the module's
doc/conventions.md ("Pose covariance"). Released (empty) when the pose is not determined: no
feature entered the cost, or the reduced pose block is singular or not finite.
@param noiseVariance Optional output: 1x1 CV_64F, the estimate of the image noise variance
(px\f$^2\f$) from the residuals: their (IRLS-weighted) sum of squares divided by their number minus
the number of parameters (6 + 3 per point + 4 per line that entered the cost); +inf when there are
no more residuals than parameters. Released together with @p covariance.
@return The RMS reprojection error in pixels at the refined estimate over every residual of the
three views (two per point and per line in each view) of the features that enter the cost; +inf when
no feature does (then R, t are returned unchanged).

@throws cv::Exception naming the argument for the input errors listed at estimatePoseLinePoint()
(with at least three features required), when R is not a rotation or R, t are malformed or not finite,
or when a field of @p params is out of range.
*/
CV_EXPORTS_W double refinePoseLinePoint(
    InputArray points1, InputArray points2, InputArray points3,
    InputArray lines1, InputArray lines2, InputArray lines3,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    InputOutputArray R, InputOutputArray t,
    const RefineParams& params = RefineParams(),
    OutputArray points3d = noArray(), OutputArray lines3d = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_REFINE_HPP
