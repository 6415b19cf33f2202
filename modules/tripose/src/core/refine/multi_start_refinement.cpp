// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "multi_start_refinement.hpp"

namespace tripose {

namespace {

// Re-triangulation settles in one or two rounds when it changes anything; the bound only guards
// against cycling between two structures of equal cost.
constexpr int kMaxRetriangulations = 5;
// RMS changes below this (px) are rounding, not a different minimum.
constexpr double kSameRms = 1e-9;
// searchBasins() repeats the centre-direction starts around the best minimum when its rotation
// differs from the first start's by more than this (Frobenius norm of the difference, about 0.4
// degrees): closer, the starts would be the same ones again.
constexpr double kRecentreRotation = 1e-2;
// searchBasins() refines from its starts with at least this many iterations: in a narrow scene the
// cost creeps along valleys for tens of iterations, and at the default 30 a start stopped short of
// its minimum ranks above or below the others by where it stopped (doc/studies/accuracy.md, "Narrow known
// baselines: the lowest minimum").
constexpr int kSearchIterations = 100;
// settleMinima(): the lowest minima of a search, at most kMaxSettled of them (distinct rotations)
// and at most kSettleCostFactor times the best cost, are refined again from their poses with
// kSettleFactor times the iterations, the structure re-triangulated there.
constexpr int kSettleFactor = 3;
constexpr int kMaxSettled = 8;
constexpr double kSettleCostFactor = 2.0;
// Unsettled minima whose rotations are closer than this (Frobenius norm, about 0.04 degrees) are
// settled once.
constexpr double kSameSettledRotation = 1e-3;


int countUsed(const RefinedStructure& s)
{
    int used = 0;
    for (unsigned char u : s.pointUsed)
        used += u;
    // A line that settled behind a view, where its residuals cannot see it, explains nothing.
    for (size_t k = 0; k < s.lineUsed.size(); ++k)
        used += s.lineUsed[k] && s.lineInFront[k];
    return used;
}

//! Pose and structure parameters of the refinement: one pose, a point's three coordinates, a line's
//! four (orthonormal representation).
int countParameters(const RefinedStructure& s)
{
    int parameters = 6;
    for (unsigned char u : s.pointUsed)
        parameters += 3 * u;
    for (unsigned char u : s.lineUsed)
        parameters += 4 * u;
    return parameters;
}

} // namespace

LocalMinimum refineRetriangulating(const ViewSet& set, const CameraPose& start, const RefineOptions& params,
                                   const std::vector<int>* pointIndices, const std::vector<int>* lineIndices)
{
    LocalMinimum best;
    CameraPose pose = start;
    for (int round = 0; round < kMaxRetriangulations; ++round)
    {
        RefinedStructure structure;
        const RefinementSummary summary =
            refinePoseAndStructure(set, pose, params, pointIndices, lineIndices, &structure);
        LocalMinimum current;
        current.pose = pose;
        current.rms = summary.finalRms;
        current.used = countUsed(structure);
        current.residuals = summary.residuals;
        current.parameters = countParameters(structure);
        if (!current.finite())
            break;
        const bool settled = round > 0 && current.used == best.used && std::abs(current.rms - best.rms) <= kSameRms;
        if (current.betterThan(best))
            best = current;
        if (settled)
            break;
    }
    return best;
}

void centreDirectionStarts(const ViewSet& set, const CameraPose& pose, std::vector<CameraPose>& starts)
{
    Eigen::Vector3d pivot = Eigen::Vector3d::Zero(), other = Eigen::Vector3d::Zero();
    int known = 0;
    for (const View& view : set.views)
    {
        if (view.estimated)
            continue;
        if (known == 0)
            pivot = view.pose.centre();
        else if (known == 1)
            other = view.pose.centre();
        ++known;
    }
    double distance = (pose.centre() - pivot).norm();
    // At the pivot itself the direction is meaningless; the known pair's baseline sets the scale.
    if (!(distance > 0) || !std::isfinite(distance))
        distance = (other - pivot).norm();
    if (!(distance > 0) || !std::isfinite(distance))
        return;
    for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
            for (int c = -1; c <= 1; ++c)
            {
                if (a == 0 && b == 0 && c == 0)
                    continue;
                const Eigen::Vector3d centre = pivot + distance * Eigen::Vector3d(a, b, c).normalized();
                CameraPose start;
                start.R = pose.R;
                start.t = -(pose.R * centre);
                starts.push_back(start);
            }
}

LocalMinimum refineFromStarts(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& params,
                              const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                              std::vector<LocalMinimum>* minima)
{
    LocalMinimum best;
    for (const CameraPose& start : starts)
    {
        if (!start.allFinite())
            continue;
        const LocalMinimum m = refineRetriangulating(set, start, params, pointIndices, lineIndices);
        if (!m.finite())
            continue;
        if (minima)
            minima->push_back(m);
        if (m.betterThan(best))
            best = m;
    }
    return best;
}

namespace {

/** The minima of a search, refined to their ends: each of @p minima that could be the lowest (see
the constants above) is replaced by the minimum that refineRetriangulating() reaches from its pose
with kSettleFactor times the iterations. Two things change there: a minimum that stopped on the
iteration limit goes on along its valley (in narrow scenes a minimum ranked above the best at the
iteration limit can be the lowest at convergence; doc/studies/accuracy.md), and one that the
search's structure held (a line kept in front, a point at another depth) moves to the minimum that
refinement of its pose alone reaches, which is what a refinement of the returned pose finds. Returns
the best of the result; @p minima holds the settled minima in place of those. A minimum already
settled costs a few iterations. */
LocalMinimum settleMinima(const ViewSet& set, std::vector<LocalMinimum>& minima, const RefineOptions& params,
                          const std::vector<int>* pointIndices, const std::vector<int>* lineIndices)
{
    LocalMinimum best;
    for (const LocalMinimum& m : minima)
        if (m.betterThan(best))
            best = m;
    if (!best.finite())
        return best;
    std::vector<LocalMinimum> order = minima;
    std::stable_sort(order.begin(), order.end(),
                     [](const LocalMinimum& a, const LocalMinimum& b) { return a.betterThan(b); });
    RefineOptions longer = params;
    longer.maxIterations = kSettleFactor * params.maxIterations;
    std::vector<LocalMinimum> settled, kept;
    std::vector<CameraPose> tried;
    LocalMinimum lowest;
    for (const LocalMinimum& m : order)
    {
        bool repeated = false;
        for (const CameraPose& t : tried)
            repeated = repeated || (t.R - m.pose.R).norm() <= kSameSettledRotation;
        if (repeated)
            continue;
        const bool contender = (int)tried.size() < kMaxSettled && m.used >= best.used &&
                               m.squares() <= kSettleCostFactor * best.squares();
        if (!contender)
        {
            kept.push_back(m);
            if (m.betterThan(lowest))
                lowest = m;
            continue;
        }
        tried.push_back(m.pose);
        const LocalMinimum s = refineRetriangulating(set, m.pose, longer, pointIndices, lineIndices);
        if (s.finite())
        {
            settled.push_back(s);
            if (s.betterThan(lowest))
                lowest = s;
        }
    }
    kept.insert(kept.end(), settled.begin(), settled.end());
    minima.swap(kept);
    return lowest;
}

} // namespace

LocalMinimum searchBasins(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& options,
                          const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                          std::vector<LocalMinimum>* minima)
{
    RefineOptions params = options;
    params.maxIterations = std::max(params.maxIterations, kSearchIterations);
    if (starts.empty())
        return LocalMinimum();
    std::vector<LocalMinimum> reached;
    std::vector<CameraPose> first = starts;
    centreDirectionStarts(set, starts.front(), first);
    LocalMinimum best = refineFromStarts(set, first, params, pointIndices, lineIndices, &reached);
    if (best.finite() && (best.pose.R - starts.front().R).norm() > kRecentreRotation)
    {
        std::vector<CameraPose> second;
        centreDirectionStarts(set, best.pose, second);
        refineFromStarts(set, second, params, pointIndices, lineIndices, &reached);
    }
    best = settleMinima(set, reached, params, pointIndices, lineIndices);
    if (minima)
        minima->insert(minima->end(), reached.begin(), reached.end());
    return best;
}

LocalMinimum searchFromStarts(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& params,
                              const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                              std::vector<LocalMinimum>* minima)
{
    std::vector<LocalMinimum> reached;
    refineFromStarts(set, starts, params, pointIndices, lineIndices, &reached);
    const LocalMinimum best = settleMinima(set, reached, params, pointIndices, lineIndices);
    if (minima)
        minima->insert(minima->end(), reached.begin(), reached.end());
    return best;
}

} // namespace tripose
