// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "../scoring/candidate_ranking.hpp"
#include "robust_estimator.hpp"
#include "mixed_sampler.hpp"
#include "sample_generator.hpp"

namespace tripose {

namespace {

constexpr int kLocalOptimizationRounds = 3;
// Rounds of refinement and inlier re-classification at the end; they settle in one or two.
constexpr int kSettleRounds = 3;
// Problems up to this many features are also settled from all of them (run()).
constexpr int kMaxSettleFromAll = 60;
// Hypotheses are scored against structure triangulated from the known views alone, which carries
// the triangulation error of those views on top of the image noise: their residuals are tested
// against this multiple of the user's threshold. The final inliers use residuals with the feature
// re-triangulated from every view (PoseScorer::refitResiduals) against the threshold itself.
constexpr double kSamplingThresholdFactor = 2.0;
// Mixed samples stop after this many if none gave a pose: every kind the pools allow is then
// degenerate there (parallel lines alone), and drawing more would run to the iteration limit.
constexpr int kMaxSamplesWithoutPose = 200;

class RobustEstimator
{
public:
    RobustEstimator(const PoseSolver& solver, const PoseScorer& scorer, const PoseRefiner* refiner,
                    const RansacOptions& params)
        : solver_(solver), scorer_(scorer), refiner_(refiner), params_(params),
          samplingThreshold_(kSamplingThresholdFactor * params.threshold)
    {
        const ViewSet& set = scorer.views();
        numPoints_ = set.numPoints;
        numFeatures_ = set.numFeatures();
    }

    bool run(RobustEstimate& estimate)
    {
        const MixedSampling* mixed = solver_.mixedSampling();
        bool enumerated = false;
        const int iterations = mixed ? sampleMixed(*mixed, estimate.samplesOfKind) : sampleUniform(enumerated);
        // With few features every sample was tried, and the structure of the known views alone may
        // put all their residuals over the threshold (a minimal set has no redundancy to test).
        // Then the solver's estimate over all features, ranked by the scorer, goes on to the
        // re-triangulated inlier test below.
        bool haveModel = std::isfinite(best_.cost) && best_.inliers > 0;
        // Likewise when no mixed sample gave a pose at all (pools whose samples are all degenerate,
        // e.g. parallel lines alone).
        if (!haveModel && (enumerated || (mixed && !sampledPose_)))
            haveModel = adoptAllFeatureEstimate();
        if (!haveModel)
            return false;

        estimate.iterations = iterations;
        estimate.pose = bestPose_;
        double cost = settleInliers(estimate);
        // A small problem's hypotheses come from four features scored against the known views'
        // structure alone, which with a narrow known pair leaves true inliers out; refined on that
        // subset the pose can stay in another basin. Settling from every feature as well, and
        // keeping the lower truncated cost of residuals re-triangulated in all views, repairs it.
        if (refiner_ && refiner_->searchesSeveralBasins() && numFeatures_ <= kMaxSettleFromAll)
        {
            RobustEstimate fromAll = estimate;
            std::fill(fromAll.pointInliers.begin(), fromAll.pointInliers.end(), 1);
            std::fill(fromAll.lineInliers.begin(), fromAll.lineInliers.end(), 1);
            const double allCost = settleInliers(fromAll, false);
            if (allCost < cost)
            {
                estimate = fromAll;
                cost = allCost;
            }
        }
        return estimate.numInliers > 0;
    }

private:
    //! Samples of solver_.sampleSize() features from the first samplePool(); returns how many were
    //! drawn. @p enumerated: every distinct sample was drawn once (SampleGenerator).
    int sampleUniform(bool& enumerated)
    {
        const int sampleSize = solver_.sampleSize();
        pool_ = std::min(numFeatures_, solver_.samplePool(numFeatures_));
        SampleGenerator samples(pool_, sampleSize, params_.maxIterations, params_.seed);
        enumerated = samples.enumerates();
        std::vector<int> indices(sampleSize);
        FeatureSubset sample;
        long maxIterations = params_.maxIterations;
        int iteration = 0;
        for (; iteration < maxIterations && samples.next(indices); ++iteration)
        {
            sample.assign(indices, numPoints_);
            if (tryMinimalSample(sample, samples.enumerates()))
                maxIterations = std::min<long>(maxIterations, requiredIterations(inliersInPool(), sampleSize));
        }
        return iteration;
    }

