// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POSE_HPP
#define OPENCV_TRIPOSE_POSE_HPP

#include "opencv2/core.hpp"
#include "opencv2/tripose/detail/cv_nd.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

//! Methods of estimatePoseLinePoint().
enum PoseMethod
{
    POSE_LINEAR = 0,        //!< The unified linear solver of @cite QadirNeubert2017 on all features (no outlier rejection).
    POSE_LINEAR_REFINE = 1, //!< POSE_LINEAR, then maximum-likelihood refinement (default RefineParams) over the
                            //!< three views from every candidate and from further starts; the distinct minima
                            //!< ranked by their reprojection error (no outlier rejection).
};

/** @brief Estimates the pose of a third calibrated view from point and line triplets, the poses of
the first two views being known.

The world frame is the frame of view 1: view 1 is \f$[I|0]\f$, view 2 is \f$[R_{12}|t_{12}]\f$ and
the estimated view 3 is \f$[R|t]\f$, each mapping a world point \f$X\f$ to \f$x \sim K(RX + t)\f$.
The metric scale of \f$t\f$ is that of \f$t_{12}\f$.

With POSE_LINEAR the method of @cite QadirNeubert2017 is used: every point triplet adds rows of the
normalized trilinear constraints and every line triplet the two rows left by eliminating the planes
of views 1 and 2; the pose is a combination of the last N singular vectors of the stacked system
(N = 1 for six or more features, also N = 2 there; N = 2 for five, N = 4 for four), whose coefficients
are found from the orthonormality of \f$R\f$. Each candidate gets the nearest rotation and a
least-squares translation, polished on the algebraic error, and its twisted pair (rotated by pi
about the baseline) is added. With the structure triangulated from views 1 and 2, candidates that
put most of it behind view 3 are dropped and the rest are ranked by their RMS reprojection error in
view 3 (points: pixel distance; segments: distances of both end points to the projected line).
Four or five features whose constraints are dependent (e.g. collinear points) give no candidate.

With POSE_LINEAR_REFINE every candidate is then refined over the three views. Where the cost has
several basins (a narrow baseline of views 1-2, planar structure, mostly lines) so are further
starts: poses of distinct rotations from the linear solver on four-feature subsets, and poses that
keep the best-ranked candidate's rotation (and, when the best minimum's rotation differs from it,
that minimum's) and move view 3's centre around view 1 at the same distance; each refinement is
repeated from its result with the structure triangulated afresh until it settles. The distinct
minima that use every usable feature are returned, ranked by their RMS reprojection error over
the three views: with a narrow known baseline or planar structure the linear candidates alone lead
to another local minimum in many scenes (doc/studies/accuracy.md). Minima whose costs the noise
cannot order are all there: see doc/conventions.md, "Several minima", for the rule (from
@p reprojectionErrors and @p noiseVariance) that tells them.

Any mix of at least four features works (4 points, 4 lines, 2 points + 2 lines, 3 + 1, 1 + 3 and
anything larger).

@param points1 Points in view 1: Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F, pixels.
N may be 0 (or the array empty) when only lines are used.
@param points2 The same N points in view 2, same layout.
@param points3 The same N points in view 3, same layout.
@param lines1 Lines in view 1: Mx4 1-channel or 1xM/Mx1 4-channel segments \f$(x_0, y_0, x_1, y_1)\f$,
or Mx3 1-channel / 3-channel homogeneous image lines \f$(a, b, c)\f$, CV_32F or CV_64F, pixels.
M may be 0. Homogeneous lines cannot be undistorted: they require empty distortion coefficients.
@param lines2 The same M lines in view 2, same layout.
@param lines3 The same M lines in view 3, same layout.
@param cameraMatrix One 3x3 intrinsic matrix \f$K\f$ shared by the three views, or a vector of three.
@param distCoeffs Distortion coefficients in OpenCV's model (4, 5, 8, 12 or 14 values), one vector
shared by the views or a vector of three; empty means no distortion.
@param R12 Rotation of view 2 w.r.t. view 1: 3x3 matrix or 3x1/1x3 Rodrigues vector, CV_32F/CV_64F.
@param t12 Translation of view 2 w.r.t. view 1, 3x1 or 1x3, non-zero.
@param R Output rotation of view 3 (3x3, CV_64F): the best candidate. Empty when no solution is found.
@param t Output translation of view 3 (3x1, CV_64F).
@param method One of #PoseMethod.
@param candidateRs Optional output: every candidate rotation (3x3 CV_64F), best first.
@param candidateTs Optional output: the matching translations (3x1 CV_64F).
@param reprojectionErrors Optional output: per candidate, in pixels (CV_64F, same order as candidateRs): the
RMS reprojection error in view 3 (POSE_LINEAR) or over the three views after refinement
(POSE_LINEAR_REFINE).
@param covariance Optional output: with #POSE_LINEAR_REFINE, the 6x6 CV_64F covariance of the best
candidate for 1 px image noise, as refinePoseLinePoint() reports it at that refined pose over every
feature. Released with #POSE_LINEAR (a linear estimate is not the maximum-likelihood one that the
covariance describes) and when there is no candidate or the pose is not determined.
@param noiseVariance Optional output: 1x1 CV_64F estimate of the image noise variance (px\f$^2\f$) at
that candidate, as in refinePoseLinePoint(); released together with @p covariance.
@return The number of candidate poses (0 when the geometry admits none, e.g. degenerate input).

@throws cv::Exception naming the argument when an input has the wrong shape or type, the counts
disagree between views, fewer than four features are given, a value is not finite, \f$R_{12}\f$ is
not a rotation, \f$t_{12}\f$ is zero or an intrinsic matrix is not usable, or when @p candidateRs or
@p candidateTs is not a std::vector<Mat> or @p reprojectionErrors, @p covariance or @p noiseVariance
is a vector of arrays.
*/
CV_EXPORTS_W int estimatePoseLinePoint(
    InputArray points1, InputArray points2, InputArray points3,
    InputArray lines1, InputArray lines2, InputArray lines3,
    CV_ND InputArrayOfArrays cameraMatrix, CV_ND InputArrayOfArrays distCoeffs,
    InputArray R12, InputArray t12,
    OutputArray R, OutputArray t,
    int method = POSE_LINEAR,
    OutputArrayOfArrays candidateRs = noArray(), OutputArrayOfArrays candidateTs = noArray(),
    OutputArray reprojectionErrors = noArray(),
    OutputArray covariance = noArray(), OutputArray noiseVariance = noArray());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_POSE_HPP
