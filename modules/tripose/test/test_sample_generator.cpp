// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <set>

#include "../src/core/robust/sample_generator.hpp"

namespace opencv_test {
namespace {

using ::tripose::SampleGenerator;

std::vector<std::vector<int>> drawAll(SampleGenerator& generator, int limit)
{
    std::vector<std::vector<int>> drawn;
    std::vector<int> sample;
    while ((int)drawn.size() < limit && generator.next(sample))
        drawn.push_back(sample);
    return drawn;
}

TEST(Tripose_SampleGenerator, few_features_give_every_distinct_sample_once_then_run_dry)
{
    const int expected[] = { 1, 5, 15, 35, 70 }; // 4..8 choose 4
    for (int n = 4; n <= 8; ++n)
    {
        SampleGenerator generator(n, 4, 10000, 7);
        ASSERT_TRUE(generator.enumerates());
        const std::vector<std::vector<int>> drawn = drawAll(generator, 1000);
        ASSERT_EQ((int)drawn.size(), expected[n - 4]) << "n = " << n;
        std::set<std::vector<int>> distinct;
        for (std::vector<int> s : drawn)
        {
            std::sort(s.begin(), s.end());
            EXPECT_TRUE(std::adjacent_find(s.begin(), s.end()) == s.end());
            EXPECT_GE(s.front(), 0);
            EXPECT_LT(s.back(), n);
            distinct.insert(s);
        }
        EXPECT_EQ(distinct.size(), drawn.size()) << "n = " << n;
    }
}

TEST(Tripose_SampleGenerator, enumeration_order_follows_the_seed)
{
    SampleGenerator a(9, 4, 10000, 1), b(9, 4, 10000, 1), c(9, 4, 10000, 2);
    const std::vector<std::vector<int>> da = drawAll(a, 1000), db = drawAll(b, 1000), dc = drawAll(c, 1000);
    EXPECT_EQ(da, db);
    EXPECT_NE(da, dc);
    EXPECT_EQ(da.size(), 126u);
}

TEST(Tripose_SampleGenerator, many_features_or_a_small_budget_draw_at_random)
{
    // 40 choose 4 = 91390 exceeds the enumeration limit; 8 choose 4 = 70 exceeds a budget of 50.
    SampleGenerator many(40, 4, 10000, 3), budget(8, 4, 50, 3);
    EXPECT_FALSE(many.enumerates());
    EXPECT_FALSE(budget.enumerates());
    for (SampleGenerator* g : { &many, &budget })
    {
        const std::vector<std::vector<int>> drawn = drawAll(*g, 200);
        ASSERT_EQ(drawn.size(), 200u); // never runs dry
        for (std::vector<int> s : drawn)
        {
            std::sort(s.begin(), s.end());
            EXPECT_TRUE(std::adjacent_find(s.begin(), s.end()) == s.end());
        }
    }
}

}} // namespace
