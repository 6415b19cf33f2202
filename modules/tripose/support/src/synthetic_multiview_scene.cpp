// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tripose_support/synthetic_multiview_scene.hpp"

#include "tripose_support/random_draws.hpp"

#include <cmath>
#include <limits>

namespace cv {
namespace tripose {
namespace support {

namespace {

//! A camera at @p centre looking at the origin, with a random roll.
void lookAt(const Vec3d& centre, double roll, Matx33d& R, Vec3d& t)
{
    const Vec3d z = normalize(-centre);
    Vec3d up(std::cos(roll), std::sin(roll), 0.3);
    Vec3d x = normalize(up.cross(z));
    if (!(cv::norm(x) > 0.5))
        x = normalize(Vec3d(0, 0, 1).cross(z));
    const Vec3d y = z.cross(x);
    R = Matx33d(x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]);
    t = -(R * centre);
}

} // namespace

SyntheticMultiViewScene::SyntheticMultiViewScene(int numKnown, int numPoints, int numLines, uint64 seed, int minSeen)
{
    RNG rng(seed);
    K = Matx33d(800, 0, 320, 0, 800, 240, 0, 0, 1);
    std::vector<Matx33d> Rv(numKnown + 1);
    std::vector<Vec3d> tv(numKnown + 1);
    for (int v = 0; v <= numKnown; ++v)
    {
        const Vec3d direction = uniformInCube(rng, 1.0);
        const Vec3d offset = uniformInCube(rng, 1.0);
        const Vec3d c = 20.0 * normalize(direction) + offset;
        lookAt(c, rng.uniform(0.0, 2 * CV_PI), Rv[v], tv[v]);
    }
    R = Rv[numKnown];
    t = tv[numKnown];
    for (int v = 0; v < numKnown; ++v)
    {
        Rs.push_back(Mat(Rv[v], true));
        ts.push_back(Mat(tv[v], true));
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int v = 0; v <= numKnown; ++v)
    {
        points.push_back(Mat(numPoints, 2, CV_64F, Scalar::all(nan)));
        lines.push_back(Mat(numLines, 4, CV_64F, Scalar::all(nan)));
    }
    auto project = [&](int v, const Vec3d& X) {
        const Vec3d x = K * (Rv[v] * X + tv[v]);
        return Point2d(x[0] / x[2], x[1] / x[2]);
    };
    auto seenBy = [&]() {
        std::vector<int> views(numKnown);
        for (int v = 0; v < numKnown; ++v)
            views[v] = v;
        std::vector<int> subset;
        while ((int)subset.size() < minSeen || rng.uniform(0.0, 1.0) < 0.5)
        {
            if (views.empty())
                break;
            const int pick = rng.uniform(0, (int)views.size());
            subset.push_back(views[pick]);
            views.erase(views.begin() + pick);
        }
        subset.push_back(numKnown);
        return subset;
    };
    auto randomPoint = [&]() { return uniformInCube(rng, 5.0); };
    for (int i = 0; i < numPoints; ++i)
    {
        const Vec3d X = randomPoint();
        for (int v : seenBy())
        {
            const Point2d x = project(v, X);
            points[v].at<double>(i, 0) = x.x;
            points[v].at<double>(i, 1) = x.y;
        }
    }
    for (int i = 0; i < numLines; ++i)
    {
        const Vec3d A = randomPoint(), B = randomPoint();
        for (int v : seenBy())
        {
            const Point2d a = project(v, A), b = project(v, B);
            lines[v].at<double>(i, 0) = a.x;
            lines[v].at<double>(i, 1) = a.y;
            lines[v].at<double>(i, 2) = b.x;
            lines[v].at<double>(i, 3) = b.y;
        }
    }
    if (numPoints == 0)
        points.clear();
    if (numLines == 0)
        lines.clear();
}

void SyntheticMultiViewScene::addNoise(double sigma, uint64 seed)
{
    RNG rng(seed);
    for (std::vector<Mat>* kind : { &points, &lines })
        for (Mat& m : *kind)
        {
            Mat noise(m.size(), CV_64F);
            rng.fill(noise, RNG::NORMAL, 0.0, sigma);
            m = m + noise;
        }
}

} // namespace support
} // namespace tripose
} // namespace cv
