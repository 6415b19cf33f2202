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
#include "../scoring/noise_test.hpp"
#include "robust_estimator.hpp"
#include "mixed_sampler.hpp"
#include "sample_generator.hpp"

namespace tripose {

namespace {

constexpr int kLocalOptimizationRounds = 3;
// Rounds of refinement and inlier re-classification at the end; they settle in one or two.
constexpr int kSettleRounds = 3;
// Iterations of a settle round's refinement before its inliers are re-classified (settleInliers()):
// on small rig sets whose consensus leaves true features out, a full refinement on the partial set
// is wasted, since it is re-triangulated and refined again on the settled set; the cap shortens the
// slowest estimates (doc/studies/speed.md).
constexpr int kSettleRoundIterations = 12;
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
          samplingThreshold_(kSamplingThresholdFactor * params.threshold),
          featuresAgainstNoise_(scorer.slidesKnownDepth()),
          capSettleRounds_(scorer.slidesKnownDepth() && refiner && !refiner->searchesOtherStarts())
    {
        const ViewSet& set = scorer.views();
        numPoints_ = set.numPoints;
        numFeatures_ = set.numFeatures();
        stopsByRefitInliers_ = refiner && refiner->searchesBasinOfLargeSets() && numFeatures_ > kMaxSettleFromAll;
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
        // Where the first settle kept every feature there is nothing to repair: settling from all
        // of them would refine the same features from the same pose, and a refiner that descends
        // from the pose it is given would end where it started. (One that searches other starts
        // may still find a better basin there.)
        const bool descends = refiner_ && !refiner_->searchesOtherStarts();
        if (refiner_ && refiner_->searchesSeveralBasins() && numFeatures_ <= kMaxSettleFromAll &&
            !(descends && estimate.numInliers == numFeatures_))
        {
            RobustEstimate fromAll = estimate;
            std::fill(fromAll.pointInliers.begin(), fromAll.pointInliers.end(), 1);
            std::fill(fromAll.lineInliers.begin(), fromAll.lineInliers.end(), 1);
            // A refiner that searches other starts may find another basin of the same inliers'
            // cost from the new pose, so it is let finish (doc/studies/accuracy.md): only a refiner
            // that descends from the pose it is given gives up on coming back to them.
            const double allCost = settleInliers(fromAll, false, descends ? &estimate : nullptr);
            if (allCost < cost)
            {
                estimate = fromAll;
                cost = allCost;
            }
        }
        // A pose is found only when one feature more than a minimal sample of the solver agrees with
        // it (all of them where the input holds no more): a minimal sample fits any observations,
        // wrong matches too, and one or two inliers more leave the pose free (doc/studies/hardening.md).
        return estimate.numInliers >= std::min(solver_.sampleSize() + 1, numFeatures_);
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
                maxIterations = std::min<long>(maxIterations, requiredIterations(stoppingInliers(), sampleSize));
        }
        return iteration;
    }

