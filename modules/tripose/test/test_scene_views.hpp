// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TEST_SCENE_VIEWS_HPP
#define OPENCV_TRIPOSE_TEST_SCENE_VIEWS_HPP

#include "test_precomp.hpp"
#include "../src/opencv/argument_reading.hpp"

namespace opencv_test {

//! A synthetic three-view scene read as the public entry points read their arguments: checked, and
//! converted to the core's views (the known pair's cameras and the third view's observations).
inline ::tripose::ViewSet readScene(const cv::tripose::support::SyntheticScene& s)
{
    return cv::tripose::detail::readThreeViewInput(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                   s.cameraMatrices, noArray(), s.R12, s.t12);
}

} // namespace opencv_test

#endif // OPENCV_TRIPOSE_TEST_SCENE_VIEWS_HPP
