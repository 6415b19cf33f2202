// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "pose_pipelines.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "../linear/rig_pose_solver.hpp"
#include "../refine/distinct_minima.hpp"
#include "../refine/hypothesis_starts.hpp"
#include "../refine/multi_start_refinement.hpp"
#include "../refine/multi_start_refiner.hpp"
#include "../robust/hybrid_pose_solver.hpp"
#include "../scoring/candidate_ranking.hpp"
#include "../scoring/known_structure.hpp"

namespace tripose {

namespace {

std::vector<ScoredPose> scoredPoses(const std::vector<LocalMinimum>& minima)
{
    std::vector<ScoredPose> out;
    for (const LocalMinimum& m : minima)
    {
        ScoredPose p;
        p.pose = m.pose;
        p.rms = m.rms;
        out.push_back(p);
    }
    return out;
}

/** Refines every candidate over every view and, when the problem has several basins
(@p severalBasins: a narrow known pair or planar structure, scoring/known_structure.hpp), also from
the solver's starts of distinct rotations and the centre-direction starts around the best minimum
(searchBasins(), refine/hypothesis_starts.hpp); each is re-triangulated until it settles. Returns
the distinct minima that use as many features as the best one (an RMS over fewer residuals is not
comparable), lowest RMS first: with a narrow known pair or planar structure the linear candidates
alone lead refinement to another minimum in most scenes (doc/studies/accuracy.md). Candidates whose
refinement has no usable feature are dropped. */
void refineCandidates(const ViewSet& views, const PoseSolver& solver, bool severalBasins,
                      std::vector<ScoredPose>& candidates)
{
    const RefineOptions params;
    std::vector<CameraPose> starts;
    for (const ScoredPose& candidate : candidates)
        starts.push_back(candidate.pose);
    std::vector<LocalMinimum> minima;
    if (severalBasins)
    {
        // The solver's minimal samples give starts even where its estimate over all features has
        // no candidate, as can happen with a narrow known pair (doc/studies/accuracy.md).
        appendHypothesisStarts(views, solver, FeatureSubset::all(views.numPoints, views.numLines), starts);
        searchBasins(views, starts, params, nullptr, nullptr, &minima);
    }
    else
        refineFromStarts(views, starts, params, nullptr, nullptr, &minima);
    candidates = scoredPoses(distinctMinima(minima, kSameMinimum));
}

} // namespace

std::vector<ScoredPose> estimateCandidates(const ViewSet& views, const PoseSolver& solver, bool refine)
{
    std::vector<CameraPose> poses;
    solver.estimateNonMinimal(FeatureSubset::all(views.numPoints, views.numLines), poses);
    const PoseScorer scorer(views);
    std::vector<ScoredPose> ranked = rankCandidates(scorer, poses);
    if (refine)
        refineCandidates(views, solver, hasSeveralBasins(views, scorer), ranked);
    return ranked;
}

bool estimateRobustOnKnownStructure(const ViewSet& views, const PoseSolver& linear, const RansacOptions& options,
                                    RobustEstimate& estimate, BasinSearch basins)
{
    const PoseScorer scorer(views);
    const HybridPoseSolver solver(views, scorer, linear);
    return estimateRobust(views, scorer, solver, options, estimate, basins);
}

bool estimateRobustRig(const ViewSet& views, const RansacOptions& options, RobustEstimate& estimate)
{
    const PoseScorer scorer(views, PoseScorer::KnownDepth::Slides);
    const RigPoseSolver linear(views);
    const HybridPoseSolver solver(views, scorer, linear);
    return estimateRobust(views, scorer, solver, options, estimate);
}

bool estimateRobust(const ViewSet& views, const PoseScorer& scorer, const PoseSolver& solver,
                    const RansacOptions& options, RobustEstimate& estimate, BasinSearch basins)
{
    // Mixed minimal samples include three-line samples of the whole set, scored on all of it: they
    // find the basin of a line-dominated set as three-point samples do for points (doc/studies/speed.md,
    // "Mixed samples of points and lines"), and the starts would cost far more than the rest.
    // The structure's own regimes (narrow pair, planar) still call for them, except where the
    // scorer lets the known structure slide in depth (the stereo rig): its minimal samples then
    // find the basin too, and the starts would take nearly all of the time without changing the
    // result (doc/studies/speed.md, "Stereo rig"); settling from all features, which costs one
    // refinement, stays.
    const bool severalBasins = basins == BasinSearch::WhereSeveral &&
        (solver.mixedSampling() ? structureHasSeveralBasins(views, scorer) : hasSeveralBasins(views, scorer));
    const MultiStartRefiner refiner(views, options.refineOptions, &solver, severalBasins, !scorer.slidesKnownDepth(),
                                    severalBasins && knownPairIsNarrow(views, scorer));
    estimate.minima.clear();
    if (estimatePoseRobust(solver, scorer, options.refine ? &refiner : nullptr, options, estimate) &&
        estimate.numInliers >= options.minInliers)
    {
        estimate.minima = scoredPoses(refiner.minimaWithinNoise(estimate.pose));
        return true;
    }
    estimate = RobustEstimate();
    estimate.pointInliers.assign(views.numPoints, 0);
    estimate.lineInliers.assign(views.numLines, 0);
    return false;
}

double refineInitialPose(const ViewSet& views, CameraPose& pose, const RefineOptions& options,
                         RefinedStructure* structure, PoseCovariance* covariance)
{
    return refinePoseAndStructure(views, pose, options, nullptr, nullptr, structure, covariance).finalRms;
}

PoseCovariance covarianceOfEstimate(const ViewSet& views, const CameraPose& pose, const RefineOptions& options,
                                    const std::vector<unsigned char>* pointMask,
                                    const std::vector<unsigned char>* lineMask)
{
    std::vector<int> points, lines;
    for (int i = 0; i < views.numPoints; ++i)
        if (!pointMask || (*pointMask)[i])
            points.push_back(i);
    for (int i = 0; i < views.numLines; ++i)
        if (!lineMask || (*lineMask)[i])
            lines.push_back(i);
    CameraPose refined = pose;
    PoseCovariance covariance;
    refinePoseAndStructure(views, refined, options, &points, &lines, nullptr, &covariance);
    return covariance;
}

double refineSeveralPoses(const ViewSet& views, const std::vector<int>& poseOfView, std::vector<CameraPose>& poses,
                          const RefineOptions& options, RefinedStructure* structure)
{
    return refinePosesAndStructure(views, poseOfView, poses, options, structure).finalRms;
}

std::vector<CameraPose> allViewPoses(const ViewSet& views, const std::vector<int>& poseOfView,
                                     const std::vector<CameraPose>& poses)
{
    std::vector<CameraPose> all(views.views.size());
    for (size_t v = 0; v < all.size(); ++v)
        all[v] = poseOfView[v] >= 0 ? poses[poseOfView[v]] : views.views[v].pose;
    return all;
}

} // namespace tripose