    //! Samples of the solver's kinds (MixedSampler), until one all-inlier sample is drawn with the
    //! requested confidence (by the best model's support, or every kind covered: MixedSampler::
    //! confident()); @p samplesOfKind receives how many of each kind were drawn.
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
        if (!keepBest(candidates_, params_.sequentialTest ? &test_ : nullptr))
            return false;
        if (params_.localOptimization)
            optimizeLocally();
        return true;
    }

    /** Refinement on the inliers and their re-classification until they settle (at most a few rounds):
    refinement on the inliers may change their classification. @p classify: start from the inliers
    of the estimate's pose, else from the masks it holds. Returns the truncated cost of the final
    pose: the sum over features of min(r^2, threshold^2), r re-triangulated from every view; +inf
    (give up, keep the other) as soon as a round classifies the inliers that @p settledBefore, an
    earlier settle, ended on. */
    double settleInliers(RobustEstimate& estimate, bool classify = true, const RobustEstimate* settledBefore = nullptr)
    {
        if (classify)
            estimate.numInliers = inlierMasks(estimate.pose, estimate.pointInliers, estimate.lineInliers);
        for (int round = 0; round < kSettleRounds && refiner_; ++round)
        {
            // A round whose refinement the inlier test then changes only hands its pose to the next:
            // where the known depth slides (the stereo rig) and the refiner descends from its start,
            // it is capped there (kSettleRoundIterations) and refined to the end once the inliers
            // settle, or in the last round. (The three-view estimators keep full rounds.) A round on
            // settled inliers that stopped at its iteration limit, capped or not, is continued once
            // from where it stopped: in a long flat valley (the rig's depth on a short baseline) the
            // default iterations can stop well short of the minimum (doc/studies/evaluation.md).
            const bool capRound = capSettleRounds_ && round + 1 < kSettleRounds;
            bool stoppedAtCap = false;
            refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers,
                            capRound ? kSettleRoundIterations : 0, &stoppedAtCap);
            std::vector<unsigned char> points, lines;
            estimate.numInliers = inlierMasks(estimate.pose, points, lines);
            // Back on the inliers that @p settledBefore ended on, the next round would refine those
            // features again: where that settle did, unless this start lies in another basin of the
            // same features' cost; dropping that round moves the errors by the last iterations'
            // amount only and saves its iterations (doc/studies/evaluation.md).
            if (settledBefore && points == settledBefore->pointInliers && lines == settledBefore->lineInliers)
                return std::numeric_limits<double>::infinity();
            const bool settled = points == estimate.pointInliers && lines == estimate.lineInliers;
            estimate.pointInliers.swap(points);
            estimate.lineInliers.swap(lines);
            if (settled && stoppedAtCap)
            {
                refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers);
                estimate.numInliers = inlierMasks(estimate.pose, estimate.pointInliers, estimate.lineInliers);
            }
            if (settled)
                break;
        }
        if (refiner_ && featuresAgainstNoise_)
            rejectPointsAboveNoiseAndRefine(estimate);
        return summarizeInliers(estimate);
    }

    /** The settled inliers' points judged against their noise (rejectPointsAboveNoise()); where some
    fail, one more refinement without them (continued once where it stops at its iteration limit),
    then the final inlier test with that one too. */
    void rejectPointsAboveNoiseAndRefine(RobustEstimate& estimate)
    {
        if (rejectPointsAboveNoise(scorer_.views(), params_.threshold, pointResiduals_, estimate.pointInliers) == 0)
            return;
        bool stopped = false;
        refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers, 0, &stopped);
        if (stopped)
            refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers);
        estimate.numInliers = inlierMasks(estimate.pose, estimate.pointInliers, estimate.lineInliers);
        estimate.numInliers -= rejectPointsAboveNoise(scorer_.views(), params_.threshold, pointResiduals_,
                                                      estimate.pointInliers);
    }

    /** Sets the estimate's inlier RMS from the residuals of the last inlierMasks(), which made its
    masks at its pose, and returns the truncated cost of that pose (settleInliers()): an outlier of
    the masks costs threshold^2. */
    double summarizeInliers(RobustEstimate& estimate) const
    {
        const double t2 = params_.threshold * params_.threshold;
        double cost = 0, inlierSquares = 0;
        const auto add = [&](const std::vector<double>& residuals, const std::vector<unsigned char>& mask) {
            for (size_t i = 0; i < residuals.size(); ++i)
            {
                const double e2 = residuals[i] * residuals[i];
                cost += mask[i] ? e2 : t2;
                inlierSquares += mask[i] ? e2 : 0.0;
            }
        };
        add(pointResiduals_, estimate.pointInliers);
        add(lineResiduals_, estimate.lineInliers);
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

    /** Makes the cheapest of @p poses the best model if it beats it; true if it did. @p test: the
    sequential test that the poses must pass before they are scored (the minimal samples' poses),
    told the rates of every new best model and what it saw of the poses it rejected. */
    bool keepBest(const std::vector<CameraPose>& poses, SequentialTest* test = nullptr)
    {
        bool improved = false;
        for (const CameraPose& pose : poses)
        {
            const PoseScore s = scorer_.score(pose, samplingThreshold_, best_.cost, &inliers_, test);
            if (s.rejected && test)
                test->addRejected(s.tested, s.testedConsistent);
            if (s.cost < best_.cost)
            {
                best_ = s;
                bestPose_ = pose;
                bestInliers_.points.swap(inliers_.points);
                bestInliers_.lines.swap(inliers_.lines);
                improved = true;
            }
        }
        if (improved)
            setGoodRates();
        return improved;
    }

    //! The sequential test's rates of a good pose: the best model's consistent observations.
    void setGoodRates()
    {
        const int points = scorer_.observations(SequentialTest::Point);
        const int lines = scorer_.observations(SequentialTest::Line);
        test_.setGoodRates(points > 0 ? double(best_.pointInliers) / points : 0.0,
                           lines > 0 ? double(best_.inliers - best_.pointInliers) / lines : 0.0);
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

    //! The features whose mask entries are set.
    static FeatureSubset subsetOfMasks(const std::vector<unsigned char>& pointMask,
                                       const std::vector<unsigned char>& lineMask)
    {
        FeatureSubset subset;
        for (int i = 0; i < (int)pointMask.size(); ++i)
            if (pointMask[i])
                subset.points.push_back(i);
        for (int i = 0; i < (int)lineMask.size(); ++i)
            if (lineMask[i])
                subset.lines.push_back(i);
        return subset;
    }

    void refineOnInliers(CameraPose& pose, const std::vector<unsigned char>& pointMask,
                         const std::vector<unsigned char>& lineMask, int maxIterations = 0,
                         bool* stoppedAtCap = nullptr) const
    {
        CameraPose refined = pose;
        if (refiner_->refine(subsetOfMasks(pointMask, lineMask), refined, maxIterations, stoppedAtCap) &&
            refined.allFinite())
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
        if (featuresAgainstNoise_)
            count -= rejectLinesAbovePointNoise(scorer_.views(), params_.threshold, pointResiduals_, pointMask,
                                                lineResiduals_, lineMask);
        return count;
    }

    //! Features of @p inliers among those samples are drawn from (features, not observations: a
    //! feature seen by both cameras of a rig counts once).
    int inliersInPool(const FeatureSubset& inliers) const
    {
        int count = 0;
        for (int i : inliers.points)
            count += i < pool_;
        for (int i : inliers.lines)
            count += numPoints_ + i < pool_;
        return count;
    }

    /** The inliers that the stopping rule counts: those of the best model's score, or
    (stopsByRefitInliers_) those of its pose with every feature re-triangulated from all views, as
    the final inlier test counts them. */
    int stoppingInliers()
    {
        if (!stopsByRefitInliers_)
            return inliersInPool(bestInliers_);
        std::vector<unsigned char> points, lines;
        inlierMasks(bestPose_, points, lines);
        return inliersInPool(subsetOfMasks(points, lines));
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
    /** Whether the final inlier test also judges lines, and the settled inliers' points, against the
    inlier points' noise (scoring/noise_test.hpp): where the known depth slides, the stereo rig, whose
    wrong matches can be consistent between the images at each time and pass the threshold. */
    const bool featuresAgainstNoise_;
    //! Whether settle rounds that re-classify the inliers are capped at kSettleRoundIterations.
    const bool capSettleRounds_;
    int numPoints_ = 0, numFeatures_ = 0, pool_ = 0;
    /** Whether the stopping rule counts the best pose's inliers re-triangulated from all views
    (stoppingInliers()): where the refiner searches the basin of sets of any size (a narrow known
    pair) and the set is larger than those settled from all features. There the known pair
    triangulates the structure poorly: the score against it leaves true inliers out and asks for
    thousands of samples, which served as a search for the basin (doc/studies/accuracy.md). With the
    refiner searching it, the samples need only find the inliers. */
    bool stopsByRefitInliers_ = false;
    bool sampledPose_ = false; //!< Some minimal sample gave a pose.
    std::vector<double> pointResiduals_, lineResiduals_;
    std::vector<CameraPose> candidates_;
    PoseScore best_ = worstScore();
    CameraPose bestPose_;
    FeatureSubset bestInliers_, inliers_;
    SequentialTest test_;

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
