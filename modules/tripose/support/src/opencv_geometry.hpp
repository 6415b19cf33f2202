// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_SUPPORT_OPENCV_GEOMETRY_HPP
#define TRIPOSE_SUPPORT_OPENCV_GEOMETRY_HPP

// Rodrigues and RQDecomp3x3 are declared in calib3d up to OpenCV 4.x and in geometry (3d in early
// 5.x snapshots) from OpenCV 5 on. The support library is built against the same OpenCVs as the
// module; opencv_modules.hpp says which of these modules the one at hand has.
#include "opencv2/opencv_modules.hpp"

#if defined(HAVE_OPENCV_GEOMETRY)
#include "opencv2/geometry.hpp"
#elif defined(HAVE_OPENCV_3D)
#include "opencv2/3d.hpp"
#else
#include "opencv2/calib3d.hpp"
#endif

#endif // TRIPOSE_SUPPORT_OPENCV_GEOMETRY_HPP
