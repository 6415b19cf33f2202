// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/linear/rig_pose_solver.hpp"
#include "core/pipeline/pose_pipelines.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/covariance_writing.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/pose_refinement.hpp"
#include "opencv/result_writing.hpp"

namespace cv {
namespace tripose {

namespace {

const int kMinStereoFeatures = 2;
const int kMinStereoRansacFeatures = 3;

} // namespace

int estimatePoseLinePointStereo(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                InputArray R12, InputArray t12, OutputArray R, OutputArray t, int method,
                                OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs, OutputArray reprojectionErrors,
                                OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    detail::checkPoseMethod(method);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                       distCoeffs, R12, t12, kMinStereoFeatures);
        const detail::core::RigPoseSolver solver(views);
        const bool refine = method == POSE_LINEAR_REFINE;
        return detail::writeCandidateEstimate(views, detail::core::estimateCandidates(views, solver, refine), refine, R,
                                              t, candidateRs, candidateTs, reprojectionErrors, covariance,
                                              noiseVariance);
    });
}

int estimatePoseLinePointStereoRansac(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                      InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                      InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                      InputArray R12, InputArray t12, OutputArray R, OutputArray t,
                                      const RansacParams& params, OutputArray pointInliers, OutputArray lineInliers,
                                      OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs,
                                      OutputArray reprojectionErrors, OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                       distCoeffs, R12, t12, kMinStereoRansacFeatures);
        const detail::core::RansacOptions options = detail::toCoreOptions(params);
        detail::core::RobustEstimate estimate;
        const bool found = detail::core::estimateRobustRig(views, options, estimate);
        detail::writeEstimateCovariance(views, found && options.refine ? &estimate.pose : nullptr,
                                        options.refineOptions, &estimate.pointInliers, &estimate.lineInliers,
                                        covariance, noiseVariance);
        detail::writeRankedPoses(estimate.minima, candidateRs, candidateTs, reprojectionErrors, "candidateRs",
                                 "candidateTs");
        return detail::writeRobustEstimate(found, estimate, R, t, pointInliers, lineInliers);
    });
}

double refinePoseLinePointStereo(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                 InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                 InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                 InputArray R12, InputArray t12, InputOutputArray R, InputOutputArray t,
                                 const RefineParams& params, OutputArray points3d, OutputArray lines3d,
                                 OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                       distCoeffs, R12, t12, kMinStereoFeatures);
        return detail::refineGivenPose(views, R, t, params, points3d, lines3d, covariance, noiseVariance);
    });
}

} // namespace tripose
} // namespace cv
