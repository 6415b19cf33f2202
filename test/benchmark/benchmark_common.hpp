// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers shared by the benchmark programs: medians and pose errors.

#ifndef TRIPOSE_BENCHMARK_COMMON_HPP
#define TRIPOSE_BENCHMARK_COMMON_HPP

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_benchmark {

inline double median(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

//! Angle (degrees) of the rotation between two 3x3 rotation matrices.
inline double rotationErrorDeg(const cv::Mat& A, const cv::Mat& B)
{
    return 2.0 * std::asin(std::min(1.0, cv::norm(A, B) / (2.0 * std::sqrt(2.0)))) * 180.0 / CV_PI;
}

inline double translationError(const cv::Mat& a, const cv::Mat& b)
{
    return cv::norm(a, b) / cv::norm(b);
}

} // namespace tripose_benchmark

#endif // TRIPOSE_BENCHMARK_COMMON_HPP
