// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_ESTIMATOR_SCORED_POSE_HPP
#define TRIPOSE_CORE_ESTIMATOR_SCORED_POSE_HPP

#include "../geometry/camera.hpp"

namespace tripose {

//! A candidate pose with the RMS reprojection error by which the candidates are ranked.
struct ScoredPose
{
    CameraPose pose;
    double rms = 0; //!< RMS reprojection error in the estimated view(s) (px).
};

} // namespace tripose

#endif // TRIPOSE_CORE_ESTIMATOR_SCORED_POSE_HPP
