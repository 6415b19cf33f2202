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

double medianTriangulationAngleDeg(const ViewSet& set, const PoseScorer& scorer)
{
    std::vector<Eigen::Vector3d> centres;
    for (const View& view : set.views)
        if (!view.estimated && centres.size() < 2)
            centres.push_back(view.pose.centre());
    if (centres.size() < 2)
        return 0.0;
    std::vector<double> angles;
    angles.reserve(set.numPoints + 2 * set.numLines);
    const auto addAngle = [&](const Eigen::Vector3d& X) {
        const Eigen::Vector3d a = X - centres[0], b = X - centres[1];
        angles.push_back(std::atan2(a.cross(b).norm(), a.dot(b)));
    };
    for (int i = 0; i < set.numPoints; ++i)
        if (scorer.hasKnownPoint(i))
            addAngle(scorer.knownPoint(i));
    for (int i = 0; i < set.numLines; ++i)
        if (scorer.hasKnownLine(i))
            for (int end = 0; end < 2; ++end)
                addAngle(scorer.knownLineEnd(i, end));
    if (angles.empty())
        return 0.0;
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    return angles[angles.size() / 2] * 180.0 / M_PI;
}

double linePlaneAngleDeg(const ViewSet& set, int line)
{
    Eigen::Vector3d normals[2];
    int found = 0;
    for (size_t v = 0; v < set.views.size() && found < 2; ++v)
    {
        const View& view = set.views[v];
        if (!view.estimated && view.seesLine(line))
            normals[found++] = view.pose.R.transpose() * view.calibratedLines[line];
    }
    if (found < 2)
        return 0.0;
    return std::atan2(normals[0].cross(normals[1]).norm(), std::abs(normals[0].dot(normals[1]))) * 180.0 / M_PI;
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
