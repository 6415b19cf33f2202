// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Combinations of k of n items: how many, and all of them in order. The samplers that draw each
// sample of a small set once (robust/sample_generator, robust/mixed_sampler) and the hypothesis
// starts that solve every subset of a small set (refine/hypothesis_starts) share them.
#ifndef TRIPOSE_CORE_SUPPORT_COMBINATIONS_HPP
#define TRIPOSE_CORE_SUPPORT_COMBINATIONS_HPP

#include <vector>

namespace tripose {

//! n choose k (0 when k > n), or @p cap + 1 once it exceeds @p cap: callers ask whether a set is small.
inline long combinationCount(int n, int k, long cap)
{
    if (k > n)
        return 0;
    long count = 1;
    for (int i = 1; i <= k; ++i)
    {
        count = count * (n - k + i) / i; // exact: a product of i consecutive integers is divisible by i!
        if (count > cap)
            return cap + 1;
    }
    return count;
}

//! Advances @p idx, a k-subset of [0, n) in increasing order, to the next in lexicographic order;
//! false after the last.
inline bool nextCombination(std::vector<int>& idx, int n)
{
    const int k = (int)idx.size();
    int i = k - 1;
    while (i >= 0 && idx[i] == n - k + i)
        --i;
    if (i < 0)
        return false;
    ++idx[i];
    for (int j = i + 1; j < k; ++j)
        idx[j] = idx[j - 1] + 1;
    return true;
}

} // namespace tripose

#endif // TRIPOSE_CORE_SUPPORT_COMBINATIONS_HPP
