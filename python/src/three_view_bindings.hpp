// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_THREE_VIEW_BINDINGS_HPP
#define TRIPOSE_PYTHON_THREE_VIEW_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! The three-view functions: estimate_pose_line_point, estimate_pose_line_point_ransac,
//! refine_pose_line_point.
void bindThreeView(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_THREE_VIEW_BINDINGS_HPP
