// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "options_conversion.hpp"

namespace cv {
namespace tripose {
namespace detail {

core::RefineOptions toCoreOptions(const RefineParams& params, const char* name)
{
    core::RefineOptions options;
    options.maxIterations = params.maxIterations;
    options.lossScale = params.lossScale;
    options.tolerance = params.tolerance;
    if (params.loss != LOSS_SQUARED && params.loss != LOSS_HUBER && params.loss != LOSS_CAUCHY)
    {
        // The fields are reported in their order: a bad maxIterations comes first.
        TRIPOSE_CALL_CORE([&] { core::checkRefineOptions(options, name); });
        CV_Error_(Error::StsBadArg, ("%s.loss must be LOSS_SQUARED (0), LOSS_HUBER (1) or LOSS_CAUCHY (2) (got %d)",
                                     name, params.loss));
    }
    options.loss = static_cast<core::Loss>(params.loss);
    return options;
}

core::RansacOptions toCoreOptions(const RansacParams& params)
{
    core::RansacOptions options;
    options.threshold = params.threshold;
    options.confidence = params.confidence;
    options.maxIterations = params.maxIterations;
    options.localOptimization = params.localOptimization;
    options.refine = params.refine;
    // A negative seed is a valid seed: its bits, as a 64-bit value, seed the generator.
    options.seed = (uint64_t)(int64_t)params.seed;
    if (params.refine)
    {
        // The fields are reported in their order: the sampling parameters come first.
        core::RansacOptions sampling = options;
        sampling.refine = false;
        TRIPOSE_CALL_CORE([&] { core::checkRansacOptions(sampling); });
        options.refineOptions = toCoreOptions(params.refineParams, "params.refineParams");
    }
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
