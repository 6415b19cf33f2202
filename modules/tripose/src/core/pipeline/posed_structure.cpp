// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "posed_structure.hpp"

#include <algorithm>
#include <limits>

#include "../geometry/feature_refit.hpp"
#include "../support/error.hpp"

namespace tripose {

PosedStructure triangulateStructure(const ViewSet& set)
{
    const int numViews = (int)set.views.size();
    std::vector<CameraPose> poses;
    for (const View& view : set.views)
    {
        TRIPOSE_ASSERT(!view.estimated);
        poses.push_back(view.pose);
    }
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const Eigen::Vector3d none = Eigen::Vector3d::Constant(nan);
    // Same bound as the scorer's: at or behind a camera, relative to the scene's scale.
    const double minDepth = 1e-9 * set.knownBaseline();

    PosedStructure out;
    out.points.assign(set.numPoints, none);
    out.lineEnds.assign(2 * set.numLines, none);
    out.pointErrors.assign((size_t)set.numPoints * numViews, nan);
    out.lineErrors.assign((size_t)set.numLines * numViews, nan);
    std::vector<Eigen::Vector2d> residuals;
    for (int i = 0; i < set.numPoints; ++i)
    {
        Eigen::Vector3d X;
        const bool fits = refitPoint(set, poses.data(), i, minDepth, X, residuals);
        if (fits)
        {
            out.points[i] = X;
            ++out.numWithStructure;
        }
        for (int v = 0; v < numViews; ++v)
            if (set.views[v].seesPoint(i))
                out.pointErrors[(size_t)i * numViews + v] = fits ? residuals[v].norm() : inf;
    }
    for (int i = 0; i < set.numLines; ++i)
    {
        PluckerLine L;
        const bool fits = refitLine(set, poses.data(), i, L, residuals);
        int first = -1;
        for (int v = 0; v < numViews; ++v)
        {
            if (!set.views[v].seesLine(i))
                continue;
            if (first < 0)
                first = v;
            out.lineErrors[(size_t)i * numViews + v] =
                fits ? std::max(std::abs(residuals[v](0)), std::abs(residuals[v](1))) : inf;
        }
        if (fits)
        {
            lineEndsSeenBy(set.views[first], poses[first], i, L, out.lineEnds[2 * i], out.lineEnds[2 * i + 1]);
            ++out.numWithStructure;
        }
    }
    return out;
}

} // namespace tripose
