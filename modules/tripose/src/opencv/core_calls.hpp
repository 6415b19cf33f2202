// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_CORE_CALLS_HPP
#define OPENCV_TRIPOSE_OPENCV_CORE_CALLS_HPP

#include "opencv2/core.hpp"

#include "../core/support/error.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! The algorithms' namespace, as the module's sources name it.
namespace core = ::tripose;

//! The cv::Exception code of a core error (an Error::Code: OpenCV 5's cv::error takes the enum, 4.x an int).
inline Error::Code errorCodeFor(core::ErrorCode code)
{
    switch (code)
    {
    case core::ErrorCode::BadArgument: return Error::StsBadArg;
    case core::ErrorCode::BadSize: return Error::StsBadSize;
    case core::ErrorCode::Internal: break;
    }
    return Error::StsInternal;
}

/** Runs @p body, turning a core error into the cv::Exception that OpenCV users catch, with the
same message, raised from @p function.
*/
template <class Body>
auto callCore(const char* function, const char* file, int line, Body body) -> decltype(body())
{
    try
    {
        return body();
    }
    catch (const core::Error& e)
    {
        cv::error(errorCodeFor(e.code()), e.what(), function, file, line); // does not return
    }
}

} // namespace detail
} // namespace tripose
} // namespace cv

//! callCore() from the calling entry point, whose name and place the exception reports.
#define TRIPOSE_CALL_CORE(body) ::cv::tripose::detail::callCore(CV_Func, __FILE__, __LINE__, body)

#endif // OPENCV_TRIPOSE_OPENCV_CORE_CALLS_HPP
