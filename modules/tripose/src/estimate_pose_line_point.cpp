// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/problem_input.hpp"
#include "linear/linear_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"

namespace cv {
namespace tripose {

int estimatePoseLinePoint(InputArray points1, InputArray points2, InputArray points3,
                          InputArray lines1, InputArray lines2, InputArray lines3,
                          InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                          InputArray R12, InputArray t12, OutputArray R, OutputArray t, int method,
                          OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray reprojectionErrors)
{
    CV_INSTRUMENT_REGION();
    detail::checkPoseMethod(method);
    const detail::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                             cameraMatrix, distCoeffs, R12, t12);
    const detail::LinearPoseSolver solver(views);
    return detail::estimateCandidates(views, solver, method, R, t, Rs, ts, reprojectionErrors);
}

} // namespace tripose
} // namespace cv
