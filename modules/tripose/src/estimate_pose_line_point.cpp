// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/linear/linear_pose_solver.hpp"
#include "core/pipeline/pose_pipelines.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/result_writing.hpp"

namespace cv {
namespace tripose {

int estimatePoseLinePoint(InputArray points1, InputArray points2, InputArray points3,
                          InputArray lines1, InputArray lines2, InputArray lines3,
                          InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                          InputArray R12, InputArray t12, OutputArray R, OutputArray t, int method,
                          OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs, OutputArray reprojectionErrors,
                          OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    detail::checkPoseMethod(method);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                                       cameraMatrix, distCoeffs, R12, t12);
        const detail::core::LinearPoseSolver solver(views);
        const bool refine = method == POSE_LINEAR_REFINE;
        return detail::writeCandidateEstimate(views, detail::core::estimateCandidates(views, solver, refine), refine, R,
                                              t, candidateRs, candidateTs, reprojectionErrors, covariance,
                                              noiseVariance);
    });
}

} // namespace tripose
} // namespace cv
