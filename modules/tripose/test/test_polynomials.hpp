// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TEST_POLYNOMIALS_HPP
#define OPENCV_TRIPOSE_TEST_POLYNOMIALS_HPP

#include <vector>

#include "opencv2/core.hpp"

namespace opencv_test {

/** Ascending coefficients of lead * prod (x - r_i) * prod ((x - a_k)^2 + b_k^2): a polynomial whose
real roots are @p roots and whose complex roots are a_k +- i b_k (@p complexPairs), the ground truth
of the root finders' tests.
*/
inline std::vector<double> polynomialFromRoots(const std::vector<double>& roots,
                                               const std::vector<cv::Vec2d>& complexPairs, double lead)
{
    std::vector<double> c(1, lead);
    auto multiply = [&c](const std::vector<double>& f) {
        std::vector<double> out(c.size() + f.size() - 1, 0.0);
        for (size_t i = 0; i < c.size(); ++i)
            for (size_t j = 0; j < f.size(); ++j)
                out[i + j] += c[i] * f[j];
        c = out;
    };
    for (double r : roots)
        multiply({ -r, 1.0 });
    for (const cv::Vec2d& z : complexPairs)
        multiply({ z[0] * z[0] + z[1] * z[1], -2.0 * z[0], 1.0 });
    return c;
}

} // namespace opencv_test

#endif // OPENCV_TRIPOSE_TEST_POLYNOMIALS_HPP
