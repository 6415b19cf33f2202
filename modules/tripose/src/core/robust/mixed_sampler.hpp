// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_MIXED_SAMPLER_HPP
#define OPENCV_TRIPOSE_ROBUST_MIXED_SAMPLER_HPP

#include <vector>

#include <cstdint>

#include "../estimator/pose_solver.hpp"
#include "../support/random.hpp"

namespace tripose {

/** Samples of several kinds (MixedSampling) and when to stop drawing them, after the hybrid RANSAC
of Camposeco et al. (CVPR 2018) that LIMAP and PoseLib use for points and lines.

Each kind's success probability is the probability that a sample of it is all inliers, from the
inlier counts of the best model so far in each pool, drawn without replacement:
C(I_p, k_p) C(I_l, k_l) / (C(N_p, k_p) C(N_l, k_l)); a pool whose inliers are only features of the
sample the model came from counts none there (they fit the model by construction, right or wrong:
with a pool of three points, the three of a wrong P3P model would otherwise make every later P3P
sample look certain, and stop the search at that pose). Drawing stops when every sample drawn so far
failing has probability at most 1 - confidence: the product over kinds of
(1 - p_kind)^(samples of that kind); with one kind this is the usual adaptive RANSAC bound. It also
stops once every kind the pools can fill has been drawn so often that any one sample of it would
have been drawn with that confidence (covered()): an all-inlier sample of any kind, if the pools
hold one, is then among those drawn, whatever the best model's support. That bounds the search
where the best model has no support beyond its sample in any pool the kinds draw from (its support
lies in features no kind draws), where the rule above would draw to the iteration limit; small
pools are covered after a few hundred samples per kind, large ones never before the limit.

A kind with few distinct samples (at most 10000, the default iteration limit) is drawn without
replacement, as SampleGenerator draws the linear samples of small sets: each of its samples at most
once, in random order, so that it is covered once a share `confidence` of them has been drawn
(C(10, 3) = 120 P3P samples for a pool of ten points, where drawing with replacement needs about
830 to cover them at 0.999) and is not drawn again once all have been. A kind's samples are the
products of a point and a line combination, so they are numbered and decoded when drawn rather
than listed in advance.

A kind is chosen per sample with probability proportional to the same all-inlier probability with
the model's own sample left out of the counts and the pools, so that where lines are the reliable
matches the samples are mostly lines, and a wrong model's own sample does not steer the choice to
its kind. (Left out of the stopping rule as well, it would underestimate a right model's support in
small pools: 20 points, 8 of them inliers, a third of the all-inlier probability, more than twice
the samples.) A tenth of the samples is chosen uniformly among the kinds the pools can fill (all of
them while no model has support beyond its sample), because a wrong model that gathered support of
one kind alone would otherwise leave the kinds that can find the truth undrawn.
*/
class MixedSampler
{
public:
    MixedSampler(const MixedSampling& sampling, uint64_t seed);

    //! Chooses a kind and draws its sample into @p sample; false when no kind can be drawn.
    bool next(FeatureSubset& sample);

    /** Sets the inliers of the best model (any features; in each pool those outside it are ignored)
    and the sample it was estimated from. */
    void setInliers(const FeatureSubset& inliers, const FeatureSubset& sample);

    /** True when an all-inlier sample is among those drawn with at least @p confidence, by the
    best model's support or because every kind is covered(). */
    bool confident(double confidence) const;

    /** True when every kind that the pools can fill was drawn so often that the probability of
    any one of its samples never having been drawn is at most 1 - @p confidence. */
    bool covered(double confidence) const;

    //! Samples drawn of each kind, in the order of MixedSampling::kinds.
    const std::vector<int>& samplesOfKind() const { return drawn_; }

private:
    //! Probability that a sample of kind @p k is all inliers (the stopping rule).
    double successProbability(int k) const;
    //! The same without the best model's own sample (the choice of a kind).
    double choiceWeight(int k) const;
    //! The pools hold enough features for a sample of kind @p k.
    bool canDraw(int k) const;
    //! canDraw(), and a kind drawn without replacement has samples left.
    bool available(int k) const;
    //! Draws a sample of a kind drawn without replacement (enumeratedSamples_[k] > 0).
    void drawUnseen(int k, FeatureSubset& sample);
    //! covered() with log(1 - confidence) given: confident() asks once per sample.
    bool coveredTo(double logMissed) const;
    int chooseKind();
    void drawDistinct(const std::vector<int>& pool, int count, std::vector<int>& out);

    //! The best model's inliers among the points or the lines of one pool (setInliers()).
    struct Support
    {
        int inliers = 0;       //!< All of them, or 0 when they are only its sample's features.
        int beyondSample = 0;  //!< Those that are not features of its sample.
        int sampleInliers = 0; //!< Features of its sample among them.
    };
    //! One pool's membership by feature index, and the best model's support there.
    struct PoolState
    {
        std::vector<unsigned char> hasPoint, hasLine;
        Support points, lines;
    };

    const MixedSampling& sampling_;
    Random rng_;
    std::vector<PoolState> pools_;
    std::vector<int> drawn_;
    std::vector<double> weights_;
    //! Per kind, log(1 - 1 / its number of distinct samples): the log of the probability that a
    //! draw misses one given sample (covered()).
    std::vector<double> logMissOne_;
    //! Per kind drawn without replacement, its number of distinct samples; 0 for the other kinds.
    std::vector<long> enumeratedSamples_;
    //! Per kind drawn without replacement, the indices of its samples not drawn yet (filled at its
    //! first draw; a sample's index numbers its point combination times the number of line
    //! combinations plus its line combination).
    std::vector<std::vector<int>> unseen_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_ROBUST_MIXED_SAMPLER_HPP
