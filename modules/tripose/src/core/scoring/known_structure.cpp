// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <Eigen/Dense>

#include "../geometry/plane_fit.hpp"
#include "known_structure.hpp"

namespace tripose {

namespace {

// Rounds of trimPlaneFit() before judging the thickness: noisy planar structure triangulated from
// the known pair has a few positions far off its plane.
constexpr int kThicknessTrimRounds = 3;

} // namespace

namespace {

//! Largest angle (rad) between two of the directions @p d (unit vectors): the widest pair.
double widestAngle(const std::vector<Eigen::Vector3d>& d, bool unsignedDirections)
{
    double smallestCos = 1.0;
    for (size_t a = 0; a < d.size(); ++a)
        for (size_t b = a + 1; b < d.size(); ++b)
        {
            const double c = d[a].dot(d[b]);
            smallestCos = std::min(smallestCos, unsignedDirections ? std::abs(c) : c);
        }
    return std::acos(std::max(-1.0, std::min(1.0, smallestCos)));
}

} // namespace

double medianTriangulationAngleDeg(const ViewSet& set, const PoseScorer& scorer)
{
    std::vector<int> known;
    for (int v = 0; v < (int)set.views.size(); ++v)
        if (!set.views[v].estimated)
            known.push_back(v);
    if (known.size() < 2)
        return 0.0;
    std::vector<double> angles;
    angles.reserve(set.numPoints + 2 * set.numLines);
    std::vector<Eigen::Vector3d> rays;
    // The widest angle between the rays to X from the known views that see the feature: the
    // structure is triangulated from all of them.
    const auto addAngle = [&](const Eigen::Vector3d& X, bool point, int i) {
        rays.clear();
        for (int v : known)
            if (point ? set.views[v].seesPoint(i) : set.views[v].seesLine(i))
                rays.push_back((X - set.views[v].pose.centre()).normalized());
        if (rays.size() >= 2)
            angles.push_back(widestAngle(rays, false));
    };
    for (int i = 0; i < set.numPoints; ++i)
        if (scorer.hasKnownPoint(i))
            addAngle(scorer.knownPoint(i), true, i);
    for (int i = 0; i < set.numLines; ++i)
        if (scorer.hasKnownLine(i))
            for (int end = 0; end < 2; ++end)
                addAngle(scorer.knownLineEnd(i, end), false, i);
    if (angles.empty())
        return 0.0;
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    return angles[angles.size() / 2] * 180.0 / M_PI;
}

double linePlaneAngleDeg(const ViewSet& set, int line)
{
    std::vector<Eigen::Vector3d> normals;
    for (const View& view : set.views)
        if (!view.estimated && view.seesLine(line))
            normals.push_back((view.pose.R.transpose() * view.calibratedLines[line]).normalized());
    if (normals.size() < 2)
        return 0.0;
    return widestAngle(normals, true) * 180.0 / M_PI;
}

double structureThickness(const ViewSet& set, const PoseScorer& scorer)
{
    std::vector<Eigen::Vector3d> X;
    for (int i = 0; i < set.numPoints; ++i)
        if (scorer.hasKnownPoint(i))
            X.push_back(scorer.knownPoint(i));
    for (int i = 0; i < set.numLines; ++i)
        if (scorer.hasKnownLine(i))
            for (int end = 0; end < 2; ++end)
                X.push_back(scorer.knownLineEnd(i, end));
    PlaneAccumulator all;
    for (const Eigen::Vector3d& x : X)
        all.add(x);
    Plane plane;
    if (!all.fit(plane) || !trimPlaneFit(X, kThicknessTrimRounds, plane))
        return 1.0;
    const Eigen::Vector3d values = plane.extents.cwiseMax(0.0); // ascending
    if (!(values(2) > 0))
        return 1.0;
    return std::sqrt(values(0) / values(2));
}

} // namespace tripose
