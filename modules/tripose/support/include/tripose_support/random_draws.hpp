// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Random draws that the scene generators, the tests and the perf tests share. Part of the tripose
// support library (built beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_RANDOM_DRAWS_HPP
#define TRIPOSE_SUPPORT_RANDOM_DRAWS_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

/** A vector uniform in the cube [-halfSize, halfSize]^3.

Its coordinates are drawn one per statement, z first, then y, then x. C++ leaves the order in which
a call's arguments are evaluated unspecified, so `Vec3d(rng.uniform(..), rng.uniform(..), ...)`
drew in another order under clang than under GCC (right to left); this is GCC's order, the one every
documented seeded scene was drawn in. */
Vec3d uniformInCube(RNG& rng, double halfSize);

} // namespace support
} // namespace tripose
} // namespace cv

#endif
