// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TEST_PRECOMP_HPP
#define OPENCV_TRIPOSE_TEST_PRECOMP_HPP

#include "opencv2/ts.hpp"
#include "opencv2/tripose.hpp"

// The support library: scenes, data sets and pose errors of the tests (not part of the module).
#include "tripose_support/known_pair_structure.hpp"
#include "tripose_support/pose_error.hpp"
#include "tripose_support/synthetic_multiview_scene.hpp"
#include "tripose_support/synthetic_scene.hpp"
#include "tripose_support/synthetic_stereo_scene.hpp"
#include "tripose_support/vgg_dataset.hpp"

#endif // OPENCV_TRIPOSE_TEST_PRECOMP_HPP
