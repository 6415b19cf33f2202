// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/combinations.hpp"
#include "../support/error.hpp"

#include "sample_generator.hpp"

namespace tripose {

SampleGenerator::SampleGenerator(int numFeatures, int sampleSize, long maxDraws, uint64_t seed)
    : numFeatures_(numFeatures), sampleSize_(sampleSize), rng_(seed)
{
    TRIPOSE_ASSERT(sampleSize > 0 && numFeatures >= sampleSize);
    const long limit = std::min<long>(kEnumerationLimit, maxDraws);
    const long distinct = combinationCount(numFeatures, sampleSize, limit);
    if (distinct > limit)
        return;
    // All combinations in lexicographic order, then a Fisher-Yates shuffle of whole samples.
    samples_.reserve((size_t)distinct * sampleSize);
    std::vector<int> c(sampleSize);
    for (int i = 0; i < sampleSize; ++i)
        c[i] = i;
    do
        samples_.insert(samples_.end(), c.begin(), c.end());
    while (nextCombination(c, numFeatures));
    for (long s = distinct - 1; s > 0; --s)
    {
        const int r = rng_.uniform(0, (int)s + 1);
        if (r != s)
            std::swap_ranges(samples_.begin() + s * sampleSize, samples_.begin() + (s + 1) * sampleSize,
                             samples_.begin() + (long)r * sampleSize);
    }
}

bool SampleGenerator::next(std::vector<int>& sample)
{
    sample.resize(sampleSize_);
    if (enumerates())
    {
        if (position_ >= samples_.size())
            return false;
        std::copy(samples_.begin() + position_, samples_.begin() + position_ + sampleSize_, sample.begin());
        position_ += sampleSize_;
        return true;
    }
    for (int k = 0; k < sampleSize_; ++k)
    {
        int f;
        do
            f = rng_.uniform(0, numFeatures_);
        while (std::find(sample.begin(), sample.begin() + k, f) != sample.begin() + k);
        sample[k] = f;
    }
    return true;
}

} // namespace tripose
