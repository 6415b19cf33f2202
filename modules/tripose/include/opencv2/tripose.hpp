// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_HPP
#define OPENCV_TRIPOSE_HPP

#include "opencv2/tripose/pose.hpp"
#include "opencv2/tripose/refine.hpp"
#include "opencv2/tripose/robust.hpp"
#include "opencv2/tripose/multiview.hpp"
#include "opencv2/tripose/stereo.hpp"

/**
@defgroup tripose Camera pose from point and line triplets in three views

Estimates the pose of a third calibrated camera from point and line correspondences seen in three
views, when the poses of the first two views are known, by the unified linear method of
@cite QadirNeubert2017 , with robust estimation and maximum-likelihood refinement on top.

Conventions, followed by every function of the module:
- The world frame is the frame of camera 1. A camera with pose \f$(R, t)\f$ maps a world point
  \f$X\f$ to \f$x \sim K (R X + t)\f$ (OpenCV convention), so view 1 is \f$[I | 0]\f$, view 2 is
  \f$[R_{12} | t_{12}]\f$ (known, \f$t_{12} \ne 0\f$ fixes the metric scale) and view 3 is
  \f$[R | t]\f$ (estimated).
- Points are pixel coordinates \f$(u, v)\f$ with \f$(0, 0)\f$ the centre of the top-left pixel.
- A line is observed either as a segment \f$(x_0, y_0, x_1, y_1)\f$ in pixels or as a homogeneous
  image line \f$(a, b, c)\f$ with \f$a u + b v + c = 0\f$.
- Rotations are 3x3 matrices or Rodrigues vectors where an input, 3x3 CV_64F matrices where an output.

@{
    @defgroup tripose_pose Pose estimation
@}
*/

#endif // OPENCV_TRIPOSE_HPP
