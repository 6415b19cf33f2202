// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "options_conversion.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

core::RefineOptions convert(const RefineParams& params)
{
    core::RefineOptions options;
    options.maxIterations = params.maxIterations;
    // An out-of-range value is representable (the enumeration's type is int): the check reports it.
    options.loss = static_cast<core::Loss>(params.loss);
    options.lossScale = params.lossScale;
    options.tolerance = params.tolerance;
    return options;
}

} // namespace

core::RefineOptions toCoreOptions(const RefineParams& params)
{
    const core::RefineOptions options = convert(params);
    core::checkRefineOptions(options, "params");
    return options;
}

core::RansacOptions toCoreOptions(const RansacParams& params)
{
    core::RansacOptions options;
    options.threshold = params.threshold;
    options.confidence = params.confidence;
    options.maxIterations = params.maxIterations;
    options.minInliers = params.minInliers;
    options.localOptimization = params.localOptimization;
    options.refine = params.refine;
    options.refineOptions = convert(params.refineParams);
    // A negative seed is a valid seed: its bits, as a 64-bit value, seed the generator.
    options.seed = (uint64_t)(int64_t)params.seed;
    core::checkRansacOptions(options, "params");
    return options;
}

void checkPoseMethod(int method)
{
    if (method != POSE_LINEAR && method != POSE_LINEAR_REFINE)
        CV_Error_(Error::StsBadArg, ("method must be POSE_LINEAR (%d) or POSE_LINEAR_REFINE (%d), got %d",
                                     (int)POSE_LINEAR, (int)POSE_LINEAR_REFINE, method));
}

} // namespace detail
} // namespace tripose
} // namespace cv
