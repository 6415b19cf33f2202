// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <cmath>
#include <set>

#include "../src/core/robust/mixed_sampler.hpp"

namespace opencv_test {
namespace {

using ::tripose::FeatureSubset;
using ::tripose::MixedSampler;
using ::tripose::MixedSampling;

//! The four kinds of the three-view problem over pools of @p points points and @p lines lines (every
//! third index, so that the pools are not the first indices).
MixedSampling threeFeatureKinds(int points, int lines)
{
    MixedSampling sampling;
    for (int p = 3; p >= 0; --p)
        sampling.kinds.push_back(MixedSampling::Kind{ p, 3 - p, 1.0, 0 });
    sampling.pools.resize(1);
    for (int i = 0; i < points; ++i)
        sampling.pools[0].points.push_back(3 * i);
    for (int i = 0; i < lines; ++i)
        sampling.pools[0].lines.push_back(3 * i + 1);
    return sampling;
}

FeatureSubset firstOfPools(const MixedSampling& sampling, int points, int lines)
{
    FeatureSubset subset;
    const MixedSampling::Pool& pool = sampling.pools[0];
    subset.points.assign(pool.points.begin(), pool.points.begin() + points);
    subset.lines.assign(pool.lines.begin(), pool.lines.begin() + lines);
    return subset;
}

//! A kind of @p points points from one pool of @p size points (features 0 .. size - 1).
MixedSampling pointKind(int points, int size)
{
    MixedSampling sampling;
    sampling.kinds.push_back(MixedSampling::Kind{ points, 0, 1.0, 0 });
    sampling.pools.resize(1);
    for (int i = 0; i < size; ++i)
        sampling.pools[0].points.push_back(i);
    return sampling;
}

//! Samples needed to draw, with confidence 0.999, one that succeeds with probability @p p.
long samplesForConfidence(double p)
{
    return (long)std::ceil(std::log(1 - 0.999) / std::log(1 - p));
}

//! Draws from @p sampler until it is confident at 0.999; the number of draws, or -1 past 100000.
long drawsUntilConfident(MixedSampler& sampler)
{
    FeatureSubset sample;
    long drawn = 0;
    while (!sampler.confident(0.999))
    {
        if (!sampler.next(sample) || ++drawn > 100000)
            return -1;
    }
    return drawn;
}

// Samples are one kind's distinct features from its pools; without a model every kind is drawn.
TEST(Tripose_MixedSampler, samples_are_distinct_pool_features_of_one_kind)
{
    const MixedSampling sampling = threeFeatureKinds(10, 100);
    MixedSampler sampler(sampling, 3);
    FeatureSubset sample;
    for (int draw = 0; draw < 2000; ++draw)
    {
        ASSERT_TRUE(sampler.next(sample));
        ASSERT_EQ(3, sample.size());
        bool kindFound = false;
        for (const MixedSampling::Kind& kind : sampling.kinds)
            kindFound = kindFound || ((int)sample.points.size() == kind.points && (int)sample.lines.size() == kind.lines);
        EXPECT_TRUE(kindFound);
        for (const std::vector<int>* drawn : { &sample.points, &sample.lines })
        {
            const std::vector<int>& pool = drawn == &sample.points ? sampling.pools[0].points : sampling.pools[0].lines;
            for (size_t a = 0; a < drawn->size(); ++a)
            {
                EXPECT_NE(std::find(pool.begin(), pool.end(), (*drawn)[a]), pool.end());
                for (size_t b = a + 1; b < drawn->size(); ++b)
                    EXPECT_NE((*drawn)[a], (*drawn)[b]);
            }
        }
    }
    // Uniform while no model has inliers, until the 120 P3P samples (C(10, 3)) are all drawn, once each.
    EXPECT_EQ(120, sampler.samplesOfKind()[0]);
    for (int k = 1; k < 4; ++k)
        EXPECT_GT(sampler.samplesOfKind()[k], 500) << "2000 draws of four kinds";
}

// The kinds follow the inlier ratios, but for a tenth of the samples chosen uniformly: no point
// inlier leaves three-line samples and that tenth; lines of which one in ten is an inlier, beside
// points all inliers, leave mostly three-point samples.
TEST(Tripose_MixedSampler, kinds_follow_the_inlier_ratios)
{
    const MixedSampling sampling = threeFeatureKinds(10, 100);
    const FeatureSubset noSample;
    MixedSampler linesOnly(sampling, 5);
    linesOnly.setInliers(firstOfPools(sampling, 0, 50), noSample);
    FeatureSubset sample;
    for (int draw = 0; draw < 1000; ++draw)
        ASSERT_TRUE(linesOnly.next(sample));
    // Expected 925 three-line samples, 25 of each other kind.
    EXPECT_GT(linesOnly.samplesOfKind()[3], 880);
    for (int k = 0; k < 3; ++k)
        EXPECT_LT(linesOnly.samplesOfKind()[k], 50);

    // Forty points (C(40, 3) = 9880 P3P samples, more than are drawn here).
    const MixedSampling morePoints = threeFeatureKinds(40, 100);
    MixedSampler pointsFirst(morePoints, 5);
    pointsFirst.setInliers(firstOfPools(morePoints, 40, 10), noSample);
    for (int draw = 0; draw < 1000; ++draw)
        ASSERT_TRUE(pointsFirst.next(sample));
    // Success probabilities 1, 0.1, 0.0091, 0.00073: P3P about 84 % of the samples, P3L 2.6 %.
    EXPECT_GT(pointsFirst.samplesOfKind()[0], 790);
    EXPECT_LT(pointsFirst.samplesOfKind()[3], 50);

    // Features outside the pools do not count: no support, every kind alike.
    MixedSampler outside(sampling, 5);
    FeatureSubset notInPools;
    notInPools.points = { 1, 2, 4 };
    notInPools.lines = { 0, 3, 6 };
    outside.setInliers(notInPools, noSample);
    for (int draw = 0; draw < 400; ++draw)
        ASSERT_TRUE(outside.next(sample));
    for (int count : outside.samplesOfKind())
        EXPECT_GT(count, 50);
}

// The features of the sample a model came from fit it by construction: with a pool of three points, the
// three of a P3P sample are no evidence that the next P3P sample is all inliers.
TEST(Tripose_MixedSampler, the_model_s_own_sample_is_no_support)
{
    const MixedSampling sampling = threeFeatureKinds(3, 60);
    MixedSampler sampler(sampling, 9);
    const FeatureSubset own = firstOfPools(sampling, 3, 0);
    sampler.setInliers(own, own);
    FeatureSubset sample;
    ASSERT_TRUE(sampler.next(sample));
    EXPECT_FALSE(sampler.confident(0.999));
    for (int draw = 0; draw < 400; ++draw)
        ASSERT_TRUE(sampler.next(sample));
    EXPECT_FALSE(sampler.confident(0.999));
    // No support beyond the sample: every kind alike (the single P3P sample of three points drawn once).
    EXPECT_EQ(1, sampler.samplesOfKind()[0]);
    for (int k = 1; k < 4; ++k)
        EXPECT_GT(sampler.samplesOfKind()[k], 80);

    // The same three points as inliers of a model from three lines are support.
    FeatureSubset lines = firstOfPools(sampling, 0, 3);
    FeatureSubset inliers = lines;
    inliers.points = own.points;
    MixedSampler supported(sampling, 9);
    supported.setInliers(inliers, lines);
    // P3P has all the success probability (92.5 % of the samples): once one is drawn, it is enough.
    for (int draw = 0; draw < 20 && supported.samplesOfKind()[0] == 0; ++draw)
    {
        EXPECT_FALSE(supported.confident(0.999));
        ASSERT_TRUE(supported.next(sample));
    }
    EXPECT_TRUE(supported.confident(0.999));
}

// With one kind the stopping rule is the usual adaptive RANSAC bound (all-inlier probability of a
// sample drawn without replacement); with several, the samples of every kind count.
TEST(Tripose_MixedSampler, stops_at_the_requested_confidence)
{
    const MixedSampling points = pointKind(3, 100);
    MixedSampler sampler(points, 1);
    sampler.setInliers(firstOfPools(points, 50, 0), FeatureSubset());
    EXPECT_EQ(samplesForConfidence(50.0 / 100 * 49.0 / 99 * 48.0 / 98), drawsUntilConfident(sampler));

    // All pool features inliers: one sample of a kind is enough.
    const MixedSampling mixed = threeFeatureKinds(10, 100);
    MixedSampler clean(mixed, 1);
    clean.setInliers(firstOfPools(mixed, 10, 100), FeatureSubset());
    EXPECT_FALSE(clean.confident(0.999));
    FeatureSubset sample;
    ASSERT_TRUE(clean.next(sample));
    EXPECT_TRUE(clean.confident(0.999));
}

//! Draws needed to cover, at 0.999, a kind of @p samples distinct samples drawn without replacement.
long drawsToCover(long samples)
{
    return (long)std::ceil(0.999 * samples);
}

// Where the best model's support lies in no pool a kind draws from (only its own sample's features
// are there), its inlier counts cannot stop the search; it stops once every kind has been drawn so
// often that any one of its samples would have been drawn with the confidence.
TEST(Tripose_MixedSampler, stops_once_every_kind_is_covered)
{
    // Few distinct samples: drawn without replacement, covered once a share 0.999 of them is drawn
    // (drawn with replacement it took samplesForConfidence(1.0 / 120) = 826 draws).
    const MixedSampling points = pointKind(3, 10);
    const FeatureSubset own = firstOfPools(points, 3, 0);
    MixedSampler sampler(points, 4);
    sampler.setInliers(own, own);
    EXPECT_EQ(drawsToCover(120), drawsUntilConfident(sampler)) << "C(10, 3) = 120 samples";

    // Two kinds: both must be covered, P2P1L's 450 samples (C(10, 2) x 10) as well as P3P's 120.
    MixedSampling two = points;
    two.kinds.push_back(MixedSampling::Kind{ 2, 1, 1.0, 0 });
    for (int i = 0; i < 10; ++i)
        two.pools[0].lines.push_back(i);
    MixedSampler both(two, 4);
    both.setInliers(own, own);
    ASSERT_GT(drawsUntilConfident(both), 0);
    EXPECT_GE(both.samplesOfKind()[0], drawsToCover(120));
    EXPECT_LE(both.samplesOfKind()[0], 120) << "no P3P sample drawn twice";
    EXPECT_EQ(drawsToCover(450), both.samplesOfKind()[1]) << "the last kind to be covered ends the search";
    EXPECT_TRUE(both.covered(0.9999)) << "all samples of both kinds drawn";

    // Many distinct samples (C(40, 3) = 9880 P3P and C(40, 2) x 40 = 31200 P2P1L): the P2P1L kind is
    // drawn with replacement and covered by the probability of missing a sample.
    MixedSampling many = pointKind(3, 40);
    many.kinds.push_back(MixedSampling::Kind{ 2, 1, 1.0, 0 });
    for (int i = 0; i < 40; ++i)
        many.pools[0].lines.push_back(i);
    MixedSampler large(many, 4);
    large.setInliers(firstOfPools(many, 3, 0), firstOfPools(many, 3, 0));
    FeatureSubset sample;
    for (int draw = 0; draw < 25000; ++draw)
        ASSERT_TRUE(large.next(sample));
    EXPECT_EQ(9880, large.samplesOfKind()[0]) << "every P3P sample drawn, none twice";
    EXPECT_EQ(25000 - 9880, large.samplesOfKind()[1]);
    EXPECT_FALSE(large.covered(0.999));

    // A kind with a single sample (three points of a pool of three) is covered once it is drawn.
    const MixedSampling three = pointKind(3, 3);
    const FeatureSubset all = firstOfPools(three, 3, 0);
    MixedSampler once(three, 4);
    once.setInliers(all, all);
    EXPECT_FALSE(once.confident(0.999));
    EXPECT_EQ(1, drawsUntilConfident(once));
}

// A kind of few samples is drawn without replacement: every sample once, each one of the kind's
// distinct feature sets, and then the kind is not drawn again.
TEST(Tripose_MixedSampler, few_samples_are_each_drawn_once)
{
    MixedSampling sampling;
    sampling.kinds.push_back(MixedSampling::Kind{ 1, 2, 1.0, 0 });
    sampling.pools.resize(1);
    for (int i = 0; i < 6; ++i)
        sampling.pools[0].points.push_back(5 * i);
    for (int i = 0; i < 7; ++i)
        sampling.pools[0].lines.push_back(5 * i + 2);
    MixedSampler sampler(sampling, 11);
    std::set<std::vector<int>> seen;
    FeatureSubset sample;
    const int distinct = 6 * 21; // C(6, 1) x C(7, 2)
    for (int draw = 0; draw < distinct; ++draw)
    {
        ASSERT_TRUE(sampler.next(sample));
        ASSERT_EQ(1u, sample.points.size());
        ASSERT_EQ(2u, sample.lines.size());
        ASSERT_EQ(0, sample.points[0] % 5);
        ASSERT_NE(sample.lines[0], sample.lines[1]);
        for (int line : sample.lines)
            ASSERT_EQ(2, line % 5);
        std::vector<int> key = { sample.points[0], std::min(sample.lines[0], sample.lines[1]),
                                 std::max(sample.lines[0], sample.lines[1]) };
        EXPECT_TRUE(seen.insert(key).second) << "drawn twice at draw " << draw;
    }
    EXPECT_EQ((size_t)distinct, seen.size());
    EXPECT_TRUE(sampler.covered(0.999999));
    EXPECT_FALSE(sampler.next(sample)) << "nothing left to draw";
}

TEST(Tripose_MixedSampler, same_seed_same_samples)
{
    const MixedSampling sampling = threeFeatureKinds(10, 60);
    MixedSampler a(sampling, 42), b(sampling, 42);
    FeatureSubset inliers = firstOfPools(sampling, 4, 30);
    a.setInliers(inliers, FeatureSubset());
    b.setInliers(inliers, FeatureSubset());
    FeatureSubset sa, sb;
    for (int draw = 0; draw < 500; ++draw)
    {
        ASSERT_TRUE(a.next(sa));
        ASSERT_TRUE(b.next(sb));
        ASSERT_EQ(sa.points, sb.points);
        ASSERT_EQ(sa.lines, sb.lines);
    }
}

// Pools too small for any kind: nothing to draw.
TEST(Tripose_MixedSampler, no_sample_from_pools_too_small)
{
    MixedSampling sampling;
    sampling.kinds.push_back(MixedSampling::Kind{ 3, 0, 1.0, 0 });
    sampling.pools.resize(1);
    sampling.pools[0].points = { 0, 1 };
    MixedSampler sampler(sampling, 0);
    FeatureSubset sample;
    EXPECT_FALSE(sampler.next(sample));
}

// Two pools (the cameras of a stereo rig at time B): a sample's features all come from the pool of
// its kind, and each kind's all-inlier probability is counted in its own pool.
TEST(Tripose_MixedSampler, a_sample_comes_from_the_pool_of_its_kind)
{
    MixedSampling sampling;
    sampling.pools.resize(2);
    for (int i = 0; i < 40; ++i)
    {
        sampling.pools[0].points.push_back(i);       // points 0-39 and lines 0-19 in the first
        sampling.pools[1].points.push_back(i + 20);  // points 20-59 and lines 10-29 in the second
    }
    for (int i = 0; i < 20; ++i)
    {
        sampling.pools[0].lines.push_back(i);
        sampling.pools[1].lines.push_back(i + 10);
    }
    for (int pool = 0; pool < 2; ++pool)
        for (int p = 3; p >= 0; --p)
            sampling.kinds.push_back(MixedSampling::Kind{ p, 3 - p, 1.0, pool });
    MixedSampler sampler(sampling, 5);
    FeatureSubset sample;
    int fromFirstOnly = 0, fromSecondOnly = 0;
    for (int draw = 0; draw < 2000; ++draw)
    {
        ASSERT_TRUE(sampler.next(sample));
        ASSERT_EQ(3, sample.size());
        bool inFirst = true, inSecond = true;
        for (int i : sample.points)
        {
            inFirst = inFirst && i < 40;
            inSecond = inSecond && i >= 20;
        }
        for (int i : sample.lines)
        {
            inFirst = inFirst && i < 20;
            inSecond = inSecond && i >= 10;
        }
        ASSERT_TRUE(inFirst || inSecond);
        fromFirstOnly += inFirst && !inSecond;
        fromSecondOnly += inSecond && !inFirst;
    }
    EXPECT_GT(fromFirstOnly, 100);
    EXPECT_GT(fromSecondOnly, 100);

    // Every feature of the second pool inlier, none of the first beyond the shared ones: the second
    // pool's samples are certain, the first's are not, so the sampler is confident once it has
    // drawn a sample of the second pool and not before.
    FeatureSubset inliers;
    for (int i = 20; i < 60; ++i)
        inliers.points.push_back(i);
    for (int i = 10; i < 30; ++i)
        inliers.lines.push_back(i);
    MixedSampler supported(sampling, 9);
    supported.setInliers(inliers, FeatureSubset());
    EXPECT_FALSE(supported.confident(0.999));
    bool drewSecond = false;
    for (int draw = 0; draw < 200 && !drewSecond; ++draw)
    {
        ASSERT_TRUE(supported.next(sample));
        const std::vector<int>& counts = supported.samplesOfKind();
        for (int k = 4; k < 8; ++k)
            drewSecond = drewSecond || counts[k] > 0;
        EXPECT_EQ(drewSecond, supported.confident(0.999));
    }
    EXPECT_TRUE(drewSecond);
}

} // namespace
} // namespace opencv_test
