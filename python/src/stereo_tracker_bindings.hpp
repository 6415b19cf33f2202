// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_STEREO_TRACKER_BINDINGS_HPP
#define TRIPOSE_PYTHON_STEREO_TRACKER_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! tripose.StereoTracker's extension class _StereoTracker (after bindTracker(), whose options and
//! results it uses).
void bindStereoTracker(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_STEREO_TRACKER_BINDINGS_HPP
