// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_PRECOMP_HPP
#define OPENCV_TRIPOSE_PRECOMP_HPP

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "opencv2/core.hpp"
#include "opencv2/core/utility.hpp"
#include "opencv2/tripose.hpp"

#ifdef __OPENCV_BUILD
#include "opencv2/core/private.hpp"
#else
// Standalone build: OpenCV's private header (instrumentation) is not installed.
#define CV_INSTRUMENT_REGION() ((void)0)
#endif

#endif // OPENCV_TRIPOSE_PRECOMP_HPP
