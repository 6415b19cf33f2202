// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_instruction_guard: runs one hot path of the benchmarks a fixed number of times on fixed,
// seeded synthetic scenes, one thread, so that the instructions it executes are the same on every
// run of one binary. test/python/test_instruction_guard.py counts them under callgrind and compares
// them with test/benchmark/instruction_counts.txt.
//
// Only the calls inside tripose_guard_measured() are the hot path: scenes, trackers and their given
// frames are made outside it, and the counter is told to count that function only
// (valgrind --tool=callgrind --collect-atstart=no --toggle-collect=tripose_guard_measured).
//
//   tripose_instruction_guard <path> [--repeats N] [--seed-offset S]
//   paths: linear, ransac_point_rich, ransac_line_heavy, rig, multiview, tracked_frame
//
// Prints the path, the calls made and a checksum of the poses found (the same on every run).
// --seed-offset shifts the estimators' sampling seeds: how far the count moves then is how far a change
// that only alters rounding (and so the samples' fate) can move it.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp> // Rodrigues
#include <opencv2/core.hpp>
#include <opencv2/tripose.hpp>

#include "tripose_support/synthetic_multiview_scene.hpp"
#include "tripose_support/synthetic_scene.hpp"
#include "tripose_support/synthetic_stereo_scene.hpp"

#if __has_include("opencv2/tripose/tracker.hpp")
#include "opencv2/tripose/tracker.hpp"
#define TRIPOSE_GUARD_HAS_TRACKER 1
#else
#define TRIPOSE_GUARD_HAS_TRACKER 0
#endif

// The counter counts this function and its callees only, so it must keep its name and never be inlined.
extern "C" __attribute__((noinline)) void tripose_guard_measured(const std::function<void()>& hotPath)
{
    hotPath();
    asm volatile("" ::: "memory");
}

namespace {

using namespace cv::tripose::support;

//! Sum of the entries of the poses found: printed so that a path that stops finding poses shows.
double checksum = 0;

//! Added to every sampling seed (--seed-offset).
int seedOffset = 0;

void accumulate(const cv::Mat& R, const cv::Mat& t)
{
    if (!R.empty())
        checksum += cv::sum(R)[0] + cv::sum(t)[0];
}

std::vector<SyntheticScene> threeViewScenes(int count, int points, int lines, double outliers, int firstSeed)
{
    std::vector<SyntheticScene> scenes;
    for (int k = 0; k < count; ++k)
    {
        SyntheticSceneParams params;
        params.numPoints = points;
        params.numLines = lines;
        params.noiseSigma = 1.0;
        params.outlierRatio = outliers;
        params.seed = firstSeed + k;
        scenes.push_back(generateSyntheticScene(params));
    }
    return scenes;
}

//! estimatePoseLinePoint() on inlier-only triplets of 10 points and 10 lines (1 px noise).
int runLinear(int repeats)
{
    const std::vector<SyntheticScene> scenes = threeViewScenes(8, 10, 10, 0.0, 1000);
    for (int r = 0; r < repeats; ++r)
    {
        const SyntheticScene& s = scenes[r % scenes.size()];
        cv::Mat R, t;
        tripose_guard_measured([&] {
            cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                               s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t);
        });
        accumulate(R, t);
    }
    return repeats;
}

//! estimatePoseLinePointRansac() as tripose_ransac_benchmark runs it (1 px noise, threshold 2 px).
int runRansac(int repeats, int points, int lines, double outliers)
{
    const std::vector<SyntheticScene> scenes = threeViewScenes(8, points, lines, outliers, 2000);
    for (int r = 0; r < repeats; ++r)
    {
        const SyntheticScene& s = scenes[r % scenes.size()];
        cv::tripose::RansacParams params;
        params.seed = seedOffset + r;
        cv::Mat R, t;
        tripose_guard_measured([&] {
            cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                     s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t, params);
        });
        accumulate(R, t);
    }
    return repeats;
}

//! estimatePoseLinePointStereoRansac() as tripose_stereo_benchmark's RANSAC row: 100 points, 40
//! lines, half of them wrong at time B, a fifth seen by one time-B camera.
int runRig(int repeats)
{
    std::vector<SyntheticStereoScene> scenes;
    for (int k = 0; k < 4; ++k)
    {
        SyntheticStereoParams params;
        params.numPoints = 100;
        params.numLines = 40;
        params.noiseSigma = 1.0;
        params.outlierRatio = 0.5;
        params.missingRatio = 0.2;
        params.seed = 3000 + k;
        scenes.push_back(generateSyntheticStereoScene(params));
    }
    for (int r = 0; r < repeats; ++r)
    {
        const SyntheticStereoScene& s = scenes[r % scenes.size()];
        cv::tripose::RansacParams params;
        params.seed = seedOffset + r;
        cv::Mat R, t;
        tripose_guard_measured([&] {
            cv::tripose::estimatePoseLinePointStereoRansac(s.points1, s.points2, s.points3, s.points4, s.lines1,
                                                           s.lines2, s.lines3, s.lines4, s.cameraMatrices,
                                                           cv::noArray(), s.R12, s.t12, R, t, params);
        });
        accumulate(R, t);
    }
    return repeats;
}

