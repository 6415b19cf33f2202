// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

// Test data sits directly under OPENCV_TEST_DATA_PATH (the repository's test/data), with no
// resource subfolder, in the standalone build and inside OpenCV alike.
CV_TEST_MAIN("")
