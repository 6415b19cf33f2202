// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What the synthetic scene generators (three-view and stereo rig) share: seeded random streams,
// random directions and turns, projection and the image tests that rejection sampling applies.
// Internal to the support library.

#ifndef TRIPOSE_SUPPORT_SCENE_SAMPLING_HPP
#define TRIPOSE_SUPPORT_SCENE_SAMPLING_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {
namespace sampling {

//! Noise-free features stay this far inside the image border, so small noise rarely pushes them out.
const double kImageMarginPx = 2.0;
//! Shorter projected segments carry almost no direction.
const double kMinSegmentLengthPx = 20.0;
//! A replaced (outlier) observation is at least this far from being consistent with the truth.
const double kOutlierMinOffsetPx = 20.0;
//! Rejection-sampling budget per feature before the parameters are declared infeasible.
const int kMaxAttemptsPerFeature = 20000;

/** The random stream @p stream of a scene with seed @p seed: a splitmix64 mix of the two (cv::RNG
needs a non-zero state; the mix of distinct inputs gives well separated states). Separate streams
keep e.g. the cameras of a seed when only the number of lines or the noise changes.
*/
RNG makeStream(int seed, int stream);

Vec3d randomUnitVector(RNG& rng);

//! A rotation by an angle uniform in [0, maxRadians] about a uniformly random axis.
Matx33d randomTurn(RNG& rng, double maxRadians);

//! A camera: x ~ K (R X + t).
struct ViewGeometry
{
    Matx33d K;
    Matx33d R;
    Vec3d t;
};

//! Projects X; false when X is not at least @p minDepth in front of the camera.
inline bool project(const ViewGeometry& view, const Vec3d& X, Point2d& x, double minDepth = 0)
{
    const Vec3d c = view.R * X + view.t;
    if (!(c[2] > minDepth))
        return false;
    const Vec3d p = view.K * c;
    x = Point2d(p[0] / p[2], p[1] / p[2]);
    return true;
}

//! True when @p x is at least kImageMarginPx inside an image of @p size.
inline bool insideImage(const Point2d& x, const Size& size)
{
    return x.x >= kImageMarginPx && x.x <= size.width - 1 - kImageMarginPx &&
           x.y >= kImageMarginPx && x.y <= size.height - 1 - kImageMarginPx;
}

//! A pixel uniform in the image, kImageMarginPx inside its border.
Point2d randomImagePoint(RNG& rng, const Size& size);

//! Distance of @p x to the infinite line through @p a and @p b.
double distanceToLine(const Point2d& x, const Point2d& a, const Point2d& b);

//! Creates the N x 2 point and M x 4 segment observation matrices (CV_64F) of @p views views.
inline void createObservations(Mat* const* points, Mat* const* lines, int views, int N, int M)
{
    for (int v = 0; v < views; ++v)
    {
        points[v]->create(N, 2, CV_64F);
        lines[v]->create(M, 4, CV_64F);
    }
}

/** Checks one 3x3 intrinsic matrix given to a generator: 1-channel, finite, last row (0, 0, k) with
k != 0 (so that the third projected coordinate is the depth); returns it scaled to k = 1. Raises
cv::Exception "<function>: <params>::<name>: ..." otherwise.
*/
Matx33d checkedCameraMatrix(const Mat& m, const char* function, const char* params, const String& name);

} // namespace sampling
} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_SCENE_SAMPLING_HPP