    //! Samples of the solver's kinds (MixedSampler), until one all-inlier sample is drawn with the
    //! requested confidence; @p samplesOfKind receives how many of each kind were drawn.
    int sampleMixed(const MixedSampling& sampling, std::vector<int>& samplesOfKind)
    {
        MixedSampler samples(sampling, params_.seed);
        FeatureSubset sample;
        int iteration = 0;
        for (; iteration < params_.maxIterations && samples.next(sample); ++iteration)
        {
            if (!sampledPose_ && iteration >= kMaxSamplesWithoutPose)
                break;
            if (tryMinimalSample(sample, false))
                samples.setInliers(bestInliers_, sample);
            if (samples.confident(params_.confidence))
            {
                ++iteration;
                break;
            }
        }
        samplesOfKind = samples.samplesOfKind();
        return iteration;
    }

    //! Solves @p sample and keeps the best of its poses (locally optimised); true if it improved.
    bool tryMinimalSample(const FeatureSubset& sample, bool exhaustive)
    {
        candidates_.clear();
        solver_.estimateMinimal(sample, exhaustive, candidates_);
        sampledPose_ = sampledPose_ || !candidates_.empty();
        if (!keepBest(candidates_))
            return false;
        if (params_.localOptimization)
            optimizeLocally();
        return true;
    }

    /** Refinement on the inliers and their re-classification until they settle (at most a few rounds):
    refinement on the inliers may change their classification. @p classify: start from the inliers
    of the estimate's pose, else from the masks it holds. Returns the truncated cost of the final
    pose: the sum over features of min(r^2, threshold^2), r re-triangulated from every view. */
    double settleInliers(RobustEstimate& estimate, bool classify = true)
    {
        if (classify)
            estimate.numInliers = inlierMasks(estimate.pose, estimate.pointInliers, estimate.lineInliers);
        for (int round = 0; round < kSettleRounds && refiner_; ++round)
        {
            refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers);
            std::vector<unsigned char> points, lines;
            estimate.numInliers = inlierMasks(estimate.pose, points, lines);
            const bool settled = points == estimate.pointInliers && lines == estimate.lineInliers;
            estimate.pointInliers.swap(points);
            estimate.lineInliers.swap(lines);
            if (settled)
                break;
        }
        const double t2 = params_.threshold * params_.threshold;
        double cost = 0, inlierSquares = 0;
        for (const std::vector<double>* r : { &pointResiduals_, &lineResiduals_ })
            for (double e : *r)
            {
                cost += std::min(e * e, t2);
                // The masks compare these same residuals with the threshold.
                if (e < params_.threshold)
                    inlierSquares += e * e;
            }
        estimate.inlierRms = estimate.numInliers > 0 ? std::sqrt(inlierSquares / estimate.numInliers)
                                                     : std::numeric_limits<double>::quiet_NaN();
        return cost;
    }

    bool adoptAllFeatureEstimate()
    {
        std::vector<CameraPose> poses;
        solver_.estimateNonMinimal(FeatureSubset::all(numPoints_, numFeatures_ - numPoints_), poses);
        const std::vector<ScoredPose> ranked = rankCandidates(scorer_, poses);
        if (ranked.empty())
            return false;
        bestPose_ = ranked.front().pose;
        best_ = scorer_.score(bestPose_, samplingThreshold_, std::numeric_limits<double>::infinity(), &bestInliers_);
        return true;
    }

    //! Makes the cheapest of @p poses the best model if it beats it; true if it did.
    bool keepBest(const std::vector<CameraPose>& poses)
    {
        bool improved = false;
        for (const CameraPose& pose : poses)
        {
            const PoseScore s = scorer_.score(pose, samplingThreshold_, best_.cost, &inliers_);
            if (s.cost < best_.cost)
            {
                best_ = s;
                bestPose_ = pose;
                bestInliers_.points.swap(inliers_.points);
                bestInliers_.lines.swap(inliers_.lines);
                improved = true;
            }
        }
        return improved;
    }

