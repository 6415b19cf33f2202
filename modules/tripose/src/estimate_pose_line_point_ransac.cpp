// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/linear/linear_pose_solver.hpp"
#include "core/pipeline/pose_pipelines.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/covariance_writing.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/result_writing.hpp"

namespace cv {
namespace tripose {

RansacParams::RansacParams()
    : threshold(2.0), confidence(0.999), maxIterations(10000), localOptimization(true), refine(true), seed(0),
      minInliers(15)
{}

int estimatePoseLinePointRansac(InputArray points1, InputArray points2, InputArray points3,
                                InputArray lines1, InputArray lines2, InputArray lines3,
                                InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                InputArray R12, InputArray t12, OutputArray R, OutputArray t,
                                const RansacParams& params, OutputArray pointInliers, OutputArray lineInliers,
                                OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs,
                                OutputArray reprojectionErrors, OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    detail::checkCandidateOutputs(candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance);
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                                       cameraMatrix, distCoeffs, R12, t12);
        const detail::core::RansacOptions options = detail::toCoreOptions(params);
        const detail::core::LinearPoseSolver linear(views);
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

} // namespace tripose
} // namespace cv
