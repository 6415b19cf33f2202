// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "options.hpp"

#include <cmath>

#include "error.hpp"

#include <string>

namespace tripose {

namespace {

//! "<name>.<field>", or the field alone where the caller names its options one by one (@p name empty).
std::string fieldName(const char* name, const char* field)
{
    return name && *name ? formatString("%s.%s", name, field) : std::string(field);
}

} // namespace

void checkRefineOptions(const RefineOptions& options, const char* name, const RefineOptionNames& fields)
{
    if (!(options.maxIterations > 0))
        fail(ErrorCode::BadArgument, "%s must be positive (got %d)", fieldName(name, fields.maxIterations).c_str(),
             options.maxIterations);
    if (options.loss != Loss::Squared && options.loss != Loss::Huber && options.loss != Loss::Cauchy)
        fail(ErrorCode::BadArgument, "%s must be %s (got %d)", fieldName(name, fields.loss).c_str(), fields.lossValues,
             (int)options.loss);
    if (!(options.lossScale > 0) || !std::isfinite(options.lossScale))
        fail(ErrorCode::BadArgument, "%s must be a positive, finite number of pixels (got %g)",
             fieldName(name, fields.lossScale).c_str(), options.lossScale);
    if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
        fail(ErrorCode::BadArgument, "%s must be finite and >= 0 (got %g)", fieldName(name, fields.tolerance).c_str(),
             options.tolerance);
}

void checkRansacOptions(const RansacOptions& options, const char* name, const RansacOptionNames& fields)
{
    if (!(options.threshold > 0) || !std::isfinite(options.threshold))
        fail(ErrorCode::BadArgument, "%s must be a positive number of pixels, got %g", fieldName(name, fields.threshold).c_str(),
             options.threshold);
    if (!(options.confidence > 0 && options.confidence < 1))
        fail(ErrorCode::BadArgument, "%s must be in (0, 1), got %g", fieldName(name, fields.confidence).c_str(),
             options.confidence);
    if (options.maxIterations <= 0)
        fail(ErrorCode::BadArgument, "%s must be positive, got %d", fieldName(name, fields.maxIterations).c_str(),
             options.maxIterations);
    if (options.minInliers < 0)
        fail(ErrorCode::BadArgument, "%s must be >= 0, got %d", fieldName(name, fields.minInliers).c_str(),
             options.minInliers);
    if (options.refine)
    {
        const std::string refineName = fields.refineOptions && *fields.refineOptions ? fieldName(name, fields.refineOptions) : std::string(name);
        checkRefineOptions(options.refineOptions, refineName.c_str(), fields.refine);
    }
}

} // namespace tripose
