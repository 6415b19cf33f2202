// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <cmath>
#include <vector>

#include "distinct_minima.hpp"

namespace tripose {

bool sameMinimum(const CameraPose& a, const CameraPose& b, double tolerance)
{
    const double scale = std::max(1e-300, std::max(a.t.norm(), b.t.norm()));
    return (a.R - b.R).norm() <= tolerance && (a.t - b.t).norm() <= tolerance * scale;
}

std::vector<LocalMinimum> distinctMinima(std::vector<LocalMinimum> minima, double tolerance)
{
    std::stable_sort(minima.begin(), minima.end(),
                     [](const LocalMinimum& a, const LocalMinimum& b) { return a.betterThan(b); });
    std::vector<LocalMinimum> distinct;
    for (const LocalMinimum& m : minima)
    {
        if (!m.finite() || m.used < minima.front().used)
            continue;
        bool repeated = false;
        for (const LocalMinimum& d : distinct)
            repeated = repeated || sameMinimum(d.pose, m.pose, tolerance);
        if (!repeated)
            distinct.push_back(m);
    }
    return distinct;
}

bool withinNoise(const LocalMinimum& best, const LocalMinimum& other)
{
    const double variance = best.noiseVariance();
    if (!std::isfinite(variance) || other.used != best.used)
        return false;
    return other.squares() - best.squares() < kChiSquare6Quantile95 * variance;
}

} // namespace tripose
