// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "scene_sampling.hpp"

#include "tripose_support/random_draws.hpp"

#include <algorithm>
#include <cmath>

#include "opencv_geometry.hpp"

namespace cv {
namespace tripose {
namespace support {

Vec3d uniformInCube(RNG& rng, double halfSize)
{
    const double z = rng.uniform(-halfSize, halfSize);
    const double y = rng.uniform(-halfSize, halfSize);
    const double x = rng.uniform(-halfSize, halfSize);
    return Vec3d(x, y, z);
}

namespace sampling {

RNG makeStream(int seed, int stream)
{
    uint64 z = (uint64)(unsigned)seed * 0x9E3779B97F4A7C15ULL + (uint64)(unsigned)stream * 0xD1B54A32D192ED03ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return RNG(z ? z : 0x853C49E6748FEA9BULL);
}

Vec3d randomUnitVector(RNG& rng)
{
    const double z = rng.uniform(-1.0, 1.0);
    const double phi = rng.uniform(0.0, 2.0 * CV_PI);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3d(r * std::cos(phi), r * std::sin(phi), z);
}

Matx33d randomTurn(RNG& rng, double maxRadians)
{
    const Vec3d axis = randomUnitVector(rng);
    const Vec3d rvec = rng.uniform(0.0, maxRadians) * axis;
    Matx33d R;
    Rodrigues(rvec, R);
    return R;
}

Point2d randomImagePoint(RNG& rng, const Size& size)
{
    // One draw per statement: the order in which C++ evaluates a call's arguments is unspecified.
    // y before x is the order the documented seeded scenes were drawn in (GCC's, right to left).
    const double y = rng.uniform(kImageMarginPx, size.height - 1 - kImageMarginPx);
    const double x = rng.uniform(kImageMarginPx, size.width - 1 - kImageMarginPx);
    return Point2d(x, y);
}

double distanceToLine(const Point2d& x, const Point2d& a, const Point2d& b)
{
    const Point2d d = b - a;
    return std::abs(d.cross(x - a)) / std::sqrt(d.dot(d));
}

Matx33d checkedCameraMatrix(const Mat& m, const char* function, const char* params, const String& name)
{
    if (m.dims > 2 || m.rows != 3 || m.cols != 3 || m.channels() != 1)
        CV_Error(Error::StsBadArg, format("%s: %s::%s: expected a 3x3 1-channel matrix, got %dx%d with %d channels",
                                          function, params, name.c_str(), m.rows, m.cols, m.channels()));
    Mat m64;
    m.convertTo(m64, CV_64F);
    const Matx33d k(m64.ptr<double>());
    if (!checkRange(m64))
        CV_Error(Error::StsBadArg, format("%s: %s::%s: expected finite entries", function, params, name.c_str()));
    if (k(2, 0) != 0 || k(2, 1) != 0 || k(2, 2) == 0)
        CV_Error(Error::StsBadArg, format("%s: %s::%s: expected a last row (0, 0, k) with k != 0, got (%g, %g, %g)",
                                          function, params, name.c_str(), k(2, 0), k(2, 1), k(2, 2)));
    return k * (1.0 / k(2, 2));
}

} // namespace sampling
} // namespace support
} // namespace tripose
} // namespace cv
