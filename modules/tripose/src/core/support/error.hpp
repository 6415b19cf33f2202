// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_SUPPORT_ERROR_HPP
#define TRIPOSE_CORE_SUPPORT_ERROR_HPP

#include <stdexcept>
#include <string>

namespace tripose {

//! What kind of failure an Error reports; each adapter maps it to its own exception type.
enum class ErrorCode
{
    BadArgument, //!< A value the caller passed is out of range, non-finite or inconsistent.
    BadSize,     //!< Arrays that must agree in size do not.
    Internal     //!< An invariant of the library failed: a bug, never the caller's input.
};

/** The one exception the core throws. Its message names the caller's argument (as the adapter
called it) and says what was expected, so that each language's binding can pass it on unchanged.
*/
class Error : public std::runtime_error
{
public:
    Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const { return code_; }

private:
    ErrorCode code_;
};

//! Throws Error(@p code) with a printf-style message.
[[noreturn]] void fail(ErrorCode code, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

//! printf-style formatting into a std::string.
std::string formatString(const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/** Runs @p step, whose input the caller built from its own state: an Error about that input (a
degenerate geometry) is caught and its message put in @p reason, while an ErrorCode::Internal one,
a bug, propagates. True when @p step returned. */
template <typename Step>
bool runCatchingInputErrors(Step&& step, std::string* reason = nullptr)
{
    try
    {
        step();
        return true;
    }
    catch (const Error& e)
    {
        if (e.code() == ErrorCode::Internal)
            throw;
        if (reason)
            *reason = e.what();
        return false;
    }
}

namespace support_detail {
[[noreturn]] void failAssertion(const char* expression, const char* file, int line);
} // namespace support_detail

} // namespace tripose

//! An invariant of the core (not a check of the caller's input): Error(ErrorCode::Internal) when false.
#define TRIPOSE_ASSERT(expression)                                                                   \
    do                                                                                               \
    {                                                                                                \
        if (!(expression))                                                                           \
            ::tripose::support_detail::failAssertion(#expression, __FILE__, __LINE__);               \
    } while (false)

//! TRIPOSE_ASSERT in debug builds only: for checks on paths too hot to pay for one in release.
#ifdef NDEBUG
#define TRIPOSE_DEBUG_ASSERT(expression) ((void)0)
#else
#define TRIPOSE_DEBUG_ASSERT(expression) TRIPOSE_ASSERT(expression)
#endif

#endif // TRIPOSE_CORE_SUPPORT_ERROR_HPP
