// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_MULTIVIEW_BINDINGS_HPP
#define TRIPOSE_PYTHON_MULTIVIEW_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! The several-views functions: estimate_pose_multiview, estimate_pose_multiview_ransac,
//! refine_pose_multiview, adjust_poses_multiview, triangulate_multiview.
void bindMultiView(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_MULTIVIEW_BINDINGS_HPP
