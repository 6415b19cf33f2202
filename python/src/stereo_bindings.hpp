// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_STEREO_BINDINGS_HPP
#define TRIPOSE_PYTHON_STEREO_BINDINGS_HPP

#include <nanobind/nanobind.h>

//! The stereo-rig functions: estimate_pose_line_point_stereo, estimate_pose_line_point_stereo_ransac,
//! refine_pose_line_point_stereo.
void bindStereo(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_STEREO_BINDINGS_HPP
