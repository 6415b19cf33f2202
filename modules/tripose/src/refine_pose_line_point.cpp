// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/pipeline/pose_pipelines.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/options_conversion.hpp"
#include "opencv/result_writing.hpp"
#include "opencv/pose_refinement.hpp"

namespace cv {
namespace tripose {

RefineParams::RefineParams() : maxIterations(30), loss(LOSS_SQUARED), lossScale(1.0), tolerance(1e-10)
{
}

double refinePoseLinePoint(InputArray points1, InputArray points2, InputArray points3,
                           InputArray lines1, InputArray lines2, InputArray lines3,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, InputOutputArray R, InputOutputArray t,
                           const RefineParams& params, OutputArray points3d, OutputArray lines3d,
                           OutputArray covariance, OutputArray noiseVariance)
{
    CV_INSTRUMENT_REGION();
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                                       cameraMatrix, distCoeffs, R12, t12, 3);
        return detail::refineGivenPose(views, R, t, params, points3d, lines3d, covariance, noiseVariance);
    });
}

} // namespace tripose
} // namespace cv
