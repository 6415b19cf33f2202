// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
#define OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP

#include <vector>

#include "../estimator/pose_solver.hpp"
#include "distinct_minima.hpp"
#include "hypothesis_starts.hpp"
#include "multi_start_refinement.hpp"

namespace tripose {

/** The robust estimator's final stage: maximum-likelihood refinement over every view from the
estimator's pose, from the solver's estimates on the inliers (when it has one and they are enough),
from the solver's starts of distinct rotations (hypothesis_starts.hpp) and from the starts of
centreDirectionStarts() around the best minimum (searchBasins()), each re-triangulated until it
settles, the lowest cost kept and the minima within the noise of it remembered
(minimaWithinNoise()). Only where the problem has several basins (a narrow known baseline, planar
structure) and the caller asks for the starts. Sets larger than kMaxMultiStartFeatures are searched
only with a narrow known pair (searchesBasinOfLargeSets()), once per estimate: on the first call
(the inliers at the robust estimator's pose), from the estimator's pose and the solver's estimates
alone (searchFromStarts()); the estimator's later calls, on the inliers as they settle, refine once
from the pose they are given. With a narrow known pair, one search reaches the lowest minimum more
often than one refinement from the RANSAC's pose (doc/studies/accuracy.md, "Narrow known baselines,
large sets"). Large planar sets with a wide baseline are refined once: their samples find the basin,
and the search does not change their errors at several times the time. Elsewhere one refinement
from the estimator's pose reaches the optimum.
*/
class MultiStartRefiner : public PoseRefiner
{
public:
    static constexpr int kMaxMultiStartFeatures = 60;

    /** @p severalBasins: whether the problem has several basins (scoring/known_structure.hpp);
    without, one refinement from the estimator's pose reaches the optimum and the starts would only
    cost time. @p searchStarts: whether to refine from the starts there; a problem whose samples
    already find the basin (the stereo rig's, scored with the known depth sliding) settles from
    all features (searchesSeveralBasins()) without them. */
    MultiStartRefiner(const ViewSet& set, const RefineOptions& params, const PoseSolver* solver, bool severalBasins,
                      bool searchStarts = true, bool narrowKnownPair = false)
        : set_(set), params_(params), solver_(solver), severalBasins_(severalBasins),
          searchStarts_(severalBasins && searchStarts), searchLargeSets_(searchStarts_ && narrowKnownPair)
    {}

    bool searchesSeveralBasins() const override { return severalBasins_; }
    bool searchesOtherStarts() const override { return searchStarts_; }
    bool searchesBasinOfLargeSets() const override { return searchLargeSets_; }

    bool refine(const FeatureSubset& inliers, CameraPose& pose, int maxIterations = 0,
                bool* stoppedAtCap = nullptr) const override
    {
        if (stoppedAtCap)
            *stoppedAtCap = false;
        // Fewer than three features leave the pose and structure under-determined.
        if (inliers.size() < 3)
            return false;
        const bool large = inliers.size() > kMaxMultiStartFeatures;
        if (!searchStarts_ || (large && (!searchLargeSets_ || searchedLarge_)))
        {
            LocalMinimum single;
            RefineOptions params = params_;
            const bool capped = !searchStarts_ && maxIterations > 0 && maxIterations < params.maxIterations;
            if (capped)
                params.maxIterations = maxIterations;
            // A call on the features and from the pose that a call stopped at its iteration limit
            // (the caller's cap or the options') ended on continues from the structure it reached:
            // re-triangulated, that structure would cost most of the cap again (a far line on a
            // short baseline moves by metres).
            const bool resumes = stopped_.valid && inliers.points == stopped_.inliers.points &&
                                 inliers.lines == stopped_.inliers.lines && pose.R == stopped_.result.R &&
                                 pose.t == stopped_.result.t;
            const RefinementSummary summary = refinePoseAndStructure(
                set_, pose, params, &inliers.points, &inliers.lines, &stopped_.next, nullptr,
                resumes ? &stopped_.structure : nullptr);
            stopped_.valid = summary.iterations >= params.maxIterations;
            if (stopped_.valid)
            {
                stopped_.inliers = inliers;
                stopped_.result = pose;
                stopped_.structure.points.swap(stopped_.next.points);
                stopped_.structure.lineEnds.swap(stopped_.next.lineEnds);
                stopped_.structure.pointUsed.swap(stopped_.next.pointUsed);
                stopped_.structure.lineUsed.swap(stopped_.next.lineUsed);
            }
            if (stoppedAtCap)
                *stoppedAtCap = stopped_.valid;
            single.pose = pose;
            single.rms = summary.finalRms;
            single.residuals = summary.residuals;
            remember(inliers, pose, std::vector<LocalMinimum>(1, single));
            return true;
        }
        // The estimator asks again from the pose this returned, on the same features, when its
        // inliers settle at once and then settling from all features finds them all inliers: the
        // starts would be those of the previous call, moved by its refinement.
        if (last_.valid && inliers.points == last_.inliers.points && inliers.lines == last_.inliers.lines &&
            pose.R == last_.result.R && pose.t == last_.result.t)
            return true;
        // The solver's estimates on the inliers first: the centre-direction starts keep the first
        // start's rotation, so around the estimate's pose alone they can miss the lowest minimum
        // that POSE_LINEAR_REFINE's search reaches with a narrow known pair (doc/studies/accuracy.md).
        std::vector<CameraPose> starts;
        if (solver_ && inliers.size() >= solver_->nonMinimalSize())
            solver_->estimateNonMinimal(inliers, starts);
        starts.push_back(pose);
        if (solver_)
            appendHypothesisStarts(set_, *solver_, inliers, starts);
        std::vector<LocalMinimum> minima;
        searchedLarge_ = searchedLarge_ || large;
        const LocalMinimum best = large ? searchFromStarts(set_, starts, params_, &inliers.points, &inliers.lines, &minima)
                                        : searchBasins(set_, starts, params_, &inliers.points, &inliers.lines, &minima);
        if (!best.finite())
            return false;
        pose = best.pose;
        remember(inliers, pose, distinctMinima(minima, kSameMinimum));
        last_.valid = true;
        last_.inliers = inliers;
        last_.result = pose;
        return true;
    }

