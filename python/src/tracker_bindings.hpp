// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP
#define TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! tripose.Tracker's extension classes: _Tracker, TrackerOptions, RansacOptions, RefineOptions,
//! MatchOptions, FrameStatus, FrameResult.
void bindTracker(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP
