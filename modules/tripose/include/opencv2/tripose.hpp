// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_HPP
#define OPENCV_TRIPOSE_HPP

#include "opencv2/tripose/params.hpp"
#include "opencv2/tripose/pose.hpp"
#include "opencv2/tripose/refine.hpp"
#include "opencv2/tripose/robust.hpp"
#include "opencv2/tripose/multiview.hpp"
#include "opencv2/tripose/stereo.hpp"
#include "opencv2/tripose/features.hpp"
#include "opencv2/tripose/tracker.hpp"

/**
@defgroup tripose Camera pose from point and line triplets in three views

Estimates the pose of a third calibrated camera from point and line correspondences seen in three
views, when the poses of the first two views are known, by the unified linear method of
@cite QadirNeubert2017 , with robust estimation and maximum-likelihood refinement on top.

Conventions of every function of the module (doc/conventions.md):
- A camera with pose \f$(R, t)\f$ maps a world point \f$X\f$ to \f$x \sim K (R X + t)\f$ (OpenCV
  convention).
- Three views (estimatePoseLinePoint() and its siblings): the world frame is the frame of view 1, so
  view 1 is \f$[I | 0]\f$, view 2 is \f$[R_{12} | t_{12}]\f$ (known, \f$t_{12} \ne 0\f$ fixes the
  metric scale) and view 3 is \f$[R | t]\f$ (estimated).
- A stereo rig (estimatePoseLinePointStereo() and its siblings): the same frame, the left camera at
  time A being view 1 and \f$[R_{12} | t_{12}]\f$ the rig; \f$[R | t]\f$ is the left camera at time B.
- Several known views (estimatePoseMultiView() and its siblings, adjustPosesMultiView()): every pose,
  given or returned, is a world pose in the caller's frame.
- Every estimator takes its arguments in one order: the observations, the cameras (@p cameraMatrix,
  @p distCoeffs), the known poses, the output pose @p R, @p t, then its method (#PoseMethod) or its
  RansacParams, the inlier masks @p pointInliers, @p lineInliers (robust functions), and last the
  same optional outputs in every family: @p candidateRs, @p candidateTs, @p reprojectionErrors,
  @p covariance, @p noiseVariance.
- @p Rs and @p ts are always poses the caller gives (the known views' world poses; in
  adjustPosesMultiView() every view's, refined in place); the candidates a function returns are
  @p candidateRs and @p candidateTs.
- Rotations are 3x3 matrices or Rodrigues vectors where an input, 3x3 CV_64F matrices where an
  output (translations: 3x1 CV_64F).
- Points are pixel coordinates \f$(u, v)\f$ with \f$(0, 0)\f$ the centre of the top-left pixel.
- A line is observed either as a segment \f$(x_0, y_0, x_1, y_1)\f$ in pixels or as a homogeneous
  image line \f$(a, b, c)\f$ with \f$a u + b v + c = 0\f$.
- Bad input throws cv::Exception naming the argument; geometry that determines no pose gives zero
  candidates (or zero inliers, or +inf from a refinement), never a NaN pose.

@{
    @defgroup tripose_pose Pose estimation
@}
*/

#endif // OPENCV_TRIPOSE_HPP