//! estimatePoseMultiViewRansac() as the module's perf test: 4 known views, 100 points and 40
//! lines, 1 px noise, 30 % of the points 40 px off in the new view (a tracker's frame).
int runMultiView(int repeats)
{
    std::vector<SyntheticMultiViewScene> scenes;
    for (int k = 0; k < 4; ++k)
    {
        SyntheticMultiViewScene s(4, 100, 40, 5 + k);
        s.addNoise(1.0, 17 + k);
        cv::Mat& newView = s.points.back();
        for (int i = 0; i < cvRound(0.3 * newView.rows); ++i)
            newView.at<double>(i, 0) += 40.0;
        scenes.push_back(s);
    }
    for (int r = 0; r < repeats; ++r)
    {
        const SyntheticMultiViewScene& s = scenes[r % scenes.size()];
        cv::tripose::RansacParams params;
        params.seed = seedOffset + r;
        cv::Mat R, t;
        tripose_guard_measured([&] {
            cv::tripose::estimatePoseMultiViewRansac(s.points, s.lines, s.K, cv::noArray(), s.Rs, s.ts, R, t, params);
        });
        accumulate(R, t);
    }
    return repeats;
}

#if TRIPOSE_GUARD_HAS_TRACKER
const int kDescriptorLength = 128;

/** A camera moving forward with a slight turn through a scene of 300 points and 80 segments, each
with a CV_32F descriptor (the scene of modules/tripose/test/test_stereo_tracker.cpp, one camera). */
struct Sequence
{
    cv::Matx33d K = cv::Matx33d(600, 0, 320, 0, 600, 240, 0, 0, 1);
    std::vector<cv::Matx33d> Rs;
    std::vector<cv::Vec3d> ts;
    std::vector<cv::tripose::ImageFeatures> frames;

    explicit Sequence(uint64 seed)
    {
        cv::RNG rng(seed);
        std::vector<cv::Vec3d> points;
        std::vector<std::pair<cv::Vec3d, cv::Vec3d>> segments;
        for (int i = 0; i < 300; ++i)
            points.emplace_back(rng.uniform(-8.0, 8.0), rng.uniform(-4.0, 4.0), rng.uniform(6.0, 22.0));
        for (int i = 0; i < 80; ++i)
        {
            const cv::Vec3d a(rng.uniform(-8.0, 8.0), rng.uniform(-4.0, 4.0), rng.uniform(6.0, 22.0));
            cv::Vec3d d(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(0.3));
            d *= rng.uniform(0.8, 2.0) / cv::norm(d);
            segments.emplace_back(a, a + d);
        }
        cv::Mat pointDescriptors(300, kDescriptorLength, CV_32F), lineDescriptors(80, kDescriptorLength, CV_32F);
        rng.fill(pointDescriptors, cv::RNG::UNIFORM, 0.0, 1.0);
        rng.fill(lineDescriptors, cv::RNG::UNIFORM, 0.0, 1.0);
        for (int k = 0; k < 3; ++k)
        {
            cv::Mat R;
            cv::Rodrigues(cv::Vec3d(0.01 * k, 0.03 * k, 0.005 * k), R);
            Rs.push_back(cv::Matx33d(R));
            ts.push_back(-(Rs.back() * cv::Vec3d(0.25 * k, 0.02 * k, 0.4 * k)));
            frames.push_back(observe(Rs.back(), ts.back(), points, segments, pointDescriptors, lineDescriptors, rng));
        }
    }

