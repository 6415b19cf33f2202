// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers shared by the benchmark programs (pose errors come from the support library).

#ifndef TRIPOSE_BENCHMARK_COMMON_HPP
#define TRIPOSE_BENCHMARK_COMMON_HPP

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "opencv2/core.hpp"
#include "tripose_support/pose_error.hpp"

namespace tripose_benchmark {

inline double median(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

//! A pose further than this from the truth counts as a failure (far beyond the noise of any scene here).
const double kFailedRotationDeg = 10.0;

//! Per method name, over every runInterleaved() call: (scenes run, scenes with a pose within
//! kFailedRotationDeg of the truth).
inline std::map<std::string, std::pair<int, int>>& solvedScenes()
{
    static std::map<std::string, std::pair<int, int>> counts;
    return counts;
}

/** 0 when every method run by runInterleaved() solved at least one of its scenes; otherwise names the
others on stderr and returns 1: the times reported for them are the times of failures.
*/
inline int failureStatus()
{
    int status = 0;
    for (const auto& m : solvedScenes())
        if (m.second.second == 0)
        {
            std::fprintf(stderr, "%s returned no pose within %.0f deg of the truth on any of its %d scenes: "
                                 "its times are not times of solving\n",
                         m.first.c_str(), kFailedRotationDeg, m.second.first);
            status = 1;
        }
    return status;
}

/** Runs every method of @p methods on scene @p s (index @p k) @p repeats times, interleaved so that
frequency changes and other load hit all of them alike. Per method: @p times receives the median
time in units of 1 / @p unitsPerSecond, @p errors the pose error of the last call against the
scene's truth (+inf when it found no pose or threw). Counts the scene in solvedScenes().
*/
template <typename Scene>
void runInterleaved(const Scene& s, int k,
                    const std::vector<std::pair<std::string, std::function<bool(const Scene&, int, cv::Mat&, cv::Mat&)>>>& methods,
                    int repeats, double unitsPerSecond, std::vector<double>& times,
                    std::vector<cv::tripose::support::PoseError>& errors)
{
    const size_t M = methods.size();
    std::vector<std::vector<double>> perScene(M);
    std::vector<cv::Mat> Rs(M), ts(M);
    std::vector<bool> ok(M, false);
    for (int r = 0; r < repeats; ++r)
        for (size_t m = 0; m < M; ++m)
        {
            cv::Mat R, t;
            bool solved = false;
            const int64 t0 = cv::getTickCount();
            try { solved = methods[m].second(s, k, R, t); } catch (const cv::Exception&) { solved = false; }
            const int64 t1 = cv::getTickCount();
            perScene[m].push_back(unitsPerSecond * double(t1 - t0) / cv::getTickFrequency());
            ok[m] = solved && !R.empty();
            Rs[m] = R;
            ts[m] = t;
        }
    times.assign(M, 0.0);
    errors.assign(M, cv::tripose::support::PoseError{ HUGE_VAL, HUGE_VAL, HUGE_VAL });
    for (size_t m = 0; m < M; ++m)
    {
        times[m] = median(perScene[m]);
        if (ok[m])
            errors[m] = cv::tripose::support::poseError(Rs[m], ts[m], s.R, s.t);
        std::pair<int, int>& count = solvedScenes()[methods[m].first];
        ++count.first;
        count.second += errors[m].rotationDeg < kFailedRotationDeg;
    }
}

} // namespace tripose_benchmark

#endif // TRIPOSE_BENCHMARK_COMMON_HPP
