// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/problem_input.hpp"
#include "linear/multiview_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"

namespace cv {
namespace tripose {

namespace {

// Four features of any mix are the fewest the linear method solves, as with three views.
const int kMinMultiViewFeatures = 4;

} // namespace

int estimatePoseMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                          InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts, OutputArray R,
                          OutputArray t, int method, OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs,
                          OutputArray reprojectionErrors)
{
    CV_INSTRUMENT_REGION();
    detail::checkPoseMethod(method);
    const detail::ViewSet views =
        detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
    const detail::MultiViewPoseSolver solver(views);
    return detail::estimateCandidates(views, solver, method, R, t, candidateRs, candidateTs, reprojectionErrors);
}

int estimatePoseMultiViewRansac(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                                InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                                OutputArray R, OutputArray t, const RansacParams& params, OutputArray pointInliers,
                                OutputArray lineInliers)
{
    CV_INSTRUMENT_REGION();
    const detail::ViewSet views =
        detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
    const detail::MultiViewPoseSolver solver(views);
    return detail::estimateRobust(views, solver, params, R, t, pointInliers, lineInliers);
}

double refinePoseMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                           InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                           InputOutputArray R, InputOutputArray t, const RefineParams& params, OutputArray points3d,
                           OutputArray lines3d)
{
    CV_INSTRUMENT_REGION();
    const detail::ViewSet views =
        detail::readMultiViewInput(points, lines, cameraMatrix, distCoeffs, Rs, ts, kMinMultiViewFeatures);
    return detail::refineInitialPose(views, R, t, params, points3d, lines3d);
}

double refinePosesMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                            InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                            InputArray fixedViews, OutputArrayOfArrays refinedRs, OutputArrayOfArrays refinedTs,
                            const RefineParams& params, OutputArray points3d, OutputArray lines3d)
{
    CV_INSTRUMENT_REGION();
    std::vector<int> poseOfView;
    std::vector<detail::CameraPose> poses;
    const detail::ViewSet views = detail::readSeveralPosesInput(points, lines, cameraMatrix, distCoeffs, Rs, ts,
                                                                fixedViews, poseOfView, poses);
    return detail::refineSeveralPoses(views, poseOfView, poses, params, refinedRs, refinedTs, points3d, lines3d);
}

} // namespace tripose
} // namespace cv
