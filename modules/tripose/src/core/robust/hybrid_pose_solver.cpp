// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <vector>

#include "../minimal/p1p2l.hpp"
#include "../minimal/p2p1l.hpp"
#include "../minimal/p3l.hpp"
#include "../minimal/p3p.hpp"
#include "../scoring/known_structure.hpp"
#include "hybrid_pose_solver.hpp"

namespace tripose {

namespace {

// Time of a sample with lines relative to a P3P sample: the line solvers take three times as long
// (doc/minimal_solvers.md) and return more poses to score.
constexpr double kLineSampleCost = 3.0;

} // namespace

HybridPoseSolver::HybridPoseSolver(const ViewSet& set, const PoseScorer& scorer, const PoseSolver& linear)
    : set_(set), scorer_(scorer), linear_(linear)
{
    int estimated = 0;
    for (const View& view : set.views)
        estimated += view.estimated;
    // One estimated camera, the last view (the three-view problem; registration against several
    // known views), absolute-posed on the structure of the known views.
    const View& last = set.views.back();
    if (estimated != 1 || !last.estimated || medianTriangulationAngleDeg(set, scorer) < kWeakTriangulationAngleDeg)
        return;
    for (int i = 0; i < set.numPoints; ++i)
        if (last.seesPoint(i) && scorer.hasKnownPoint(i))
            mixed_.points.push_back(i);
    for (int i = 0; i < set.numLines; ++i)
        if (last.seesLine(i) && scorer.hasKnownLine(i) && linePlaneAngleDeg(set, i) >= kWeakLinePlaneAngleDeg)
            mixed_.lines.push_back(i);
    const int numPoints = (int)mixed_.points.size(), numLines = (int)mixed_.lines.size();
    if (numPoints + numLines >= kMinMixedFeatures)
    {
        sampling_ = Sampling::Mixed;
        for (int points = 3; points >= 0; --points)
            if (points <= numPoints && 3 - points <= numLines)
                mixed_.kinds.push_back(MixedSampling::Kind{ points, 3 - points, points == 3 ? 1.0 : kLineSampleCost });
    }
    // Point triples are drawn from every point (samplePool()): the estimated view must see them all.
    else if (last.pointSeen.empty() && numPoints >= kMinPoints && 4 * numPoints >= set.numFeatures())
        sampling_ = Sampling::PointTriples;
}

int HybridPoseSolver::estimateMinimal(const FeatureSubset& sample, bool exhaustive,
                                      std::vector<CameraPose>& models) const
{
    if (sampling_ == Sampling::Linear)
        return linear_.estimateMinimal(sample, exhaustive, models);
    const int numPoints = (int)sample.points.size(), numLines = (int)sample.lines.size();
    if (numPoints + numLines != 3 || (sampling_ == Sampling::PointTriples && numLines != 0))
        return 0;
    const View& view = set_.views.back();
    Eigen::Vector3d bearings[3], points[3], imageLines[3];
    WorldLine lines[3];
    for (int k = 0; k < numPoints; ++k)
    {
        const int i = sample.points[k];
        if (!scorer_.hasKnownPoint(i))
            return 0;
        points[k] = scorer_.knownPoint(i);
        bearings[k] = view.calibratedPoints[i].homogeneous();
    }
    for (int k = 0; k < numLines; ++k)
    {
        const int i = sample.lines[k];
        if (!scorer_.hasKnownLine(i))
            return 0;
        lines[k] = WorldLine::throughPoints(scorer_.knownLineEnd(i, 0), scorer_.knownLineEnd(i, 1));
        imageLines[k] = view.calibratedLines[i];
    }
    switch (numPoints)
    {
    case 3:
        return solveP3P(bearings, points, models);
    case 2:
        return solveP2P1L(bearings, points, imageLines[0], lines[0], models);
    case 1:
        return solveP1P2L(bearings[0], points[0], imageLines, lines, models);
    default:
        return solveP3L(imageLines, lines, models);
    }
}

} // namespace tripose
