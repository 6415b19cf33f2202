// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/problem_input.hpp"
#include "linear/linear_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"
#include "robust/hybrid_pose_solver.hpp"
#include "scoring/pose_scorer.hpp"

namespace cv {
namespace tripose {

RansacParams::RansacParams()
    : threshold(2.0), confidence(0.999), maxIterations(10000), localOptimization(true), refine(true), seed(0)
{}

int estimatePoseLinePointRansac(InputArray points1, InputArray points2, InputArray points3,
                                InputArray lines1, InputArray lines2, InputArray lines3,
                                InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                InputArray R12, InputArray t12, OutputArray R, OutputArray t,
                                const RansacParams& params, OutputArray pointInliers, OutputArray lineInliers)
{
    CV_INSTRUMENT_REGION();
    const detail::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                             cameraMatrix, distCoeffs, R12, t12);
    // The scorer's structure from views 1-2 is also what the minimal absolute-pose samples solve on.
    const detail::PoseScorer scorer(views);
    const detail::LinearPoseSolver linear(views);
    const detail::HybridPoseSolver solver(views, scorer, linear);
    return detail::estimateRobust(views, scorer, solver, params, R, t, pointInliers, lineInliers);
}

} // namespace tripose
} // namespace cv
