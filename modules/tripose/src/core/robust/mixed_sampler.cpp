// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/combinations.hpp"
#include "mixed_sampler.hpp"

namespace tripose {

namespace {

// The share of the samples whose kind is chosen uniformly (MixedSampler's description says why).
constexpr double kExplorationShare = 0.1;

// Kinds with at most this many distinct samples are drawn without replacement: the estimators'
// default iteration limit, so that such a kind can be drawn to the end within it (drawn with
// replacement, a kind of more than about 1450 samples is never covered within 10000 draws).
constexpr long kMaxEnumeratedSamples = 10000;

/** The combination of @p count positions among @p size with rank @p index (0 <= index <
C(size, count)) in the combinatorial number system: positions c_count > ... > c_1 with
index = sum C(c_j, j); appended to @p out as pool[c_j]. */
void appendCombination(long index, int size, int count, const std::vector<int>& pool, std::vector<int>& out)
{
    for (int j = count; j >= 1; --j)
    {
        int c = j == 1 ? (int)index : j - 1; // C(c, 1) = c
        while (j > 1 && c + 1 < size && combinationCount(c + 1, j, index) <= index)
            ++c;
        index -= combinationCount(c, j, index);
        out.push_back(pool[c]);
        size = c;
    }
}

//! Probability that @p count draws without replacement from @p size items, @p good of them good,
//! are all good.
double allGood(int good, int size, int count)
{
    double p = 1.0;
    for (int j = 0; j < count; ++j)
        p *= size - j > 0 ? std::max(0.0, double(good - j) / (size - j)) : 0.0;
    return p;
}

std::vector<unsigned char> membership(const std::vector<int>& pool)
{
    int size = 0;
    for (int i : pool)
        size = std::max(size, i + 1);
    std::vector<unsigned char> in(size, 0);
    for (int i : pool)
        in[i] = 1;
    return in;
}

} // namespace

MixedSampler::MixedSampler(const MixedSampling& sampling, uint64_t seed)
    : sampling_(sampling), rng_(seed), pools_(sampling.pools.size()), drawn_(sampling.kinds.size(), 0),
      weights_(sampling.kinds.size(), 0.0)
{
    for (size_t k = 0; k < pools_.size(); ++k)
    {
        pools_[k].hasPoint = membership(sampling.pools[k].points);
        pools_[k].hasLine = membership(sampling.pools[k].lines);
    }
    const size_t kinds = sampling.kinds.size();
    logMissOne_.resize(kinds);
    enumeratedSamples_.assign(kinds, 0);
    unseen_.resize(kinds);
    for (size_t k = 0; k < kinds; ++k)
    {
        const MixedSampling::Kind& kind = sampling.kinds[k];
        const MixedSampling::Pool& pool = sampling.pools[kind.pool];
        // The probability of drawing one given sample of this kind is 1 / (number of its samples).
        logMissOne_[k] = std::log1p(-allGood(kind.points, (int)pool.points.size(), kind.points) *
                                    allGood(kind.lines, (int)pool.lines.size(), kind.lines));
        const long distinct = combinationCount((int)pool.points.size(), kind.points, kMaxEnumeratedSamples) *
                              combinationCount((int)pool.lines.size(), kind.lines, kMaxEnumeratedSamples);
        if (distinct <= kMaxEnumeratedSamples)
            enumeratedSamples_[k] = distinct;
    }
}

void MixedSampler::setInliers(const FeatureSubset& inliers, const FeatureSubset& sample)
{
    const auto count = [](const std::vector<int>& inliers, const std::vector<int>& sample,
                          const std::vector<unsigned char>& pool, Support& support) {
        int all = 0, own = 0;
        for (int i : inliers)
            if (i < (int)pool.size() && pool[i])
            {
                ++all;
                own += std::find(sample.begin(), sample.end(), i) != sample.end();
            }
        support.inliers = all > own ? all : 0;
        support.beyondSample = all - own;
        support.sampleInliers = own;
    };
    for (PoolState& pool : pools_)
    {
        count(inliers.points, sample.points, pool.hasPoint, pool.points);
        count(inliers.lines, sample.lines, pool.hasLine, pool.lines);
    }
}

double MixedSampler::successProbability(int k) const
{
    const MixedSampling::Kind& kind = sampling_.kinds[k];
    const MixedSampling::Pool& pool = sampling_.pools[kind.pool];
    const PoolState& state = pools_[kind.pool];
    return allGood(state.points.inliers, (int)pool.points.size(), kind.points) *
           allGood(state.lines.inliers, (int)pool.lines.size(), kind.lines);
}

double MixedSampler::choiceWeight(int k) const
{
    const MixedSampling::Kind& kind = sampling_.kinds[k];
    const MixedSampling::Pool& pool = sampling_.pools[kind.pool];
    const PoolState& state = pools_[kind.pool];
    return allGood(state.points.beyondSample, (int)pool.points.size() - state.points.sampleInliers, kind.points) *
           allGood(state.lines.beyondSample, (int)pool.lines.size() - state.lines.sampleInliers, kind.lines);
}

bool MixedSampler::canDraw(int k) const
{
    const MixedSampling::Kind& kind = sampling_.kinds[k];
    const MixedSampling::Pool& pool = sampling_.pools[kind.pool];
    return kind.points <= (int)pool.points.size() && kind.lines <= (int)pool.lines.size();
}

bool MixedSampler::available(int k) const
{
    return canDraw(k) && !(enumeratedSamples_[k] > 0 && drawn_[k] >= enumeratedSamples_[k]);
}

int MixedSampler::chooseKind()
{
    const int kinds = (int)sampling_.kinds.size();
    double supported = 0;
    int drawable = 0;
    for (int k = 0; k < kinds; ++k)
    {
        weights_[k] = choiceWeight(k) / sampling_.kinds[k].cost;
        supported += weights_[k];
        drawable += available(k);
    }
    if (drawable == 0)
        return -1;
    // Each kind's weight: its part of the uniform share (all of the weight while no model has
    // support beyond its sample) and its share of the choice weights.
    const double uniform = supported > 0 ? kExplorationShare : 1.0;
    for (int k = 0; k < kinds; ++k)
        weights_[k] = available(k) ? uniform / drawable + (1 - uniform) * (supported > 0 ? weights_[k] / supported : 0.0)
                                 : 0.0;
    // 32 random bits in [0, 1): the weights sum to 1.
    const double u = rng_.next() / 4294967296.0;
    double sum = 0;
    int last = -1;
    for (int k = 0; k < kinds; ++k)
    {
        if (!(weights_[k] > 0))
            continue;
        last = k;
        sum += weights_[k];
        if (u < sum)
            return k;
    }
    return last;
}

void MixedSampler::drawDistinct(const std::vector<int>& pool, int count, std::vector<int>& out)
{
    out.clear();
    for (int k = 0; k < count; ++k)
    {
        int f;
        do
            f = pool[rng_.uniform(0, (int)pool.size())];
        while (std::find(out.begin(), out.end(), f) != out.end());
        out.push_back(f);
    }
}

void MixedSampler::drawUnseen(int k, FeatureSubset& sample)
{
    const MixedSampling::Kind& kind = sampling_.kinds[k];
    const MixedSampling::Pool& pool = sampling_.pools[kind.pool];
    std::vector<int>& unseen = unseen_[k];
    if (drawn_[k] == 0)
    {
        unseen.resize((size_t)enumeratedSamples_[k]);
        for (size_t i = 0; i < unseen.size(); ++i)
            unseen[i] = (int)i;
    }
    // One of the samples not drawn yet, uniformly; the last takes its place.
    const int at = rng_.uniform(0, (int)unseen.size());
    const int index = unseen[at];
    unseen[at] = unseen.back();
    unseen.pop_back();
    const long lineCombinations = combinationCount((int)pool.lines.size(), kind.lines, kMaxEnumeratedSamples);
    sample.points.clear();
    sample.lines.clear();
    appendCombination(index / lineCombinations, (int)pool.points.size(), kind.points, pool.points, sample.points);
    appendCombination(index % lineCombinations, (int)pool.lines.size(), kind.lines, pool.lines, sample.lines);
}

bool MixedSampler::next(FeatureSubset& sample)
{
    const int k = chooseKind();
    if (k < 0)
        return false;
    const MixedSampling::Kind& kind = sampling_.kinds[k];
    if (enumeratedSamples_[k] > 0)
        drawUnseen(k, sample);
    else
    {
        drawDistinct(sampling_.pools[kind.pool].points, kind.points, sample.points);
        drawDistinct(sampling_.pools[kind.pool].lines, kind.lines, sample.lines);
    }
    ++drawn_[k];
    return true;
}

bool MixedSampler::confident(double confidence) const
{
    // log of the probability that every sample drawn so far had an outlier; log1p keeps tiny
    // success probabilities from rounding to no progress.
    double logAllFailed = 0;
    for (size_t k = 0; k < drawn_.size(); ++k)
    {
        if (drawn_[k] == 0)
            continue;
        const double p = successProbability((int)k);
        if (p >= 1.0)
            return true;
        logAllFailed += drawn_[k] * std::log1p(-p);
    }
    const double logMissed = std::log1p(-confidence);
    return logAllFailed <= logMissed || coveredTo(logMissed);
}

bool MixedSampler::covered(double confidence) const
{
    return coveredTo(std::log1p(-confidence));
}

bool MixedSampler::coveredTo(double logMissed) const
{
    bool drawable = false;
    for (size_t k = 0; k < drawn_.size(); ++k)
    {
        if (!canDraw((int)k))
            continue;
        drawable = true;
        if (enumeratedSamples_[k] > 0)
        {
            // Drawn without replacement: a given sample is missed with probability 1 - drawn / N
            // (log1p(-1) = -inf once all are drawn).
            if (!(std::log1p(-std::min(1.0, double(drawn_[k]) / enumeratedSamples_[k])) <= logMissed))
                return false;
            continue;
        }
        // A kind with a single sample is covered once drawn (log1p(-1) = -inf; not drawn: NaN, false).
        if (!(drawn_[k] * logMissOne_[k] <= logMissed))
            return false;
    }
    return drawable;
}

} // namespace tripose
