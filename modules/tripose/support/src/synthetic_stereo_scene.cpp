// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Synthetic stereo-rig scenes: the geometry of test/evaluation/codegen/stereo_rig.py (a rig of
// nearly parallel cameras a short baseline apart, structure 5-30 m ahead, a motion of a few metres and a
// moderate turn), in the frame of view 1.

#include "tripose_support/synthetic_stereo_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene_sampling.hpp"

namespace cv {
namespace tripose {
namespace support {

SyntheticStereoParams::SyntheticStereoParams()
    : numPoints(4), numLines(4), baselineMin(0.1), baselineMax(0.5), rigTiltDegrees(3.0), depthMin(5.0),
      depthMax(30.0), motionMin(0.3), motionMax(3.0), rotationDegrees(20.0), noiseSigma(0.0), outlierRatio(0.0),
      missingRatio(0.0), imageSize(640, 480), focalLength(800.0), seed(0)
{
}

namespace {

using namespace sampling;

//! Separate random streams (see generateSyntheticStereoScene()).
enum Stream
{
    STREAM_RIG = 1,
    STREAM_POINTS,
    STREAM_LINES,
    STREAM_VISIBILITY,
    STREAM_OUTLIERS,
    STREAM_NOISE
};

//! Structure closer than this to any camera is rejected: it would look huge and move fast.
const double kMinDepth = 1.0;
//! Segments shorter than this in space are rejected: their direction is ill-defined.
const double kMinSegmentLength = 0.5;
//! The right camera's centre lies along the left camera's x axis within about this slope.
const double kBaselineSlope = 0.05;

[[noreturn]] void badParam(const char* name, const String& expected)
{
    CV_Error(Error::StsBadArg,
             format("generateSyntheticStereoScene: SyntheticStereoParams::%s: %s", name, expected.c_str()));
}

[[noreturn]] void infeasible(const char* what)
{
    CV_Error(Error::StsBadArg,
             format("generateSyntheticStereoScene: no %s found after %d random attempts; the four views barely "
                    "overlap (check the depth, motion and rotation ranges, imageSize and focalLength)",
                    what, kMaxAttemptsPerFeature));
}

void checkInterval(const char* minName, double minValue, const char* maxName, double maxValue, double lowest)
{
    if (!(minValue >= lowest) || !std::isfinite(minValue))
        badParam(minName, format("expected a finite value >= %g, got %g", lowest, minValue));
    if (!(maxValue >= minValue) || !std::isfinite(maxValue))
        badParam(maxName, format("expected a finite value >= %s (%g), got %g", minName, minValue, maxValue));
}

void checkVisibility(const std::vector<int>& visibility, int count, const char* name, const char* countName)
{
    if (visibility.empty())
        return;
    if ((int)visibility.size() != count)
        badParam(name, format("expected empty or one entry per feature (%s = %d), got %d", countName, count,
                              (int)visibility.size()));
    for (size_t i = 0; i < visibility.size(); ++i)
        if (visibility[i] != SEEN_IN_VIEW3 && visibility[i] != SEEN_IN_VIEW4 && visibility[i] != SEEN_IN_BOTH)
            badParam(name, format("entry %d: expected SEEN_IN_VIEW3 (1), SEEN_IN_VIEW4 (2) or SEEN_IN_BOTH (3), got %d",
                                  (int)i, visibility[i]));
}

void validate(const SyntheticStereoParams& p)
{
    if (p.numPoints < 0)
        badParam("numPoints", format("expected >= 0, got %d", p.numPoints));
    if (p.numLines < 0)
        badParam("numLines", format("expected >= 0, got %d", p.numLines));
    checkInterval("baselineMin", p.baselineMin, "baselineMax", p.baselineMax, 0.0);
    if (!(p.baselineMin > 0))
        badParam("baselineMin", format("expected > 0 (the baseline fixes the scale), got %g", p.baselineMin));
    checkInterval("depthMin", p.depthMin, "depthMax", p.depthMax, kMinDepth);
    checkInterval("motionMin", p.motionMin, "motionMax", p.motionMax, 0.0);
    if (!(p.rigTiltDegrees >= 0 && p.rigTiltDegrees <= 90))
        badParam("rigTiltDegrees", format("expected a value in [0, 90], got %g", p.rigTiltDegrees));
    if (!(p.rotationDegrees >= 0 && p.rotationDegrees <= 180))
        badParam("rotationDegrees", format("expected a value in [0, 180], got %g", p.rotationDegrees));
    if (!(p.noiseSigma >= 0) || !std::isfinite(p.noiseSigma))
        badParam("noiseSigma", format("expected a finite value >= 0, got %g", p.noiseSigma));
    if (!(p.outlierRatio >= 0 && p.outlierRatio < 1))
        badParam("outlierRatio", format("expected a value in [0, 1), got %g", p.outlierRatio));
    if (!(p.missingRatio >= 0 && p.missingRatio <= 1))
        badParam("missingRatio", format("expected a value in [0, 1], got %g", p.missingRatio));
    checkVisibility(p.pointVisibility, p.numPoints, "pointVisibility", "numPoints");
    checkVisibility(p.lineVisibility, p.numLines, "lineVisibility", "numLines");
    const int minSide = (int)(2 * kImageMarginPx) + 2;
    if (p.imageSize.width < minSide || p.imageSize.height < minSide)
        badParam("imageSize", format("expected both sides >= %d px, got %dx%d", minSide, p.imageSize.width,
                                     p.imageSize.height));
    if (!(p.focalLength > 0) || !std::isfinite(p.focalLength))
        badParam("focalLength", format("expected a finite value > 0, got %g", p.focalLength));
}

//! The four cameras in the frame of view 1.
void placeCameras(const SyntheticStereoParams& p, const Matx33d& K, ViewGeometry views[4])
{
    RNG rng = makeStream(p.seed, STREAM_RIG);
    const double baseline = rng.uniform(p.baselineMin, p.baselineMax);
    // One draw per statement: the order in which C++ evaluates operands and arguments is unspecified.
    // z before y, and the direction before the distance, is the order the documented seeded scenes
    // were drawn in (GCC's, right to left).
    const double slopeZ = kBaselineSlope * rng.gaussian(1.0);
    const double slopeY = kBaselineSlope * rng.gaussian(1.0);
    const Vec3d centre2 = baseline * Vec3d(1.0, slopeY, slopeZ);
    const Matx33d rigR = randomTurn(rng, p.rigTiltDegrees * CV_PI / 180);
    const Vec3d rigT = -(rigR * centre2);
    const Vec3d direction = randomUnitVector(rng);
    const Vec3d centre3 = rng.uniform(p.motionMin, p.motionMax) * direction;
    const Matx33d R = randomTurn(rng, p.rotationDegrees * CV_PI / 180);
    const Vec3d t = -(R * centre3);
    for (int v = 0; v < 4; ++v)
        views[v].K = K;
    views[0].R = Matx33d::eye();
    views[0].t = Vec3d(0, 0, 0);
    views[1].R = rigR;
    views[1].t = rigT;
    views[2].R = R;
    views[2].t = t;
    views[3].R = rigR * R;
    views[3].t = rigR * t + rigT;
}

//! A point in view 1's field of view in the depth range, visible in all four views; its pixels in @p x.
Vec3d visiblePoint(RNG& rng, const SyntheticStereoParams& p, const ViewGeometry views[4], Point2d x[4],
                   const char* what)
{
    const Matx33d& K = views[0].K;
    for (int attempt = 0; attempt < kMaxAttemptsPerFeature; ++attempt)
    {
        const Point2d pixel = randomImagePoint(rng, p.imageSize);
        const Vec3d ray((pixel.x - K(0, 2)) / K(0, 0), (pixel.y - K(1, 2)) / K(1, 1), 1.0);
        const Vec3d X = rng.uniform(p.depthMin, p.depthMax) * ray;
        bool ok = true;
        for (int v = 0; v < 4 && ok; ++v)
            ok = project(views[v], X, x[v], kMinDepth) && insideImage(x[v], p.imageSize);
        if (ok)
            return X;
    }
    infeasible(what);
}

//! A segment of two visible points, long enough in space and in every image.
void visibleSegment(RNG& rng, const SyntheticStereoParams& p, const ViewGeometry views[4], Vec3d& A, Vec3d& B,
                    Point2d a[4], Point2d b[4])
{
    const char* what = "segment inside all four images and at least 20 px long in each";
    for (int attempt = 0; attempt < kMaxAttemptsPerFeature; ++attempt)
    {
        A = visiblePoint(rng, p, views, a, what);
        B = visiblePoint(rng, p, views, b, what);
        bool ok = norm(A - B) >= kMinSegmentLength;
        for (int v = 0; v < 4 && ok; ++v)
            ok = norm(b[v] - a[v]) >= kMinSegmentLengthPx;
        if (ok)
            return;
    }
    infeasible(what);
}

//! The visibility of @p count features: given, or exactly round(ratio * count) of them, chosen at
//! random, seen by one time-B view (each view 3 or 4 with probability 1/2).
std::vector<int> drawVisibility(const std::vector<int>& given, int count, double ratio, RNG& rng)
{
    if (!given.empty())
        return given;
    std::vector<int> visibility(count, SEEN_IN_BOTH), order(count);
    for (int i = 0; i < count; ++i)
        order[i] = i;
    const int missing = (int)std::lround(ratio * count);
    for (int i = 0; i < missing; ++i)
    {
        std::swap(order[i], order[rng.uniform(i, count)]);
        visibility[order[i]] = rng.uniform(0, 2) == 0 ? SEEN_IN_VIEW3 : SEEN_IN_VIEW4;
    }
    return visibility;
}

bool seenIn(int visibility, int view)
{
    return view < 2 || (visibility & (view == 2 ? SEEN_IN_VIEW3 : SEEN_IN_VIEW4)) != 0;
}

//! Indices of exactly round(ratio * count) features chosen at random.
std::vector<int> drawOutliers(int count, double ratio, RNG& rng)
{
    std::vector<int> order(count);
    for (int i = 0; i < count; ++i)
        order[i] = i;
    const int n = (int)std::lround(ratio * count);
    for (int i = 0; i < n; ++i)
        std::swap(order[i], order[rng.uniform(i, count)]);
    order.resize(n);
    return order;
}

} // namespace

SyntheticStereoScene generateSyntheticStereoScene(const SyntheticStereoParams& params)
{
    validate(params);
    const Matx33d K(params.focalLength, 0, (params.imageSize.width - 1) * 0.5,
                    0, params.focalLength, (params.imageSize.height - 1) * 0.5,
                    0, 0, 1);
    ViewGeometry views[4];
    placeCameras(params, K, views);

    const int N = params.numPoints, M = params.numLines;
    SyntheticStereoScene scene;
    scene.points3d.create(N, 3, CV_64F);
    scene.lines3d.create(M, 6, CV_64F);
    Mat* pointObs[4] = { &scene.points1, &scene.points2, &scene.points3, &scene.points4 };
    Mat* lineObs[4] = { &scene.lines1, &scene.lines2, &scene.lines3, &scene.lines4 };
    createObservations(pointObs, lineObs, 4, N, M);

    RNG pointRng = makeStream(params.seed, STREAM_POINTS);
    for (int i = 0; i < N; ++i)
    {
        Point2d x[4];
        const Vec3d X = visiblePoint(pointRng, params, views, x, "point inside all four images");
        std::copy(X.val, X.val + 3, scene.points3d.ptr<double>(i));
        for (int v = 0; v < 4; ++v)
        {
            double* o = pointObs[v]->ptr<double>(i);
            o[0] = x[v].x; o[1] = x[v].y;
        }
    }
    RNG lineRng = makeStream(params.seed, STREAM_LINES);
    for (int i = 0; i < M; ++i)
    {
        Vec3d A, B;
        Point2d a[4], b[4];
        visibleSegment(lineRng, params, views, A, B, a, b);
        double* L = scene.lines3d.ptr<double>(i);
        std::copy(A.val, A.val + 3, L);
        std::copy(B.val, B.val + 3, L + 3);
        for (int v = 0; v < 4; ++v)
        {
            double* o = lineObs[v]->ptr<double>(i);
            o[0] = a[v].x; o[1] = a[v].y; o[2] = b[v].x; o[3] = b[v].y;
        }
    }

    RNG visibilityRng = makeStream(params.seed, STREAM_VISIBILITY);
    const std::vector<int> pointVisibility = drawVisibility(params.pointVisibility, N, params.missingRatio, visibilityRng);
    const std::vector<int> lineVisibility = drawVisibility(params.lineVisibility, M, params.missingRatio, visibilityRng);

    // Outliers: the time-B observations replaced by those of another random point or segment, as a
    // wrong temporal match that the stereo matching at time B still made consistently.
    scene.pointInliers = Mat::ones(N, 1, CV_8U);
    scene.lineInliers = Mat::ones(M, 1, CV_8U);
    RNG outlierRng = makeStream(params.seed, STREAM_OUTLIERS);
    for (int i : drawOutliers(N, params.outlierRatio, outlierRng))
    {
        scene.pointInliers.at<uchar>(i) = 0;
        for (int attempt = 0;; ++attempt)
        {
            if (attempt == kMaxAttemptsPerFeature)
                infeasible("outlier point far enough from the true one");
            Point2d x[4];
            visiblePoint(outlierRng, params, views, x, "outlier point inside all four images");
            bool far = true;
            for (int v = 2; v < 4 && far; ++v)
            {
                const double* o = pointObs[v]->ptr<double>(i);
                far = !seenIn(pointVisibility[i], v) || norm(x[v] - Point2d(o[0], o[1])) >= kOutlierMinOffsetPx;
            }
            if (!far)
                continue;
            for (int v = 2; v < 4; ++v)
            {
                double* o = pointObs[v]->ptr<double>(i);
                o[0] = x[v].x; o[1] = x[v].y;
            }
            break;
        }
    }
    for (int i : drawOutliers(M, params.outlierRatio, outlierRng))
    {
        scene.lineInliers.at<uchar>(i) = 0;
        for (int attempt = 0;; ++attempt)
        {
            if (attempt == kMaxAttemptsPerFeature)
                infeasible("outlier segment far enough from the true line");
            Vec3d A, B;
            Point2d a[4], b[4];
            visibleSegment(outlierRng, params, views, A, B, a, b);
            bool far = true;
            for (int v = 2; v < 4 && far; ++v)
            {
                const double* o = lineObs[v]->ptr<double>(i);
                const Point2d ta(o[0], o[1]), tb(o[2], o[3]);
                far = !seenIn(lineVisibility[i], v) ||
                      std::max(distanceToLine(a[v], ta, tb), distanceToLine(b[v], ta, tb)) >= kOutlierMinOffsetPx;
            }
            if (!far)
                continue;
            for (int v = 2; v < 4; ++v)
            {
                double* o = lineObs[v]->ptr<double>(i);
                o[0] = a[v].x; o[1] = a[v].y; o[2] = b[v].x; o[3] = b[v].y;
            }
            break;
        }
    }

    if (params.noiseSigma > 0)
    {
        RNG noiseRng = makeStream(params.seed, STREAM_NOISE);
        for (int v = 0; v < 4; ++v)
            for (Mat* obs : { pointObs[v], lineObs[v] })
            {
                double* d = obs->ptr<double>();
                for (size_t j = 0, n = obs->total(); j < n; ++j)
                    d[j] += noiseRng.gaussian(params.noiseSigma);
            }
    }

    // Views that do not see a feature: rows of NaN.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    scene.pointVisibility.create(N, 1, CV_8U);
    scene.lineVisibility.create(M, 1, CV_8U);
    for (int i = 0; i < N; ++i)
    {
        scene.pointVisibility.at<uchar>(i) = (uchar)pointVisibility[i];
        for (int v = 2; v < 4; ++v)
            if (!seenIn(pointVisibility[i], v))
                pointObs[v]->row(i).setTo(nan);
    }
    for (int i = 0; i < M; ++i)
    {
        scene.lineVisibility.at<uchar>(i) = (uchar)lineVisibility[i];
        for (int v = 2; v < 4; ++v)
            if (!seenIn(lineVisibility[i], v))
                lineObs[v]->row(i).setTo(nan);
    }

    scene.cameraMatrices.assign(4, Mat());
    for (int v = 0; v < 4; ++v)
        scene.cameraMatrices[v] = Mat(K, true);
    scene.R12 = Mat(views[1].R, true);
    scene.t12 = Mat(views[1].t, true);
    scene.R = Mat(views[2].R, true);
    scene.t = Mat(views[2].t, true);
    return scene;
}

} // namespace support
} // namespace tripose
} // namespace cv
