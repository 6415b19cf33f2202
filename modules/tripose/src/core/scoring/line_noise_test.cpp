// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "line_noise_test.hpp"

#include <cmath>

namespace tripose {

namespace {

// Degrees of freedom of the inlier points below which their noise estimate is too uncertain to
// judge lines by: the relative standard deviation of the variance, sqrt(2 / k), is 10 % here. At 50
// (10 points in four views, 20 %) the lines that an underestimate rejected cost 1 % of the mean
// rotation error over 500 rig scenes of 10 points + 10 lines.
constexpr int kMinNoiseDegrees = 200;
// The threshold's share of sigma, as the documentation sets it (max(2 px, 3 sigma)).
constexpr double kThresholdSigmas = 3.0;

/** The 99.9 % quantile of chi-square with @p k degrees of freedom: tabulated for the few a line
has in up to five views, the Wilson-Hilferty approximation beyond (within 1 % there). */
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

} // namespace

int rejectLinesAbovePointNoise(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                               const std::vector<unsigned char>& pointMask, const std::vector<double>& lineResiduals,
                               std::vector<unsigned char>& lineMask)
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
    const double variance = degrees >= kMinNoiseDegrees ? squares / degrees : sigma * sigma;
    int rejected = 0;
    for (size_t i = 0; i < lineResiduals.size(); ++i)
    {
        if (!lineMask[i])
            continue;
        const int n = residualsOf(set, (int)i, &View::seesLine);
        if (n <= 4)
            continue;
        if (lineResiduals[i] * lineResiduals[i] * n > chiSquareQuantile999(n - 4) * variance)
        {
            lineMask[i] = 0;
            ++rejected;
        }
    }
    return rejected;
}

} // namespace tripose
