// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tripose_support/json_writing.hpp"

#include <cmath>
#include <cstdio>

namespace cv {
namespace tripose {
namespace support {

std::string jsonNumber(double x, int significantDigits)
{
    if (!std::isfinite(x))
        return "null";
    char text[40];
    std::snprintf(text, sizeof(text), "%.*g", significantDigits, x);
    return text;
}

std::string jsonMatrix(const Mat& m, int significantDigits)
{
    CV_Assert(m.empty() || (m.type() == CV_64FC1 && m.dims == 2));
    std::string s = "[";
    for (int r = 0; r < m.rows; ++r)
    {
        s += r ? ",[" : "[";
        for (int c = 0; c < m.cols; ++c)
            s += (c ? "," : "") + jsonNumber(m.at<double>(r, c), significantDigits);
        s += "]";
    }
    return s + "]";
}

std::string jsonEscape(const std::string& text)
{
    std::string out;
    for (char c : text)
    {
        if (static_cast<unsigned char>(c) < 0x20)
        {
            out += ' ';
            continue;
        }
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    return out;
}

} // namespace support
} // namespace tripose
} // namespace cv