    /** The minima that the refinement which returned @p pose reached: that one first, then the
    other distinct minima within the noise of it (withinNoise()), lowest cost first, each with its
    RMS over that refinement's features. The others are refined further first (kPolishFactor times
    the iterations, re-triangulating), at most kMaxReportedMinima of them, and kept if they stay
    within the noise and apart from the returned pose refined as far: in a narrow scene's flat
    valleys the default 30 iterations stop two refinements of one minimum further apart than
    kSameMinimum, and their costs more than 1e-3 apart (test_narrow_minima.cpp).
    Empty when @p pose did not come from this refiner; the returned pose alone where the
    refinement searched a single basin. */
    std::vector<LocalMinimum> minimaWithinNoise(const CameraPose& pose) const
    {
        std::vector<LocalMinimum> out;
        for (const Result& r : results_)
        {
            if (!(r.minima.front().pose.R == pose.R && r.minima.front().pose.t == pose.t))
                continue;
            out.push_back(r.minima.front());
            if (r.minima.size() < 2)
                break;
            RefineOptions longer = params_;
            longer.maxIterations = kPolishFactor * params_.maxIterations;
            // The returned pose refined as far, polished only once another minimum is within the noise.
            LocalMinimum first;
            std::vector<LocalMinimum> others;
            for (size_t k = 1; k < r.minima.size() && (int)others.size() < kMaxReportedMinima; ++k)
            {
                if (!withinNoise(r.minima.front(), r.minima[k]))
                    continue;
                if (!first.finite())
                {
                    first = refineRetriangulating(set_, pose, longer, &r.inliers.points, &r.inliers.lines);
                    if (!first.finite())
                        break;
                }
                const LocalMinimum polished =
                    refineRetriangulating(set_, r.minima[k].pose, longer, &r.inliers.points, &r.inliers.lines);
                if (!polished.finite() || !withinNoise(first, polished) ||
                    sameMinimum(polished.pose, first.pose, kSameMinimum))
                    continue;
                bool repeated = false;
                for (const LocalMinimum& o : others)
                    repeated = repeated || sameMinimum(polished.pose, o.pose, kSameMinimum);
                if (!repeated)
                    others.push_back(polished);
            }
            std::stable_sort(others.begin(), others.end(),
                             [](const LocalMinimum& a, const LocalMinimum& b) { return a.betterThan(b); });
            out.insert(out.end(), others.begin(), others.end());
            break;
        }
        return out;
    }

private:
    //! The further refinement of the minima reported besides the returned pose.
    static constexpr int kPolishFactor = 10;
    static constexpr int kMaxReportedMinima = 3;

    //! Every refinement's result with the distinct minima it reached (best first): the estimator
    //! refines a few times (settling the inliers, from its hypothesis' inliers and from all).
    struct Result
    {
        FeatureSubset inliers;
        std::vector<LocalMinimum> minima;
    };

    void remember(const FeatureSubset& inliers, const CameraPose& pose, std::vector<LocalMinimum> minima) const
    {
        if (minima.empty() || !(minima.front().pose.R == pose.R && minima.front().pose.t == pose.t))
            return;
        Result r;
        r.inliers = inliers;
        r.minima.swap(minima);
        results_.push_back(r);
    }

    //! Whether a set larger than kMaxMultiStartFeatures was searched (see the class description).
    mutable bool searchedLarge_ = false;
    //! The previous multi-start refinement: its features and result. State of one estimation:
    //! a refiner is built per call and not shared between threads.
    struct LastRefinement
    {
        bool valid = false;
        FeatureSubset inliers;
        CameraPose result;
    };

    const ViewSet& set_;
    const RefineOptions& params_;
    const PoseSolver* solver_;
    bool severalBasins_, searchStarts_, searchLargeSets_;
    mutable LastRefinement last_;
    //! The last refinement from the estimator's pose if it stopped at its iteration limit: its
    //! features, result and structure (refine()); next: the structure of the call under way.
    struct StoppedRefinement
    {
        bool valid = false;
        FeatureSubset inliers;
        CameraPose result;
        RefinedStructure structure, next;
    };
    mutable StoppedRefinement stopped_;
    mutable std::vector<Result> results_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
