// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "options.hpp"

#include <cmath>

#include "error.hpp"

namespace tripose {

void checkRefineOptions(const RefineOptions& options, const char* name, const RefineOptionNames& fields)
{
    if (!(options.maxIterations > 0))
        fail(ErrorCode::BadArgument, "%s.%s must be positive (got %d)", name, fields.maxIterations,
             options.maxIterations);
    if (options.loss != Loss::Squared && options.loss != Loss::Huber && options.loss != Loss::Cauchy)
        fail(ErrorCode::BadArgument, "%s.%s is not a known loss (got %d)", name, fields.loss, (int)options.loss);
    if (!(options.lossScale > 0) || !std::isfinite(options.lossScale))
        fail(ErrorCode::BadArgument, "%s.%s must be a positive, finite number of pixels (got %g)", name,
             fields.lossScale, options.lossScale);
    if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
        fail(ErrorCode::BadArgument, "%s.%s must be finite and >= 0 (got %g)", name, fields.tolerance,
             options.tolerance);
}

void checkRansacOptions(const RansacOptions& options, const char* name, const RansacOptionNames& fields)
{
    if (!(options.threshold > 0) || !std::isfinite(options.threshold))
        fail(ErrorCode::BadArgument, "%s.%s must be a positive number of pixels, got %g", name, fields.threshold,
             options.threshold);
    if (!(options.confidence > 0 && options.confidence < 1))
        fail(ErrorCode::BadArgument, "%s.%s must be in (0, 1), got %g", name, fields.confidence, options.confidence);
    if (options.maxIterations <= 0)
        fail(ErrorCode::BadArgument, "%s.%s must be positive, got %d", name, fields.maxIterations,
             options.maxIterations);
    if (options.refine)
    {
        const std::string refineName = formatString("%s.%s", name, fields.refineOptions);
        checkRefineOptions(options.refineOptions, refineName.c_str(), fields.refine);
    }
}

} // namespace tripose
