// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <cmath>
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
// (doc/studies/minimal_solvers.md) and return more poses to score.
constexpr double kLineSampleCost = 3.0;
/** Three lines of the known structure within this angle of one direction are a degenerate sample
in practice: the rotation about that direction and the translation along it are fixed only by
their differences in direction, of the order of the structure's triangulation error (several
tenths of a degree to degrees on a short baseline), and P3L returns poses that fit every line of
that direction. Exactly parallel lines P3L itself rejects. */
constexpr double kParallelLinesDeg = 5.0;

const double kParallelLinesSine = std::sin(kParallelLinesDeg * M_PI / 180.0);

bool nearlyParallel(const WorldLine* lines, int count)
{
    const Eigen::Vector3d d0 = lines[0].direction.normalized();
    for (int j = 1; j < count; ++j)
        if (d0.cross(lines[j].direction.normalized()).norm() > kParallelLinesSine)
            return false;
    return true;
}

} // namespace

HybridPoseSolver::HybridPoseSolver(const ViewSet& set, const PoseScorer& scorer, const PoseSolver& linear)
    : set_(set), scorer_(scorer), linear_(linear)
{
    for (int v = 0; v < (int)set.views.size(); ++v)
        if (set.views[v].estimated)
            cameras_.push_back(v);
    // The estimated cameras are absolute-posed on the structure of the known views: where that
    // structure's depth is poor, only a scorer that lets it slide along its rays
    // (PoseScorer::slidesKnownDepth()) judges their poses fairly.
    if (cameras_.empty() ||
        (!scorer.slidesKnownDepth() && medianTriangulationAngleDeg(set, scorer) < kWeakTriangulationAngleDeg))
        return;
    int pooled = 0;
    for (int v : cameras_)
    {
        const View& view = set.views[v];
        MixedSampling::Pool pool;
        for (int i = 0; i < set.numPoints; ++i)
            if (view.seesPoint(i) && scorer.hasKnownPoint(i))
                pool.points.push_back(i);
        for (int i = 0; i < set.numLines; ++i)
            if (view.seesLine(i) && scorer.hasKnownLine(i) && linePlaneAngleDeg(set, i) >= kWeakLinePlaneAngleDeg)
                pool.lines.push_back(i);
        const int poolIndex = (int)mixed_.pools.size();
        std::vector<WorldLine> poolLines;
        for (int i : pool.lines)
            poolLines.push_back(WorldLine::throughPoints(scorer.knownLineEnd(i, 0), scorer.knownLineEnd(i, 1)));
        // Lines of one direction alone (a board's columns) make every three-line sample degenerate.
        const bool lineTriples = poolLines.size() >= 3 && !nearlyParallel(poolLines.data(), (int)poolLines.size());
        for (int points = 3; points >= (lineTriples ? 0 : 1); --points)
            if (points <= (int)pool.points.size() && 3 - points <= (int)pool.lines.size())
                mixed_.kinds.push_back(
                    MixedSampling::Kind{ points, 3 - points, points == 3 ? 1.0 : kLineSampleCost, poolIndex });
        pooled = std::max(pooled, (int)(pool.points.size() + pool.lines.size()));
        mixed_.pools.push_back(pool);
    }
    if (!mixed_.kinds.empty() && pooled >= kMinMixedFeatures)
    {
        sampling_ = Sampling::Mixed;
        return;
    }
    // Smaller sets: three points, where there are enough of them. A rig's cameras each see part of
    // the points, so that its triples are drawn per camera from the pools (the mixed sampler with
    // the three-point kinds alone); one camera's are every distinct triple of the points it must
    // see all of (samplePool()).
    int numPoints = 0;
    for (int i = 0; i < set.numPoints; ++i)
        numPoints += scorer.hasKnownPoint(i);
    const bool enoughPoints = numPoints >= kMinPoints && 4 * numPoints >= set.numFeatures();
    if (cameras_.size() > 1 && enoughPoints)
    {
        std::vector<MixedSampling::Kind> triples;
        for (const MixedSampling::Kind& kind : mixed_.kinds)
            if (kind.points == 3)
                triples.push_back(kind);
        mixed_.kinds.swap(triples);
        if (!mixed_.kinds.empty())
        {
            sampling_ = Sampling::Mixed;
            return;
        }
    }
    mixed_ = MixedSampling();
    if (cameras_.size() == 1 && set.views[cameras_.front()].pointSeen.empty() && enoughPoints)
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
    // The first estimated camera that sees the whole sample (every sample of a pool has one).
    int camera = -1;
    for (size_t c = 0; c < cameras_.size() && camera < 0; ++c)
    {
        const View& view = set_.views[cameras_[c]];
        bool seesAll = true;
        for (int i : sample.points)
            seesAll = seesAll && view.seesPoint(i);
        for (int i : sample.lines)
            seesAll = seesAll && view.seesLine(i);
        if (seesAll)
            camera = cameras_[c];
    }
    if (camera < 0)
        return 0;
    const View& view = set_.views[camera];
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
    const size_t first = models.size();
    switch (numPoints)
    {
    case 3:
        solveP3P(bearings, points, models);
        break;
    case 2:
        solveP2P1L(bearings, points, imageLines[0], lines[0], models);
        break;
    case 1:
        solveP1P2L(bearings[0], points[0], imageLines, lines, models);
        break;
    default:
        if (!nearlyParallel(lines, 3))
            solveP3L(imageLines, lines, models);
        break;
    }
    // Poses of the camera that saw the sample, mounted at M on the estimated one: P_c = M P.
    const CameraPose& mount = view.pose;
    for (size_t m = first; m < models.size(); ++m)
    {
        CameraPose& pose = models[m];
        pose.R = mount.R.transpose() * pose.R;
        pose.t = mount.R.transpose() * (pose.t - mount.t);
    }
    return (int)(models.size() - first);
}

} // namespace tripose
