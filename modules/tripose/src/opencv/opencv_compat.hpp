// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_COMPAT_HPP
#define OPENCV_TRIPOSE_OPENCV_COMPAT_HPP

// The two-view geometry the module relies on (Rodrigues, undistortPoints, triangulatePoints,
// projectPoints) is declared in calib3d up to OpenCV 4.x. OpenCV 5 split calib3d into geometry,
// calib and stereo, and these functions moved to geometry (named 3d in early 5.x snapshots) with
// the same signatures. Sources include this header instead of opencv2/calib3d.hpp so that the
// module builds against both: the standalone build (Debian's 4.6) and OpenCV 4.x / 5.x trees.
// opencv_modules.hpp lists the modules of the OpenCV being compiled against (HAVE_OPENCV_<NAME>).
#include "opencv2/opencv_modules.hpp"

#if defined(HAVE_OPENCV_GEOMETRY)
#include "opencv2/geometry.hpp"
#elif defined(HAVE_OPENCV_3D)
#include "opencv2/3d.hpp"
#elif defined(HAVE_OPENCV_CALIB3D)
#include "opencv2/calib3d.hpp"
#else
#error "tripose needs OpenCV's calib3d module (OpenCV 4.x) or geometry module (OpenCV 5.x)"
#endif

#endif // OPENCV_TRIPOSE_OPENCV_COMPAT_HPP
