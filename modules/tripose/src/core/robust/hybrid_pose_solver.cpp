// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "../minimal/p3p.hpp"
#include "../scoring/known_structure.hpp"
#include "hybrid_pose_solver.hpp"

namespace tripose {


HybridPoseSolver::HybridPoseSolver(const ViewSet& set, const PoseScorer& scorer, const PoseSolver& linear)
    : set_(set), scorer_(scorer), linear_(linear)
{
    int estimated = 0;
    for (const View& view : set.views)
        estimated += view.estimated;
    int withStructure = 0;
    for (int i = 0; i < set.numPoints; ++i)
        withStructure += scorer.hasKnownPoint(i);
    // One estimated camera that sees every point: the three-view problem.
    pointSamples_ = estimated == 1 && set.views.back().estimated && set.views.back().pointSeen.empty() &&
                    withStructure >= kMinPoints && 4 * withStructure >= set.numFeatures() &&
                    medianTriangulationAngleDeg(set, scorer) >= kWeakTriangulationAngleDeg;
}

int HybridPoseSolver::estimateMinimal(const FeatureSubset& sample, bool exhaustive,
                                      std::vector<CameraPose>& models) const
{
    if (!pointSamples_)
        return linear_.estimateMinimal(sample, exhaustive, models);
    if (sample.points.size() != 3 || !sample.lines.empty())
        return 0;
    const View& view = set_.views.back();
    Eigen::Vector3d bearings[3], points[3];
    for (int k = 0; k < 3; ++k)
    {
        const int i = sample.points[k];
        if (!scorer_.hasKnownPoint(i))
            return 0;
        points[k] = scorer_.knownPoint(i);
        bearings[k] = view.calibratedPoints[i].homogeneous();
    }
    return solveP3P(bearings, points, models);
}

} // namespace tripose
