// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Synthetic three-view scenes following the protocol of Qadir & Neubert (Sec. IV-A): structure in
// a cube centred at the world origin, cameras looking at the origin. Everything is returned in the
// frame of view 1.

#include "tripose_support/synthetic_scene.hpp"

#include "scene_sampling.hpp"
#include "tripose_support/random_draws.hpp"

#include <algorithm>
#include <cmath>

namespace cv {
namespace tripose {
namespace support {

SyntheticSceneParams::SyntheticSceneParams()
    : numPoints(4), numLines(4), motion(MOTION_LARGE), noiseSigma(0.0), outlierRatio(0.0),
      cubeSize(10.0), cameraDistance(20.0), smallMotionRadius(5.0), baseline12(0.0),
      baseline12Fraction(0.0), planar(false), planeTilt(30.0), imageSize(640, 480), seed(0)
{
}

namespace {

using namespace sampling;

const double kDefaultFocalPx = 800.0;

//! Independent random streams, so that e.g. changing numLines leaves the points unchanged and
//! changing noiseSigma leaves the geometry unchanged.
enum Stream
{
    STREAM_CAMERAS = 1,
    STREAM_POINTS,
    STREAM_LINES,
    STREAM_OUTLIERS,
    STREAM_NOISE,
    STREAM_PLANE
};

//! World-to-camera rotation of a camera at @p centre looking at the origin, rolled by @p roll.
Matx33d lookAtOrigin(const Vec3d& centre, double roll)
{
    const Vec3d z = -centre * (1.0 / norm(centre));
    const Vec3d helper = std::abs(z[0]) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
    Vec3d x0 = helper.cross(z);
    x0 *= 1.0 / norm(x0);
    const Vec3d y0 = z.cross(x0);
    const Vec3d x = std::cos(roll) * x0 + std::sin(roll) * y0;
    const Vec3d y = z.cross(x);
    return Matx33d(x[0], x[1], x[2],
                   y[0], y[1], y[2],
                   z[0], z[1], z[2]);
}

[[noreturn]] void badParam(const char* name, const String& expected)
{
    CV_Error(Error::StsBadArg, format("generateSyntheticScene: SyntheticSceneParams::%s: %s", name, expected.c_str()));
}

[[noreturn]] void infeasible(const char* what)
{
    CV_Error(Error::StsBadArg,
             format("generateSyntheticScene: no %s found after %d random attempts; the cube is barely visible "
                    "in all three views (check cubeSize, cameraDistance, imageSize and cameraMatrices)",
                    what, kMaxAttemptsPerFeature));
}

//! The intrinsics of the three views, scaled to K(2,2) = 1. Only what projecting needs is checked:
//! a last row (0, 0, k), so that the third projected coordinate is the depth and "in front" means
//! a positive one. Whether the estimators accept a matrix (skew, signs of the focal lengths, ...)
//! is theirs to say: their bad-input tests may use scenes made with such matrices.
void intrinsicsFromParams(const SyntheticSceneParams& params, Matx33d K[3])
{
    const std::vector<Mat>& given = params.cameraMatrices;
    if (given.empty())
    {
        const Matx33d K0(kDefaultFocalPx, 0, (params.imageSize.width - 1) * 0.5,
                         0, kDefaultFocalPx, (params.imageSize.height - 1) * 0.5,
                         0, 0, 1);
        K[0] = K[1] = K[2] = K0;
        return;
    }
    if (given.size() != 1 && given.size() != 3)
        badParam("cameraMatrices", format("expected 0 (default f = 800 px), 1 or 3 matrices, got %d", (int)given.size()));
    for (size_t i = 0; i < given.size(); ++i)
        K[i] = checkedCameraMatrix(given[i], "generateSyntheticScene", "SyntheticSceneParams",
                                   format("cameraMatrices[%d]", (int)i));
    if (given.size() == 1)
        K[1] = K[2] = K[0];
}

void validate(const SyntheticSceneParams& p)
{
    if (p.numPoints < 0)
        badParam("numPoints", format("expected >= 0, got %d", p.numPoints));
    if (p.numLines < 0)
        badParam("numLines", format("expected >= 0, got %d", p.numLines));
    if (p.motion != MOTION_LARGE && p.motion != MOTION_SMALL)
        badParam("motion", format("expected MOTION_LARGE (0) or MOTION_SMALL (1), got %d", p.motion));
    if (!(p.noiseSigma >= 0) || !std::isfinite(p.noiseSigma))
        badParam("noiseSigma", format("expected a finite value >= 0, got %g", p.noiseSigma));
    if (!(p.outlierRatio >= 0 && p.outlierRatio < 1))
        badParam("outlierRatio", format("expected a value in [0, 1), got %g", p.outlierRatio));
    if (!(p.cubeSize > 0) || !std::isfinite(p.cubeSize))
        badParam("cubeSize", format("expected a finite value > 0, got %g", p.cubeSize));
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * p.cubeSize;
    if (!(p.cameraDistance > halfDiagonal) || !std::isfinite(p.cameraDistance))
        badParam("cameraDistance", format("expected a finite value > the cube's half diagonal (%g), got %g",
                                          halfDiagonal, p.cameraDistance));
    if (!(p.smallMotionRadius >= 0) || !std::isfinite(p.smallMotionRadius))
        badParam("smallMotionRadius", format("expected a finite value >= 0, got %g", p.smallMotionRadius));
    if (p.motion == MOTION_SMALL && !(p.cameraDistance - p.smallMotionRadius > halfDiagonal))
        badParam("smallMotionRadius", format("views 2 and 3 could enter the cube: expected cameraDistance - "
                                             "smallMotionRadius > %g (the cube's half diagonal), got %g - %g",
                                             halfDiagonal, p.cameraDistance, p.smallMotionRadius));
    if (!(p.baseline12 >= 0) || !std::isfinite(p.baseline12))
        badParam("baseline12", format("expected a finite value >= 0, got %g", p.baseline12));
    if (!(p.baseline12Fraction >= 0) || !std::isfinite(p.baseline12Fraction))
        badParam("baseline12Fraction", format("expected a finite value >= 0, got %g", p.baseline12Fraction));
    if (p.baseline12 > 0 && p.baseline12Fraction > 0)
        badParam("baseline12Fraction", "expected 0 when baseline12 is set (one baseline, absolute or relative)");
    const double baseline = p.baseline12 > 0 ? p.baseline12 : p.baseline12Fraction * p.cameraDistance;
    if (!(p.cameraDistance - baseline > halfDiagonal))
        badParam(p.baseline12 > 0 ? "baseline12" : "baseline12Fraction",
                 format("view 2 could enter the cube: expected cameraDistance - baseline > %g (the cube's half "
                        "diagonal), got %g - %g", halfDiagonal, p.cameraDistance, baseline));
    if (p.planar && !(p.planeTilt >= 0 && p.planeTilt < 90))
        badParam("planeTilt", format("expected degrees in [0, 90), got %g", p.planeTilt));
    const int minSide = (int)(2 * kImageMarginPx) + 2;
    if (p.imageSize.width < minSide || p.imageSize.height < minSide)
        badParam("imageSize", format("expected both sides >= %d px, got %dx%d", minSide,
                                     p.imageSize.width, p.imageSize.height));
}

//! The three cameras in the frame of view 1, plus the world-to-view-1 transform of the structure.
void placeCameras(const SyntheticSceneParams& p, const Matx33d K[3], ViewGeometry views[3],
                  Matx33d& worldToView1R, Vec3d& worldToView1t)
{
    RNG rng = makeStream(p.seed, STREAM_CAMERAS);
    Vec3d centres[3];
    Matx33d rotations[3];
    centres[0] = p.cameraDistance * randomUnitVector(rng);
    for (int v = 1; v < 3; ++v)
    {
        if (p.motion == MOTION_LARGE)
            centres[v] = p.cameraDistance * randomUnitVector(rng);
        else // uniform in the ball of radius smallMotionRadius around view 1
        {
            // One draw per statement, as C++ leaves the order of operands and arguments unspecified:
            // the direction before the radius (and in randomStructurePoint v before u) is the order
            // the documented seeded scenes were drawn in (GCC's, right to left).
            const Vec3d direction = randomUnitVector(rng);
            const double volumeFraction = rng.uniform(0.0, 1.0);
            centres[v] = centres[0] + p.smallMotionRadius * std::cbrt(volumeFraction) * direction;
        }
    }
    const double baseline = p.baseline12 > 0 ? p.baseline12 : p.baseline12Fraction * p.cameraDistance;
    if (baseline > 0)
    {
        // Drawn after the regime's centres, so that view 3 of a seed stays where it was.
        centres[1] = centres[0] + baseline * randomUnitVector(rng);
    }
    for (int v = 0; v < 3; ++v)
        rotations[v] = lookAtOrigin(centres[v], rng.uniform(0.0, 2.0 * CV_PI));

    worldToView1R = rotations[0];
    worldToView1t = -(rotations[0] * centres[0]);
    for (int v = 0; v < 3; ++v)
    {
        // X_v = R_v (X_w - C_v) with X_w = R_1^T (X_1 - t_1).
        views[v].K = K[v];
        views[v].R = rotations[v] * rotations[0].t();
        views[v].t = -(rotations[v] * centres[v]) - views[v].R * worldToView1t;
    }
    views[0].R = Matx33d::eye(); // exact, not a rounded R_1 R_1^T
    views[0].t = Vec3d(0, 0, 0);
}

/** Where the structure is drawn, in the frame of view 1: the cube, or a square on a plane through
its centre spanned by the orthonormal axes u, v. */
struct StructureRegion
{
    double halfSize = 0;
    Matx33d R;  //!< world to view 1
    Vec3d t;
    bool planar = false;
    Vec3d centre, u, v;
};

StructureRegion makeRegion(const SyntheticSceneParams& p, const Matx33d& toView1R, const Vec3d& toView1t)
{
    StructureRegion region;
    region.halfSize = 0.5 * p.cubeSize;
    region.R = toView1R;
    region.t = toView1t;
    region.planar = p.planar;
    if (!p.planar)
        return region;
    // In view 1's frame the cube centre is at toView1t on the optical axis. The normal starts on
    // the axis (facing view 1) and is turned by the tilt about a random axis across it.
    RNG rng = makeStream(p.seed, STREAM_PLANE);
    const double phi = rng.uniform(0.0, 2.0 * CV_PI);
    const Vec3d across(std::cos(phi), std::sin(phi), 0.0);
    const double tilt = p.planeTilt * CV_PI / 180.0;
    const Vec3d normal = std::cos(tilt) * Vec3d(0, 0, -1) + std::sin(tilt) * across;
    Vec3d u = normal.cross(Vec3d(0, 0, 1)).cross(normal);
    if (norm(u) < 1e-9) // facing view 1 exactly: any in-plane axis
        u = Vec3d(1, 0, 0);
    u *= 1.0 / norm(u);
    const double psi = rng.uniform(0.0, 2.0 * CV_PI); // random in-plane orientation of the square
    const Vec3d w = normal.cross(u);
    region.u = std::cos(psi) * u + std::sin(psi) * w;
    region.v = normal.cross(region.u);
    region.centre = toView1t;
    return region;
}

Vec3d randomStructurePoint(RNG& rng, const StructureRegion& region)
{
    const double h = region.halfSize;
    if (region.planar)
    {
        const double alongV = rng.uniform(-h, h);
        const double alongU = rng.uniform(-h, h);
        return region.centre + alongU * region.u + alongV * region.v;
    }
    return region.R * uniformInCube(rng, h) + region.t;
}

} // namespace

SyntheticScene generateSyntheticScene(const SyntheticSceneParams& params)
{
    validate(params);
    Matx33d K[3];
    intrinsicsFromParams(params, K);

    ViewGeometry views[3];
    Matx33d toView1R;
    Vec3d toView1t;
    placeCameras(params, K, views, toView1R, toView1t);

    const int N = params.numPoints, M = params.numLines;
    const Size size = params.imageSize;
    const StructureRegion region = makeRegion(params, toView1R, toView1t);

    SyntheticScene scene;
    scene.points3d.create(N, 3, CV_64F);
    scene.lines3d.create(M, 6, CV_64F);
    Mat* pointObs[3] = { &scene.points1, &scene.points2, &scene.points3 };
    Mat* lineObs[3] = { &scene.lines1, &scene.lines2, &scene.lines3 };
    createObservations(pointObs, lineObs, 3, N, M);

    // Points: uniform in the cube, kept if inside every image and in front of every camera.
    RNG pointRng = makeStream(params.seed, STREAM_POINTS);
    for (int i = 0; i < N; ++i)
    {
        Point2d x[3];
        Vec3d X;
        int attempt = 0;
        for (;; ++attempt)
        {
            if (attempt == kMaxAttemptsPerFeature)
                infeasible("point projecting inside all three images");
            X = randomStructurePoint(pointRng, region);
            bool ok = true;
            for (int v = 0; v < 3 && ok; ++v)
                ok = project(views[v], X, x[v]) && insideImage(x[v], size);
            if (ok)
                break;
        }
        double* X3 = scene.points3d.ptr<double>(i);
        X3[0] = X[0]; X3[1] = X[1]; X3[2] = X[2];
        for (int v = 0; v < 3; ++v)
        {
            double* o = pointObs[v]->ptr<double>(i);
            o[0] = x[v].x; o[1] = x[v].y;
        }
    }

    // Segments: both end points in the cube and visible, long enough in every view.
    RNG lineRng = makeStream(params.seed, STREAM_LINES);
    for (int i = 0; i < M; ++i)
    {
        Point2d a[3], b[3];
        Vec3d A, B;
        int attempt = 0;
        for (;; ++attempt)
        {
            if (attempt == kMaxAttemptsPerFeature)
                infeasible(format("segment inside all three images and at least %g px long in each",
                                  kMinSegmentLengthPx).c_str());
            A = randomStructurePoint(lineRng, region);
            B = randomStructurePoint(lineRng, region);
            bool ok = true;
            for (int v = 0; v < 3 && ok; ++v)
                ok = project(views[v], A, a[v]) && project(views[v], B, b[v]) && insideImage(a[v], size) &&
                     insideImage(b[v], size) && norm(b[v] - a[v]) >= kMinSegmentLengthPx;
            if (ok)
                break;
        }
        double* L3 = scene.lines3d.ptr<double>(i);
        L3[0] = A[0]; L3[1] = A[1]; L3[2] = A[2];
        L3[3] = B[0]; L3[4] = B[1]; L3[5] = B[2];
        for (int v = 0; v < 3; ++v)
        {
            double* o = lineObs[v]->ptr<double>(i);
            o[0] = a[v].x; o[1] = a[v].y; o[2] = b[v].x; o[3] = b[v].y;
        }
    }

    // Outliers: exactly round(ratio * count) view-3 observations replaced by random ones that are
    // clearly inconsistent with the truth.
    scene.pointInliers = Mat::ones(N, 1, CV_8U);
    scene.lineInliers = Mat::ones(M, 1, CV_8U);
    RNG outlierRng = makeStream(params.seed, STREAM_OUTLIERS);
    std::vector<int> order;
    const int numPointOutliers = (int)std::lround(params.outlierRatio * N);
    order.resize(N);
    for (int i = 0; i < N; ++i)
        order[i] = i;
    for (int i = 0; i < numPointOutliers; ++i)
    {
        std::swap(order[i], order[outlierRng.uniform(i, N)]);
        const int k = order[i];
        scene.pointInliers.at<uchar>(k) = 0;
        double* o = scene.points3.ptr<double>(k);
        const Point2d truth(o[0], o[1]);
        Point2d x;
        int attempt = 0;
        do
        {
            if (attempt++ == kMaxAttemptsPerFeature)
                infeasible("outlier point far enough from the true one");
            x = randomImagePoint(outlierRng, size);
        } while (norm(x - truth) < kOutlierMinOffsetPx);
        o[0] = x.x; o[1] = x.y;
    }
    const int numLineOutliers = (int)std::lround(params.outlierRatio * M);
    order.resize(M);
    for (int i = 0; i < M; ++i)
        order[i] = i;
    for (int i = 0; i < numLineOutliers; ++i)
    {
        std::swap(order[i], order[outlierRng.uniform(i, M)]);
        const int k = order[i];
        scene.lineInliers.at<uchar>(k) = 0;
        double* o = scene.lines3.ptr<double>(k);
        const Point2d ta(o[0], o[1]), tb(o[2], o[3]);
        Point2d a, b;
        int attempt = 0;
        do
        {
            if (attempt++ == kMaxAttemptsPerFeature)
                infeasible("outlier segment far enough from the true line");
            a = randomImagePoint(outlierRng, size);
            b = randomImagePoint(outlierRng, size);
        } while (norm(b - a) < kMinSegmentLengthPx ||
                 std::max(distanceToLine(a, ta, tb), distanceToLine(b, ta, tb)) < kOutlierMinOffsetPx);
        o[0] = a.x; o[1] = a.y; o[2] = b.x; o[3] = b.y;
    }

    if (params.noiseSigma > 0)
    {
        RNG noiseRng = makeStream(params.seed, STREAM_NOISE);
        for (int v = 0; v < 3; ++v)
            for (Mat* obs : { pointObs[v], lineObs[v] })
            {
                double* d = obs->ptr<double>();
                for (size_t j = 0, n = obs->total(); j < n; ++j)
                    d[j] += noiseRng.gaussian(params.noiseSigma);
            }
    }

    scene.cameraMatrices.resize(3);
    for (int v = 0; v < 3; ++v)
        scene.cameraMatrices[v] = Mat(views[v].K, true);
    scene.R12 = Mat(views[1].R, true);
    scene.t12 = Mat(views[1].t, true);
    scene.R = Mat(views[2].R, true);
    scene.t = Mat(views[2].t, true);
    return scene;
}

} // namespace support
} // namespace tripose
} // namespace cv