    //! Re-solves from the inliers of the best model while that lowers the cost.
    void optimizeLocally()
    {
        std::vector<CameraPose> poses;
        for (int round = 0; round < kLocalOptimizationRounds; ++round)
        {
            if (bestInliers_.size() < solver_.nonMinimalSize())
                return;
            poses.clear();
            const FeatureSubset inliers = bestInliers_;
            solver_.estimateNonMinimal(inliers, poses);
            if (!keepBest(poses))
                return;
        }
    }

    void refineOnInliers(CameraPose& pose, const std::vector<unsigned char>& pointMask,
                         const std::vector<unsigned char>& lineMask) const
    {
        FeatureSubset inliers;
        for (int i = 0; i < (int)pointMask.size(); ++i)
            if (pointMask[i])
                inliers.points.push_back(i);
        for (int i = 0; i < (int)lineMask.size(); ++i)
            if (lineMask[i])
                inliers.lines.push_back(i);
        CameraPose refined = pose;
        if (refiner_->refine(inliers, refined) && refined.allFinite())
            pose = refined;
    }

    int inlierMasks(const CameraPose& pose, std::vector<unsigned char>& pointMask, std::vector<unsigned char>& lineMask)
    {
        scorer_.refitResiduals(pose, pointResiduals_, lineResiduals_);
        int count = 0;
        pointMask.resize(pointResiduals_.size());
        for (size_t i = 0; i < pointResiduals_.size(); ++i)
            count += pointMask[i] = pointResiduals_[i] < params_.threshold;
        lineMask.resize(lineResiduals_.size());
        for (size_t i = 0; i < lineResiduals_.size(); ++i)
            count += lineMask[i] = lineResiduals_[i] < params_.threshold;
        return count;
    }

    //! Inlier features of the best model among those samples are drawn from (features, not
    //! observations: a feature seen by both cameras of a rig counts once).
    int inliersInPool() const
    {
        int count = 0;
        for (int i : bestInliers_.points)
            count += i < pool_;
        for (int i : bestInliers_.lines)
            count += numPoints_ + i < pool_;
        return count;
    }

    //! Samples needed to draw one all-inlier sample with the requested confidence.
    long requiredIterations(int inliers, int sampleSize) const
    {
        const double w = double(inliers) / pool_;
        const double allInliers = std::pow(w, sampleSize);
        if (allInliers >= 1.0)
            return 1;
        if (allInliers <= 0.0)
            return params_.maxIterations;
        // log1p: for a tiny all-inlier probability, 1 - p rounds to 1 and log(1 - p) to 0.
        const double n = std::log1p(-params_.confidence) / std::log1p(-allInliers);
        if (!(n < params_.maxIterations))
            return params_.maxIterations;
        return (long)std::ceil(n);
    }

    const PoseSolver& solver_;
    const PoseScorer& scorer_;
    const PoseRefiner* refiner_;
    const RansacOptions& params_;
    const double samplingThreshold_;
    int numPoints_ = 0, numFeatures_ = 0, pool_ = 0;
    bool sampledPose_ = false; //!< Some minimal sample gave a pose.
    std::vector<double> pointResiduals_, lineResiduals_;
    std::vector<CameraPose> candidates_;
    PoseScore best_ = worstScore();
    CameraPose bestPose_;
    FeatureSubset bestInliers_, inliers_;

    static PoseScore worstScore()
    {
        PoseScore s;
        s.cost = std::numeric_limits<double>::infinity();
        return s;
    }
};

} // namespace

bool estimatePoseRobust(const PoseSolver& solver, const PoseScorer& scorer, const PoseRefiner* refiner,
                        const RansacOptions& params, RobustEstimate& estimate)
{
    return RobustEstimator(solver, scorer, refiner, params).run(estimate);
}

} // namespace tripose
