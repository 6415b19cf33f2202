// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers shared by the benchmark programs (pose errors come from the support library).

#ifndef TRIPOSE_BENCHMARK_COMMON_HPP
#define TRIPOSE_BENCHMARK_COMMON_HPP

#include <algorithm>
#include <vector>

namespace tripose_benchmark {

inline double median(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

} // namespace tripose_benchmark

#endif // TRIPOSE_BENCHMARK_COMMON_HPP
