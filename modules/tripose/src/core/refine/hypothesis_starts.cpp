// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/combinations.hpp"
#include "../support/random.hpp"
#include "hypothesis_starts.hpp"
#include "ml_refinement.hpp"

namespace tripose {

namespace {

// Rotations closer than this (Frobenius norm of the difference, about 4 degrees) give starts in the
// same basin: the centre-direction starts already cover such a neighbourhood.
constexpr double kDistinctRotation = 0.1;

struct Hypothesis
{
    CameraPose pose;
    double rms;
    int residuals;
};

} // namespace

void appendHypothesisStarts(const ViewSet& set, const PoseSolver& solver, const FeatureSubset& features,
                            std::vector<CameraPose>& starts)
{
    const int k = solver.sampleSize();
    const int n = features.size();
    if (solver.mixedSampling() || k <= 0 || n < k)
        return;
    const int numPoints = (int)features.points.size();
    const auto subsetOf = [&](const std::vector<int>& idx, FeatureSubset& sample) {
        sample.clear();
        for (int f : idx)
        {
            if (f < numPoints)
                sample.points.push_back(features.points[f]);
            else
                sample.lines.push_back(features.lines[f - numPoints]);
        }
    };
    // No iteration: the cost at the triangulated structure only ranks the hypotheses.
    RefineOptions scoring;
    scoring.maxIterations = 0;
    std::vector<Hypothesis> hypotheses;
    std::vector<CameraPose> poses;
    FeatureSubset sample;
    const auto solve = [&](const std::vector<int>& idx) {
        subsetOf(idx, sample);
        poses.clear();
        solver.estimateMinimal(sample, true, poses);
        for (const CameraPose& pose : poses)
        {
            if (!pose.allFinite())
                continue;
            CameraPose p = pose;
            const RefinementSummary s = refinePoseAndStructure(set, p, scoring, &features.points, &features.lines);
            if (std::isfinite(s.finalRms))
                hypotheses.push_back(Hypothesis{ pose, s.finalRms, s.residuals });
        }
    };
    std::vector<int> idx(k);
    if (combinationCount(n, k, kMaxHypothesisSamples) <= kMaxHypothesisSamples)
    {
        for (int i = 0; i < k; ++i)
            idx[i] = i;
        do
            solve(idx);
        while (nextCombination(idx, n));
    }
    else
    {
        Random random(0x5eed);
        for (int s = 0; s < kMaxHypothesisSamples; ++s)
        {
            // k distinct features by rejection: k is a handful, n at least a few times more.
            for (int i = 0; i < k; ++i)
            {
                int f;
                do
                    f = random.uniform(0, n);
                while (std::find(idx.begin(), idx.begin() + i, f) != idx.begin() + i);
                idx[i] = f;
            }
            solve(idx);
        }
    }
    // A pose that leaves residuals out (features behind a view) scores over fewer of them.
    int most = 0;
    for (const Hypothesis& h : hypotheses)
        most = std::max(most, h.residuals);
    std::stable_sort(hypotheses.begin(), hypotheses.end(),
                     [](const Hypothesis& a, const Hypothesis& b) { return a.rms < b.rms; });
    int added = 0;
    for (const Hypothesis& h : hypotheses)
    {
        if (added >= kMaxHypothesisStarts)
            break;
        if (h.residuals < most)
            continue;
        bool distinct = true;
        for (const CameraPose& s : starts)
            distinct = distinct && (s.R - h.pose.R).norm() > kDistinctRotation;
        if (!distinct)
            continue;
        starts.push_back(h.pose);
        ++added;
    }
}

} // namespace tripose
