// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/pose_conversion.hpp"
#include "input/problem_input.hpp"
#include "linear/linear_pose_solver.hpp"
#include "refine/multi_start_refiner.hpp"
#include "robust/robust_estimator.hpp"

namespace cv {
namespace tripose {

RansacParams::RansacParams()
    : threshold(2.0), confidence(0.999), maxIterations(10000), localOptimization(true), refine(true), seed(0)
{}

namespace {

void validate(const RansacParams& p)
{
    if (!(p.threshold > 0) || !std::isfinite(p.threshold))
        CV_Error_(Error::StsBadArg, ("params.threshold must be a positive number of pixels, got %g", p.threshold));
    if (!(p.confidence > 0 && p.confidence < 1))
        CV_Error_(Error::StsBadArg, ("params.confidence must be in (0, 1), got %g", p.confidence));
    if (p.maxIterations <= 0)
        CV_Error_(Error::StsBadArg, ("params.maxIterations must be positive, got %d", p.maxIterations));
    if (p.refine)
        detail::checkRefineParams(p.refineParams, "params.refineParams");
}

void writeMask(const std::vector<unsigned char>& mask, OutputArray out)
{
    if (out.needed())
        Mat((int)mask.size(), 1, CV_8U, (void*)mask.data()).copyTo(out);
}

} // namespace

int estimatePoseLinePointRansac(InputArray points1, InputArray points2, InputArray points3,
                                InputArray lines1, InputArray lines2, InputArray lines3,
                                InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                InputArray R12, InputArray t12, OutputArray R, OutputArray t,
                                const RansacParams& params, OutputArray pointInliers, OutputArray lineInliers)
{
    CV_INSTRUMENT_REGION();
    validate(params);
    const detail::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                             cameraMatrix, distCoeffs, R12, t12);
    const detail::LinearPoseSolver solver(views);
    const detail::PoseScorer scorer(views);
    const detail::MultiStartRefiner refiner(views, params.refineParams, &solver);
    detail::RobustEstimate estimate;
    if (!detail::estimatePoseRobust(solver, scorer, params.refine ? &refiner : nullptr, params, estimate))
    {
        R.release();
        t.release();
        writeMask(std::vector<unsigned char>(views.numPoints, 0), pointInliers);
        writeMask(std::vector<unsigned char>(views.numLines, 0), lineInliers);
        return 0;
    }
    detail::writePose(estimate.pose.R, estimate.pose.t, R, t);
    writeMask(estimate.pointInliers, pointInliers);
    writeMask(estimate.lineInliers, lineInliers);
    return estimate.numInliers;
}

} // namespace tripose
} // namespace cv
