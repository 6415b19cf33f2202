// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The support library's JSON values, which the evaluation's drivers read back.

#include "test_precomp.hpp"

#include <cstdlib>
#include <limits>

#include "tripose_support/json_writing.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::jsonEscape;
using cv::tripose::support::jsonMatrix;
using cv::tripose::support::jsonNumber;

TEST(Tripose_JsonWriting, seventeen_digits_read_back_as_the_same_double)
{
    RNG rng(5);
    for (int i = 0; i < 1000; ++i)
    {
        // One draw per statement, as C++ leaves the order of operands unspecified: the mantissa before
        // the exponent is the order the seeded numbers were drawn in so far (GCC's).
        const double mantissa = rng.gaussian(1.0);
        const double x = mantissa * std::pow(10.0, rng.uniform(-30, 30));
        EXPECT_EQ(std::strtod(jsonNumber(x, 17).c_str(), nullptr), x) << jsonNumber(x, 17);
    }
    EXPECT_EQ(jsonNumber(0.1 + 0.2, 10), "0.3");
}

TEST(Tripose_JsonWriting, numbers_json_cannot_hold_are_null)
{
    EXPECT_EQ(jsonNumber(std::numeric_limits<double>::quiet_NaN(), 17), "null");
    EXPECT_EQ(jsonNumber(std::numeric_limits<double>::infinity(), 17), "null");
    EXPECT_EQ(jsonNumber(-std::numeric_limits<double>::infinity(), 10), "null");
}

TEST(Tripose_JsonWriting, a_matrix_is_an_array_of_its_rows)
{
    EXPECT_EQ(jsonMatrix((Mat_<double>(2, 3) << 1, 2.5, -3, 4, 5, 6e-20), 10), "[[1,2.5,-3],[4,5,6e-20]]");
    EXPECT_EQ(jsonMatrix(Mat(0, 3, CV_64F), 10), "[]");
    EXPECT_EQ(jsonMatrix((Mat_<double>(1, 1) << std::numeric_limits<double>::quiet_NaN()), 10), "[[null]]");
    EXPECT_THROW(jsonMatrix(Mat::ones(2, 2, CV_32F), 10), cv::Exception);
}

TEST(Tripose_JsonWriting, text_stays_one_string)
{
    EXPECT_EQ(jsonEscape("a \"b\" \\c"), "a \\\"b\\\" \\\\c");
    EXPECT_EQ(jsonEscape("line\nbreak\ttab"), "line break tab");
}

} // namespace
} // namespace opencv_test
