// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/problem_input.hpp"
#include "linear/rig_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"

namespace cv {
namespace tripose {

namespace {

// Two features seen in both time-B views (two lines, or a point and a line) are the fewest that
// determine the motion up to a few candidates.
const int kMinStereoFeatures = 2;
// The robust estimator draws samples of three features (RigPoseSolver::sampleSize()).
const int kMinStereoRansacFeatures = 3;

} // namespace

int estimatePoseLinePointStereo(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                InputArray R12, InputArray t12, OutputArray R, OutputArray t, int method,
                                OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray reprojectionErrors)
{
    CV_INSTRUMENT_REGION();
    detail::checkPoseMethod(method);
    const detail::ViewSet views =
        detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                   distCoeffs, R12, t12, kMinStereoFeatures);
    const detail::RigPoseSolver solver(views);
    return detail::estimateCandidates(views, solver, method, R, t, Rs, ts, reprojectionErrors);
}

int estimatePoseLinePointStereoRansac(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                      InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                      InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                      InputArray R12, InputArray t12, OutputArray R, OutputArray t,
                                      const RansacParams& params, OutputArray pointInliers, OutputArray lineInliers)
{
    CV_INSTRUMENT_REGION();
    const detail::ViewSet views =
        detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                   distCoeffs, R12, t12, kMinStereoRansacFeatures);
    const detail::RigPoseSolver solver(views);
    return detail::estimateRobust(views, solver, params, R, t, pointInliers, lineInliers);
}

double refinePoseLinePointStereo(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                 InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                 InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                 InputArray R12, InputArray t12, InputOutputArray R, InputOutputArray t,
                                 const RefineParams& params, OutputArray points3d, OutputArray lines3d)
{
    CV_INSTRUMENT_REGION();
    const detail::ViewSet views =
        detail::readStereoRigInput(points1, points2, points3, points4, lines1, lines2, lines3, lines4, cameraMatrix,
                                   distCoeffs, R12, t12, kMinStereoFeatures);
    return detail::refineInitialPose(views, R, t, params, points3d, lines3d);
}

} // namespace tripose
} // namespace cv
