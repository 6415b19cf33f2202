// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The Python package's extension: numpy arrays in, the core's problems built and solved, numpy
// arrays out. Conversions only; every algorithm and every check of a value is the core's, so that
// Python and C++ report the same errors and return the same poses. The Python layer
// (python/tripose/__init__.py) gives the functions their documented signatures. Each topic binds
// itself in its own file; this one defines the module and maps the core's errors.

#include <nanobind/nanobind.h>

#include "multiview_bindings.hpp"
#include "options_bindings.hpp"
#include "pose_result.hpp"
#include "stereo_bindings.hpp"
#include "stereo_tracker_bindings.hpp"
#include "support/error.hpp"
#include "three_view_bindings.hpp"
#include "tracker_bindings.hpp"

namespace nb = nanobind;

NB_MODULE(_tripose_ext, m)
{
    m.doc() = "tripose's extension; use the functions of the tripose package, which document them.";

    nb::register_exception_translator([](const std::exception_ptr& p, void*) {
        try
        {
            std::rethrow_exception(p);
        }
        catch (const tripose::Error& e)
        {
            PyErr_SetString(e.code() == tripose::ErrorCode::Internal ? PyExc_RuntimeError : PyExc_ValueError, e.what());
        }
    });

    // The stubs list the bindings in the order bound: the options first, before what takes them.
    bindOptions(m);
    bindTracker(m);
    bindPoseResult(m);
    bindStereoTracker(m);
    bindThreeView(m);
    bindStereo(m);
    bindMultiView(m);
}
