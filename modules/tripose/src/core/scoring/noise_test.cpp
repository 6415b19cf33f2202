// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "noise_test.hpp"

#include <cmath>

namespace tripose {

namespace {

// Degrees of freedom of the inlier points below which their noise estimate is too uncertain to
// judge features by: the relative standard deviation of the variance, sqrt(2 / k), is 10 % here;
// below, the true lines that an underestimate rejects cost accuracy (doc/studies/evaluation.md).
constexpr int kMinNoiseDegrees = 200;
// The threshold's share of sigma, as the documentation sets it (max(2 px, 3 sigma)).
constexpr double kThresholdSigmas = 3.0;

/** The 99.9 % quantile of chi-square with @p k degrees of freedom: tabulated for the few a point
or line has in up to five views, the Wilson-Hilferty approximation beyond (within 1 % there). */
double chiSquareQuantile999(int k)
{
    static const double table[] = { 10.828, 13.816, 16.266, 18.467, 20.515, 22.458 };
    if (k <= 6)
        return table[k - 1];
    const double a = 2.0 / (9.0 * k), z = 3.0902;
    const double c = 1.0 - a + z * std::sqrt(a);
    return k * c * c * c;
}

//! How many residuals feature @p i has: two in each view that sees it (by @p sees, View::seesPoint or View::seesLine).
int residualsOf(const ViewSet& set, int i, bool (View::*sees)(int) const)
{
    int n = 0;
    for (const View& view : set.views)
        n += (view.*sees)(i) ? 2 : 0;
    return n;
}

/** The noise variance that the inlier points of @p pointMask show (sum of their squared residuals
over their degrees of freedom), or (threshold / 3)^2 when they have fewer than kMinNoiseDegrees.
@p estimated: whether it is the former. */
double pointNoiseVariance(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                          const std::vector<unsigned char>& pointMask, bool* estimated = nullptr)
{
    double squares = 0;
    int degrees = 0;
    for (size_t i = 0; i < pointResiduals.size(); ++i)
    {
        if (!pointMask[i])
            continue;
        const int n = residualsOf(set, (int)i, &View::seesPoint);
        if (n <= 3)
            continue;
        squares += pointResiduals[i] * pointResiduals[i] * n;
        degrees += n - 3;
    }
    const double sigma = threshold / kThresholdSigmas;
    if (estimated)
        *estimated = degrees >= kMinNoiseDegrees;
    return degrees >= kMinNoiseDegrees ? squares / degrees : sigma * sigma;
}

/** Clears the features of @p mask whose squared residuals exceed the 99.9 % quantile of chi-square
with their n - @p parameters degrees of freedom times @p variance; returns how many. */
int rejectAbove(const ViewSet& set, double variance, int parameters, bool (View::*sees)(int) const,
                const std::vector<double>& residuals, std::vector<unsigned char>& mask)
{
    int rejected = 0;
    for (size_t i = 0; i < residuals.size(); ++i)
    {
        if (!mask[i])
            continue;
        const int n = residualsOf(set, (int)i, sees);
        if (n <= parameters)
            continue;
        if (residuals[i] * residuals[i] * n > chiSquareQuantile999(n - parameters) * variance)
        {
            mask[i] = 0;
            ++rejected;
        }
    }
    return rejected;
}

} // namespace

int rejectLinesAbovePointNoise(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                               const std::vector<unsigned char>& pointMask, const std::vector<double>& lineResiduals,
                               std::vector<unsigned char>& lineMask)
{
    return rejectAbove(set, pointNoiseVariance(set, threshold, pointResiduals, pointMask), 4, &View::seesLine,
                       lineResiduals, lineMask);
}

int rejectPointsAboveNoise(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                           std::vector<unsigned char>& pointMask)
{
    bool estimated = false;
    const double variance = pointNoiseVariance(set, threshold, pointResiduals, pointMask, &estimated);
    return estimated ? rejectAbove(set, variance, 3, &View::seesPoint, pointResiduals, pointMask) : 0;
}

} // namespace tripose
