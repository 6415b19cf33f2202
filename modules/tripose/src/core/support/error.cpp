// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "error.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace tripose {

namespace {

std::string formatArguments(const char* format, va_list arguments)
{
    va_list copy;
    va_copy(copy, arguments);
    const int length = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    if (length <= 0)
        return std::string();
    std::vector<char> buffer((size_t)length + 1);
    std::vsnprintf(buffer.data(), buffer.size(), format, arguments);
    return std::string(buffer.data(), (size_t)length);
}

} // namespace

void fail(ErrorCode code, const char* format, ...)
{
    va_list arguments;
    va_start(arguments, format);
    const std::string message = formatArguments(format, arguments);
    va_end(arguments);
    throw Error(code, message);
}

std::string formatString(const char* format, ...)
{
    va_list arguments;
    va_start(arguments, format);
    const std::string text = formatArguments(format, arguments);
    va_end(arguments);
    return text;
}

namespace support_detail {

void failAssertion(const char* expression, const char* file, int line)
{
    fail(ErrorCode::Internal, "internal check failed: %s (%s:%d)", expression, file, line);
}

} // namespace support_detail

} // namespace tripose
