// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP
#define TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! tripose.Tracker's extension classes _Tracker, FrameStatus, FrameResult and the function
//! _match_triplets (after bindOptions(), whose options they take).
void bindTracker(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_TRACKER_BINDINGS_HPP
