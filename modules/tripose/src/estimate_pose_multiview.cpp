// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/linear/multiview_pose_solver.hpp"
#include "core/pipeline/pose_pipelines.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/covariance_writing.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/pose_refinement.hpp"
#include "opencv/result_writing.hpp"

namespace cv {
namespace tripose {

namespace {

const int kMinMultiViewFeatures = 4;

} // namespace

int estimatePoseMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                          InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts, OutputArray R,
                          OutputArray t, int method, OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs,
                          OutputArray reprojectionErrors, OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    detail::checkPoseMethod(method);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
        const detail::core::MultiViewPoseSolver solver(views);
        const bool refine = method == POSE_LINEAR_REFINE;
        return detail::writeCandidateEstimate(views, detail::core::estimateCandidates(views, solver, refine), refine, R,
                                              t, candidateRs, candidateTs, reprojectionErrors, covariance,
                                              noiseVariance);
    });
}

int estimatePoseMultiViewRansac(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                                InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                                OutputArray R, OutputArray t, const RansacParams& params, OutputArray pointInliers,
                                OutputArray lineInliers, OutputArrayOfArrays candidateRs,
                                OutputArrayOfArrays candidateTs, OutputArray reprojectionErrors,
                                OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
        const detail::core::RansacOptions options = detail::toCoreOptions(params);
        const detail::core::MultiViewPoseSolver linear(views);
        detail::core::RobustEstimate estimate;
        const bool found = detail::core::estimateRobustOnKnownStructure(views, linear, options, estimate);
        detail::writeEstimateCovariance(views, found && options.refine ? &estimate.pose : nullptr,
                                        options.refineOptions, &estimate.pointInliers, &estimate.lineInliers,
                                        covariance, noiseVariance);
        detail::writeRankedPoses(estimate.minima, candidateRs, candidateTs, reprojectionErrors, "candidateRs",
                                 "candidateTs");
        return detail::writeRobustEstimate(found, estimate, R, t, pointInliers, lineInliers);
    });
}

double refinePoseMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                           InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                           InputOutputArray R, InputOutputArray t, const RefineParams& params, OutputArray points3d,
                           OutputArray lines3d, OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views =
            detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
        return detail::refineGivenPose(views, R, t, params, points3d, lines3d, covariance, noiseVariance);
    });
}

double adjustPosesMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                            InputArrayOfArrays distCoeffs, InputArray fixedViews, InputOutputArrayOfArrays Rs,
                            InputOutputArrayOfArrays ts, const RefineParams& params, OutputArray points3d,
                            OutputArray lines3d)
{
    CV_INSTRUMENT_REGION();
    return TRIPOSE_CALL_CORE([&] {
        std::vector<int> poseOfView;
        std::vector<detail::core::CameraPose> poses;
        const detail::core::ViewSet views = detail::readSeveralPosesInput(points, lines, cameraMatrix, distCoeffs, Rs,
                                                                          ts, fixedViews, poseOfView, poses);
        const detail::core::RefineOptions options = detail::toCoreOptions(params);
        detail::core::RefinedStructure structure;
        const double rms = detail::core::refineSeveralPoses(views, poseOfView, poses, options, &structure);
        detail::writePoseVectors(detail::core::allViewPoses(views, poseOfView, poses), Rs, ts, "Rs", "ts");
        detail::writeStructure(structure.points, structure.lineEnds, views.numPoints, views.numLines, points3d, lines3d);
        return rms;
    });
}

} // namespace tripose
} // namespace cv
