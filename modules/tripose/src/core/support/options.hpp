// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_SUPPORT_OPTIONS_HPP
#define TRIPOSE_CORE_SUPPORT_OPTIONS_HPP

#include <cstdint>

namespace tripose {

//! Loss applied to the reprojection error of each observation (a point, or a segment's two end points, in one view).
enum class Loss : int
{
    Squared = 0, //!< Least squares: the maximum-likelihood estimate under Gaussian noise.
    Huber = 1,   //!< Quadratic up to RefineOptions::lossScale pixels, linear beyond.
    Cauchy = 2   //!< c^2 log(1 + e^2 / c^2), c = RefineOptions::lossScale: gross errors barely count.
};

//! Options of the maximum-likelihood refinement; the adapters' parameter structs convert to these.
struct RefineOptions
{
    int maxIterations = 30;   //!< Levenberg-Marquardt steps, accepted or rejected (> 0).
    Loss loss = Loss::Squared;
    double lossScale = 1.0;   //!< Scale of the robust loss in pixels (> 0, finite).
    double tolerance = 1e-10; //!< Stop when an accepted step lowers the cost by less than this fraction (>= 0).
};

//! Options of the robust estimators.
struct RansacOptions
{
    double threshold = 2.0;         //!< Inlier threshold in pixels (> 0).
    double confidence = 0.999;      //!< Probability, in (0, 1), of drawing an all-inlier sample.
    int maxIterations = 10000;      //!< Upper bound on the number of samples (> 0).
    bool localOptimization = true;  //!< Re-estimate from the inliers of every new best model.
    bool refine = true;             //!< Finish with the maximum-likelihood refinement over the inliers.
    RefineOptions refineOptions;    //!< Options of that refinement.
    uint64_t seed = 0;              //!< Seed of the sampler: the same seed gives the same result.
    /** Fewest inliers of a returned pose (>= 0); an estimate with fewer is no pose. Chance matches
    agree with a pose in numbers up to about a dozen (doc/conventions.md, "Results and errors"). */
    int minInliers = 15;
    //! Reject the minimal samples' poses early by the sequential probability ratio test
    //! (scoring/sequential_test.hpp). Not in the public parameters: for tests and measurements.
    bool sequentialTest = true;
};

/** The checks of the options, which each adapter runs on what its caller passed (the pipelines
expect valid options): Error(BadArgument) naming the first field out of range as "<name>.<field>",
or "<field>" alone when @p name is empty. @p fieldNames gives the fields' names in the caller's
language; the defaults are the C++ API's (RansacParams, RefineParams).
*/
struct RefineOptionNames
{
    const char* maxIterations = "maxIterations";
    const char* loss = "loss";
    const char* lossValues = "LOSS_SQUARED (0), LOSS_HUBER (1) or LOSS_CAUCHY (2)";
    const char* lossScale = "lossScale";
    const char* tolerance = "tolerance";
};
void checkRefineOptions(const RefineOptions& options, const char* name = "params",
                        const RefineOptionNames& fieldNames = RefineOptionNames());

struct RansacOptionNames
{
    const char* threshold = "threshold";
    const char* confidence = "confidence";
    const char* maxIterations = "maxIterations";
    const char* minInliers = "minInliers";
    const char* refineOptions = "refineParams";
    RefineOptionNames refine;
};
void checkRansacOptions(const RansacOptions& options, const char* name = "params",
                        const RansacOptionNames& fieldNames = RansacOptionNames());

} // namespace tripose

#endif // TRIPOSE_CORE_SUPPORT_OPTIONS_HPP
