// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "pose_conversion.hpp"
#include "robust_estimator.hpp"
#include "triplet_input.hpp"

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
                                const RansacParams& params, OutputArray inliersPoints, OutputArray inliersLines)
{
    CV_INSTRUMENT_REGION();
    validate(params);
    const detail::TripletData data = detail::readTripletInput(points1, points2, points3, lines1, lines2, lines3,
                                                              cameraMatrix, distCoeffs, R12, t12);
    detail::RobustEstimate estimate;
    if (!detail::estimatePoseRobust(data, params, estimate))
    {
        R.release();
        t.release();
        writeMask(std::vector<unsigned char>(data.numPoints(), 0), inliersPoints);
        writeMask(std::vector<unsigned char>(data.numLines(), 0), inliersLines);
        return 0;
    }
    detail::writePose(estimate.pose.R, estimate.pose.t, R, t);
    writeMask(estimate.pointInliers, inliersPoints);
    writeMask(estimate.lineInliers, inliersLines);
    return estimate.numInliers;
}

} // namespace tripose
} // namespace cv
