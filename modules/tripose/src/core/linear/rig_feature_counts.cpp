// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "rig_feature_counts.hpp"

namespace tripose {

int rigKernelDimension(const RigFeatureCounts& c)
{
    const int pb = c.pointsBoth, lb = c.linesBoth, ps = c.pointsSingle(), ls = c.linesSingle();
    const int in3 = c.both() + c.pointsOnly3 + c.linesOnly3;
    const int in4 = c.both() + c.pointsOnly4 + c.linesOnly4;
    if (in3 == 0 || in4 == 0)
        return std::max(1, 12 - 2 * (ps + ls));
    if (pb == 0)
        return std::max(0, 12 - 2 * ps - 4 * lb - 2 * ls);
    if (pb == 1)
        return std::max(0, 9 - 2 * ps - 4 * lb - 2 * ls + (lb >= 2 ? 1 : 0));
    if (pb == 2)
    {
        const int s = std::max(0, 3 - ls - 2 * lb);
        return std::max(0, 2 * s - ps * std::min(s, 2));
    }
    if (pb == 3)
        return std::max(0, 3 - 2 * ps - ls - 2 * lb);
    return 0;
}

int rigSolutionCount(const RigFeatureCounts& c, int kernelDimension)
{
    if (kernelDimension >= 7 || c.total() == 0)
        return 0;
    if (c.total() == 2 && c.both() == 2)
        return c.linesBoth == 0 ? 0 : 2;
    if (kernelDimension == 6)
        return (c.both() > 0 || (c.total() == 3 && c.points() == 2)) ? 4 : 8;
    return 1;
}

} // namespace tripose
