// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_COMPAT_HPP
#define OPENCV_TRIPOSE_COMPAT_HPP

// OpenCV 4.8+ marks array arguments that Python passes whole (one 3x3 K, not three rows);
// older OpenCV (Debian's 4.6) lacks the marker.
#ifndef CV_ND
#define CV_ND
#endif

#endif // OPENCV_TRIPOSE_COMPAT_HPP