    //! What a camera at [R|t] sees, with 0.5 px noise and descriptor noise.
    cv::tripose::ImageFeatures observe(const cv::Matx33d& R, const cv::Vec3d& t, const std::vector<cv::Vec3d>& points,
                                       const std::vector<std::pair<cv::Vec3d, cv::Vec3d>>& segments,
                                       const cv::Mat& pointDescriptors, const cv::Mat& lineDescriptors, cv::RNG& rng) const
    {
        cv::Mat pts(0, 2, CV_64F), pd(0, kDescriptorLength, CV_32F), segs(0, 4, CV_64F), ld(0, kDescriptorLength, CV_32F);
        const auto project = [&](const cv::Vec3d& X, cv::Vec2d& x) {
            const cv::Vec3d c = R * X + t;
            if (c[2] < 1.0)
                return false;
            const cv::Vec3d h = K * c;
            const double nx = rng.gaussian(0.5), ny = rng.gaussian(0.5);
            x = cv::Vec2d(h[0] / h[2] + nx, h[1] / h[2] + ny);
            return x[0] >= 0 && x[0] < 640 && x[1] >= 0 && x[1] < 480;
        };
        const auto descriptor = [&](const cv::Mat& source, int row) {
            cv::Mat n(1, kDescriptorLength, CV_32F);
            rng.fill(n, cv::RNG::NORMAL, 0.0, 0.03);
            return cv::Mat(source.row(row) + n);
        };
        for (int i = 0; i < (int)points.size(); ++i)
        {
            cv::Vec2d x;
            if (project(points[i], x))
            {
                pts.push_back(cv::Mat(cv::Matx12d(x[0], x[1])));
                pd.push_back(descriptor(pointDescriptors, i));
            }
        }
        for (int i = 0; i < (int)segments.size(); ++i)
        {
            cv::Vec2d a, b;
            const bool seenA = project(segments[i].first, a);
            const bool seenB = project(segments[i].second, b);
            if (seenA && seenB)
            {
                segs.push_back(cv::Mat(cv::Matx14d(a[0], a[1], b[0], b[1])));
                ld.push_back(descriptor(lineDescriptors, i));
            }
        }
        cv::tripose::ImageFeatures f;
        f.points = pts;
        f.pointDescriptors = pd;
        f.segments = segs;
        f.lineDescriptors = ld;
        return f;
    }
};

//! Tracker::addFeatures() of a third frame (matching to the second, registration against both), on
//! a new tracker given the first two frames' features and poses each time.
int runTrackedFrame(int repeats)
{
    const std::vector<Sequence> sequences = { Sequence(11), Sequence(12) };
    int registered = 0;
    for (int r = 0; r < repeats; ++r)
    {
        const Sequence& s = sequences[r % sequences.size()];
        cv::tripose::TrackerParams params;
        params.ransac.seed = seedOffset + r;
        cv::Ptr<cv::tripose::Tracker> tracker = cv::tripose::Tracker::create(s.K, cv::noArray(), params);
        tracker->addFeatures(s.frames[0], cv::Mat(s.Rs[0]), cv::Mat(s.ts[0]));
        tracker->addFeatures(s.frames[1], cv::Mat(s.Rs[1]), cv::Mat(s.ts[1]));
        cv::tripose::TrackedFrame frame;
        tripose_guard_measured([&] { frame = tracker->addFeatures(s.frames[2]); });
        registered += frame.status == cv::tripose::FRAME_REGISTERED;
        accumulate(frame.R, frame.t);
    }
    if (registered != repeats)
    {
        std::fprintf(stderr, "tracked_frame: %d of %d third frames registered\n", registered, repeats);
        std::exit(1);
    }
    return repeats;
}
#endif

struct HotPath
{
    const char* name;
    int defaultRepeats; //!< About 0.1-0.3 s of native work: 5-20 s under callgrind.
    std::function<int(int)> run;
};

} // namespace

int main(int argc, char** argv)
{
    const std::vector<HotPath> paths = {
        { "linear", 400, runLinear },
        { "ransac_point_rich", 160, [](int n) { return runRansac(n, 100, 40, 0.5); } },
        { "ransac_line_heavy", 160, [](int n) { return runRansac(n, 10, 60, 0.3); } },
        { "rig", 40, runRig },
        { "multiview", 20, runMultiView },
#if TRIPOSE_GUARD_HAS_TRACKER
        { "tracked_frame", 2, runTrackedFrame },
#endif
    };
    const HotPath* path = nullptr;
    if (argc >= 2)
        for (const HotPath& p : paths)
            if (argv[1] == std::string(p.name))
                path = &p;
    int repeats = path ? path->defaultRepeats : 0;
    bool argumentsOk = path && argc % 2 == 0;
    for (int i = 2; argumentsOk && i + 1 < argc; i += 2)
    {
        const std::string arg = argv[i];
        if (arg == "--repeats") repeats = std::atoi(argv[i + 1]);
        else if (arg == "--seed-offset") seedOffset = std::atoi(argv[i + 1]);
        else argumentsOk = false;
    }
    if (!argumentsOk || repeats < 1)
    {
        std::fprintf(stderr, "usage: tripose_instruction_guard <path> [--repeats N >= 1] [--seed-offset S]; paths:");
        for (const HotPath& p : paths)
            std::fprintf(stderr, " %s", p.name);
        std::fprintf(stderr, "\n");
        return 2;
    }
    // One thread (Eigen starts none: the build has no OpenMP), so that every run counts the same instructions.
    cv::setNumThreads(0);
    const int calls = path->run(repeats);
    std::printf("%s: %d calls, checksum %.6f\n", path->name, calls, checksum);
    return 0;
}
