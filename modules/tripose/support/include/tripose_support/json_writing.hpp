// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// JSON values for the tools that write one JSON object per line for drivers in other languages
// (tripose_evaluate, tripose_images_report --dump-inputs). Part of the tripose support library
// (built beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_JSON_WRITING_HPP
#define TRIPOSE_SUPPORT_JSON_WRITING_HPP

#include <string>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

/** A number with @p significantDigits significant digits (17 give back the same double when read),
or null where it is not finite: JSON has no NaN or infinity. */
std::string jsonNumber(double x, int significantDigits);

/** A CV_64F matrix as an array of its rows, each an array of jsonNumber()s; a matrix with no rows is
[]. */
std::string jsonMatrix(const Mat& m, int significantDigits);

//! A text to be put between quotes: quotes and backslashes escaped, control characters blanked.
std::string jsonEscape(const std::string& text);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_JSON_WRITING_HPP
