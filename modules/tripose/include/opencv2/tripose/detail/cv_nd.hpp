// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_DETAIL_CV_ND_HPP
#define OPENCV_TRIPOSE_DETAIL_CV_ND_HPP

#include "opencv2/core.hpp"

// CV_ND marks an array that OpenCV 4.8+'s Python bindings pass whole (a 3x3 camera matrix); an
// OpenCV without the marker (4.6, 4.7) generates no such bindings, so it expands to nothing there.
#ifndef CV_ND
#define CV_ND
#endif

#endif // OPENCV_TRIPOSE_DETAIL_CV_ND_HPP
