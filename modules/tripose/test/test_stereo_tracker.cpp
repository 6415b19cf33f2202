// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// cv::tripose::StereoTracker on a synthetic stereo sequence: points and segments of a 3D scene seen
// by a rig moving along a smooth path, 0.5 px noise, a descriptor per 3D feature with noise per
// observation. Every frame registered at metric scale with no pose given; frames of noise lost and
// the next ones registered; a rig lost for long restarts a map and joins it to the first, failed
// place attempts on the way leaving the tracker as it was; bad input named.

#include "test_precomp.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "../src/opencv/opencv_compat.hpp" // Rodrigues: calib3d in OpenCV 4, geometry in 5

namespace opencv_test {
namespace {

using cv::tripose::ImageFeatures;
using cv::tripose::StereoTracker;
using cv::tripose::TrackedFrame;
using cv::tripose::TrackerParams;

const int kWidth = 640, kHeight = 480, kDescriptorLength = 128;

// About four times the worst errors of python/tests/test_stereo_tracker.py's sequences (the same scene).
const double kRotationBoundDeg = 0.3;
const double kPositionBound = 0.015; // of the path's length
// A rig that mostly turns has little path to scale a bound by: in metres, twice the depth error of
// its 0.3 m baseline at 0.5 px for points 8-16 m away (about 0.4 m) averaged over the 200-odd points
// it sees.
const double kTurningPositionBound = 0.05;

struct Pose
{
    Matx33d R;
    Vec3d t;
    Vec3d centre() const { return -(R.t() * t); }
};

Matx33d rotation(double rx, double ry, double rz)
{
    Mat R;
    Rodrigues(Vec3d(rx, ry, rz), R);
    return Matx33d(R);
}

//! A rig moving forward along a gentle S with a slight yaw and pitch, and a scene in front of it.
struct StereoSequence
{
    Matx33d K = Matx33d(600, 0, 320, 0, 600, 240, 0, 0, 1);
    Pose rig;                          //!< The right camera relative to the left.
    std::vector<Pose> poses;           //!< The left camera's, world frame = frame 0's left camera.
    std::vector<Vec3d> points;         //!< Scene points.
    std::vector<std::pair<Vec3d, Vec3d>> segments; //!< Scene segments' end points.
    Mat pointDescriptors, lineDescriptors; //!< One CV_32F row per 3D feature.
    double pathLength = 0;

    StereoSequence(int frames, uint64 seed)
    {
        RNG rng(seed);
        rig.R = rotation(0, 0.01, 0);
        rig.t = -(rig.R * Vec3d(0.3, 0, 0));
        for (int k = 0; k < frames; ++k)
        {
            const double s = k / double(frames - 1);
            const Vec3d centre(0.6 * std::sin(2 * CV_PI * s), 0.1 * std::sin(CV_PI * s), 4.5 * s);
            Pose p;
            p.R = rotation(0.03 * std::sin(CV_PI * s), 0.12 * std::sin(2 * CV_PI * s), 0.02 * s);
            p.t = -(p.R * centre);
            if (k > 0)
                pathLength += cv::norm(centre - poses.back().centre());
            poses.push_back(p);
        }
        for (int i = 0; i < 300; ++i)
            points.emplace_back(rng.uniform(-8.0, 8.0), rng.uniform(-4.0, 4.0), rng.uniform(6.0, 22.0));
        for (int i = 0; i < 80; ++i)
        {
            const Vec3d a(rng.uniform(-8.0, 8.0), rng.uniform(-4.0, 4.0), rng.uniform(6.0, 22.0));
            Vec3d d(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(0.3));
            d *= rng.uniform(0.8, 2.0) / cv::norm(d);
            segments.emplace_back(a, a + d);
        }
        pointDescriptors.create((int)points.size(), kDescriptorLength, CV_32F);
        lineDescriptors.create((int)segments.size(), kDescriptorLength, CV_32F);
        rng.fill(pointDescriptors, RNG::UNIFORM, 0.0, 1.0);
        rng.fill(lineDescriptors, RNG::UNIFORM, 0.0, 1.0);
    }

    /** Points and segments on a cylinder 8-16 m around the origin, all round, and no frame yet: a rig
    facing one way sees nothing of what it sees facing the other way. */
    static StereoSequence surrounding(uint64 seed)
    {
        StereoSequence s(0, seed);
        RNG rng(seed + 1);
        const auto around = [&]() {
            const double azimuth = rng.uniform(0.0, 2 * CV_PI), radius = rng.uniform(8.0, 16.0);
            return Vec3d(radius * std::sin(azimuth), rng.uniform(-3.0, 3.0), radius * std::cos(azimuth));
        };
        s.points.clear();
        s.segments.clear();
        for (int i = 0; i < 1500; ++i)
            s.points.push_back(around());
        for (int i = 0; i < 300; ++i)
        {
            const Vec3d a = around();
            Vec3d d(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0));
            d *= rng.uniform(0.8, 2.0) / cv::norm(d);
            s.segments.emplace_back(a, a + d);
        }
        s.pointDescriptors.create((int)s.points.size(), kDescriptorLength, CV_32F);
        s.lineDescriptors.create((int)s.segments.size(), kDescriptorLength, CV_32F);
        rng.fill(s.pointDescriptors, RNG::UNIFORM, 0.0, 1.0);
        rng.fill(s.lineDescriptors, RNG::UNIFORM, 0.0, 1.0);
        return s;
    }

    //! A frame whose left camera at @p centre looks along the azimuth @p yawDeg; its index.
    int add(double yawDeg, const Vec3d& centre)
    {
        Pose p;
        p.R = rotation(0, yawDeg * CV_PI / 180, 0).t();
        p.t = -(p.R * centre);
        if (!poses.empty())
            pathLength += cv::norm(centre - poses.back().centre());
        poses.push_back(p);
        return (int)poses.size() - 1;
    }

    Pose rightPose(int k) const
    {
        Pose p;
        p.R = rig.R * poses[k].R;
        p.t = rig.R * poses[k].t + rig.t;
        return p;
    }

    //! Where a camera at @p p sees @p X, with @p noise px; false when behind it or outside the image.
    bool project(const Pose& p, const Vec3d& X, RNG& rng, double noise, Vec2d& x) const
    {
        const Vec3d c = p.R * X + p.t;
        if (c[2] < 1.0)
            return false;
        const Vec3d h = K * c;
        x = Vec2d(h[0] / h[2] + rng.gaussian(noise), h[1] / h[2] + rng.gaussian(noise));
        return x[0] >= 0 && x[0] < kWidth && x[1] >= 0 && x[1] < kHeight;
    }

    //! What a camera at @p p sees of the scene, with @p noise px and descriptor noise.
    ImageFeatures observe(const Pose& p, RNG& rng, double noise) const
    {
        ImageFeatures f;
        Mat pts(0, 2, CV_64F), pd(0, kDescriptorLength, CV_32F), segs(0, 4, CV_64F), ld(0, kDescriptorLength, CV_32F);
        const auto project = [&](const Vec3d& X, Vec2d& x) { return this->project(p, X, rng, noise, x); };
        const auto descriptor = [&](const Mat& source, int row) {
            Mat d = source.row(row).clone();
            Mat n(1, kDescriptorLength, CV_32F);
            rng.fill(n, RNG::NORMAL, 0.0, 0.03);
            return Mat(d + n);
        };
        for (int i = 0; i < (int)points.size(); ++i)
        {
            Vec2d x;
            if (project(points[i], x))
            {
                pts.push_back(Mat(Matx12d(x[0], x[1])));
                pd.push_back(descriptor(pointDescriptors, i));
            }
        }
        for (int i = 0; i < (int)segments.size(); ++i)
        {
            Vec2d a, b;
            if (project(segments[i].first, a) && project(segments[i].second, b))
            {
                segs.push_back(Mat(Matx14d(a[0], a[1], b[0], b[1])));
                ld.push_back(descriptor(lineDescriptors, i));
            }
        }
        f.points = pts;
        f.pointDescriptors = pd;
        f.segments = segs;
        f.lineDescriptors = ld;
        return f;
    }
};

//! One stereo frame's observations of linked tracks, as StereoTracker::addObservations() takes them.
struct LinkedObservations
{
    Mat points, pointIds, rightPoints, segments, lineIds, rightSegments;
};

/** What frame @p k's rig sees, each feature named by its index in the scene, with @p noise px: the
left camera's points and segments, and their positions in the right image (NaN rows where the right
camera does not see them). */
LinkedObservations observeLinked(const StereoSequence& seq, int k, RNG& rng, double noise)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    LinkedObservations o;
    o.points.create(0, 2, CV_64F);
    o.rightPoints.create(0, 2, CV_64F);
    o.segments.create(0, 4, CV_64F);
    o.rightSegments.create(0, 4, CV_64F);
    const auto project = [&](const Pose& p, const Vec3d& X, Vec2d& x) { return seq.project(p, X, rng, noise, x); };
    const Pose left = seq.poses[k], right = seq.rightPose(k);
    std::vector<int> pointIds, lineIds;
    for (int i = 0; i < (int)seq.points.size(); ++i)
    {
        Vec2d a, b;
        if (!project(left, seq.points[i], a))
            continue;
        const bool inRight = project(right, seq.points[i], b);
        o.points.push_back(Mat(Matx12d(a[0], a[1])));
        o.rightPoints.push_back(inRight ? Mat(Matx12d(b[0], b[1])) : Mat(Matx12d(nan, nan)));
        pointIds.push_back(i);
    }
    for (int i = 0; i < (int)seq.segments.size(); ++i)
    {
        Vec2d a, b, c, d;
        if (!(project(left, seq.segments[i].first, a) && project(left, seq.segments[i].second, b)))
            continue;
        const bool inRight = project(right, seq.segments[i].first, c) && project(right, seq.segments[i].second, d);
        o.segments.push_back(Mat(Matx14d(a[0], a[1], b[0], b[1])));
        o.rightSegments.push_back(inRight ? Mat(Matx14d(c[0], c[1], d[0], d[1])) : Mat(Matx14d(nan, nan, nan, nan)));
        lineIds.push_back(i);
    }
    Mat(pointIds, true).copyTo(o.pointIds);
    Mat(lineIds, true).copyTo(o.lineIds);
    return o;
}

//! Random features: a frame of another scene, or of noise.
ImageFeatures noiseFeatures(RNG& rng, int points, int segments)
{
    ImageFeatures f;
    f.points.create(points, 2, CV_64F);
    rng.fill(f.points, RNG::UNIFORM, 0.0, (double)kHeight);
    f.pointDescriptors.create(points, kDescriptorLength, CV_32F);
    rng.fill(f.pointDescriptors, RNG::UNIFORM, 0.0, 1.0);
    f.segments.create(segments, 4, CV_64F);
    rng.fill(f.segments, RNG::UNIFORM, 0.0, (double)kHeight);
    f.lineDescriptors.create(segments, kDescriptorLength, CV_32F);
    rng.fill(f.lineDescriptors, RNG::UNIFORM, 0.0, 1.0);
    return f;
}

struct Errors
{
    double rotationDeg, position; // position in metres
};

Errors poseErrors(const TrackedFrame& r, const Pose& truth)
{
    const Matx33d R(r.R);
    const Vec3d t(r.t);
    const Matx33d dR = R * truth.R.t();
    const double c = std::max(-1.0, std::min(1.0, (dR(0, 0) + dR(1, 1) + dR(2, 2) - 1) / 2));
    const Vec3d centre = -(R.t() * t);
    return { std::acos(c) * 180 / CV_PI, cv::norm(centre - truth.centre()) };
}

Ptr<StereoTracker> makeTracker(const StereoSequence& seq)
{
    return StereoTracker::create(seq.K, noArray(), seq.K, noArray(), Mat(seq.rig.R), Mat(seq.rig.t));
}

/** Gives every frame of @p seq to the tracker through @p addFrame (the frame's index in, its result
out) and checks that frame 0 is the world's origin and every later one registered within the bounds. */
void expectRegisteredWithinBounds(const StereoSequence& seq, const std::function<TrackedFrame(int)>& addFrame)
{
    double worstRotation = 0, worstPosition = 0;
    for (int k = 0; k < (int)seq.poses.size(); ++k)
    {
        const TrackedFrame r = addFrame(k);
        ASSERT_EQ(r.frame, k);
        if (k == 0)
        {
            EXPECT_EQ(r.status, cv::tripose::FRAME_GIVEN);
            EXPECT_LE(cv::norm(Mat(r.R), Mat::eye(3, 3, CV_64F)), 0.0);
            continue;
        }
        ASSERT_EQ(r.status, cv::tripose::FRAME_REGISTERED) << "frame " << k << ": " << r.reason;
        EXPECT_GE(r.inliers, 15) << "frame " << k;
        const Errors e = poseErrors(r, seq.poses[k]);
        worstRotation = std::max(worstRotation, e.rotationDeg);
        worstPosition = std::max(worstPosition, e.position);
    }
    EXPECT_LT(worstRotation, kRotationBoundDeg);
    EXPECT_LT(worstPosition, kPositionBound * seq.pathLength);
}

TEST(Tripose_StereoTracker, registers_every_frame_at_metric_scale_without_poses)
{
    const StereoSequence seq(20, 1);
    RNG rng(7);
    Ptr<StereoTracker> tracker = makeTracker(seq);
    expectRegisteredWithinBounds(seq, [&](int k) {
        return tracker->addFrame(seq.observe(seq.poses[k], rng, 0.5), seq.observe(seq.rightPose(k), rng, 0.5));
    });
    EXPECT_EQ(tracker->numFrames(), (int)seq.poses.size());
    Mat R, t;
    EXPECT_TRUE(tracker->getPose(5, R, t));
    Mat pointTracks, lineTracks, pointStereo, lineStereo;
    tracker->getTracks(5, pointTracks, lineTracks, pointStereo, lineStereo);
    EXPECT_EQ(pointTracks.total(), pointStereo.total());
    EXPECT_EQ(lineTracks.total(), lineStereo.total());
    EXPECT_GT(countNonZero(pointStereo >= 0), 50);
    EXPECT_GT(countNonZero(lineStereo >= 0), 5);
    EXPECT_THROW(tracker->getPose(20, R, t), cv::Exception);
}

TEST(Tripose_StereoTracker, registers_linked_observations_at_metric_scale)
{
    const StereoSequence seq(20, 1);
    RNG rng(11);
    Ptr<StereoTracker> tracker = makeTracker(seq);
    expectRegisteredWithinBounds(seq, [&](int k) {
        const LinkedObservations o = observeLinked(seq, k, rng, 0.5);
        return tracker->addObservations(o.points, o.pointIds, o.rightPoints, o.segments, o.lineIds, o.rightSegments);
    });
    // A feature keeps its track from frame to frame: the ids link them, no matching does.
    Mat tracksBefore, tracksAfter, unused;
    tracker->getTracks(5, tracksBefore, unused);
    tracker->getTracks(6, tracksAfter, unused);
    std::vector<int> before(tracksBefore), after(tracksAfter);
    int shared = 0;
    for (int track : before)
        shared += track >= 0 && std::find(after.begin(), after.end(), track) != after.end();
    EXPECT_GT(shared, 100);
}

TEST(Tripose_StereoTracker, frames_of_noise_are_lost_and_the_next_ones_register)
{
    const StereoSequence seq(16, 2);
    RNG rng(11);
    Ptr<StereoTracker> tracker = makeTracker(seq);
    // One frame of noise, then a run longer than TrackerParams::maxFrameGap.
    for (int k = 0; k < (int)seq.poses.size(); ++k)
    {
        const bool noise = k == 4 || (k >= 7 && k <= 11);
        const TrackedFrame r =
            tracker->addFrame(noise ? noiseFeatures(rng, 200, 40) : seq.observe(seq.poses[k], rng, 0.5),
                              noise ? noiseFeatures(rng, 200, 40) : seq.observe(seq.rightPose(k), rng, 0.5));
        if (k == 0)
            continue;
        if (noise)
        {
            EXPECT_EQ(r.status, cv::tripose::FRAME_LOST);
            EXPECT_FALSE(r.reason.empty());
            EXPECT_TRUE(r.R.empty());
            Mat R, t;
            EXPECT_FALSE(tracker->getPose(k, R, t));
            EXPECT_EQ(tracker->getMap(k), -1);
            continue;
        }
        ASSERT_EQ(r.status, cv::tripose::FRAME_REGISTERED) << "frame " << k << ": " << r.reason;
        // The noise shows no place: the rig never restarts, and stays in the first map.
        EXPECT_EQ(r.map, 0);
        EXPECT_EQ(tracker->getMap(k), 0);
        const Errors e = poseErrors(r, seq.poses[k]);
        EXPECT_LT(e.rotationDeg, kRotationBoundDeg) << "frame " << k;
        EXPECT_LT(e.position, kPositionBound * seq.pathLength) << "frame " << k;
    }
}

TEST(Tripose_StereoTracker, a_rig_lost_for_long_restarts_and_joins_its_maps)
{
    // Eight frames facing north; the first frame's view mirrored, whose descriptors match keyframe
    // 0's under an epipolar geometry though no pose fits its points, so that its place attempt fails
    // and must leave the tracker as it was; four frames of noise; then the rig faces south, where no
    // keyframe looks, restarts a map there, turns back north in steps of 8 deg and, on seeing the
    // first frames' place, joins the new map to the first.
    StereoSequence scene = StereoSequence::surrounding(11);
    RNG rng(12);
    Ptr<StereoTracker> tracker = makeTracker(scene);
    std::vector<TrackedFrame> results;
    std::vector<int> sceneFrame; // per tracked frame, its pose in scene.poses; -1 for noise
    const auto trackFeatures = [&](const ImageFeatures& left, const ImageFeatures& right, int k) {
        sceneFrame.push_back(k);
        results.push_back(tracker->addFrame(left, right));
    };
    const auto track = [&](int k) {
        if (k < 0)
            trackFeatures(noiseFeatures(rng, 300, 60), noiseFeatures(rng, 300, 60), k);
        else
            trackFeatures(scene.observe(scene.poses[k], rng, 0.5), scene.observe(scene.rightPose(k), rng, 0.5), k);
    };
    const auto mirrored = [](ImageFeatures f) {
        for (int i = 0; i < f.points.rows; ++i)
            f.points.at<double>(i, 0) = kWidth - f.points.at<double>(i, 0);
        for (int i = 0; i < f.segments.rows; ++i)
            for (int c : { 0, 2 })
                f.segments.at<double>(i, c) = kWidth - f.segments.at<double>(i, c);
        return f;
    };
    for (int k = 0; k < 8; ++k)
        track(scene.add(3.0 * k, Vec3d(0.05 * k, 0, 0.1 * k)));
    trackFeatures(mirrored(scene.observe(scene.poses[0], rng, 0.5)),
                  mirrored(scene.observe(scene.rightPose(0), rng, 0.5)), -1);
    EXPECT_EQ(results.back().status, cv::tripose::FRAME_LOST);
    for (int k = 0; k < 4; ++k)
        track(-1);
    for (int k = 0; k < 26; ++k)
        track(scene.add(180.0 + 8.0 * k, Vec3d(0.35 + 0.02 * k, 0, 0.7 - 0.02 * k)));

    for (int i = 1; i < 8; ++i)
        ASSERT_EQ(results[i].status, cv::tripose::FRAME_REGISTERED) << "frame " << i << ": " << results[i].reason;
    int restart = -1, join = -1;
    for (int i = 8; i < (int)results.size(); ++i)
    {
        if (restart < 0 && results[i].status == cv::tripose::FRAME_RESTARTED)
            restart = i;
        else if (restart >= 0 && join < 0 && results[i].recognisedKeyframe >= 0)
            join = i;
    }
    ASSERT_GE(restart, 13) << "noise restarted a map";
    ASSERT_GT(join, restart + 1) << "the new map never joined the first";
    EXPECT_EQ(results[restart].map, 1);
    EXPECT_EQ(results[results[join].recognisedKeyframe].map, 0);
    for (int i = restart + 1; i < (int)results.size(); ++i)
        EXPECT_EQ(results[i].status, cv::tripose::FRAME_REGISTERED) << "frame " << i << ": " << results[i].reason;
    // At the end every posed frame is in the first frame's world and matches the truth.
    for (int i = 0; i < (int)results.size(); ++i)
    {
        Mat R, t;
        if (sceneFrame[i] < 0 || (i < restart && i >= 8))
        {
            EXPECT_FALSE(tracker->getPose(i, R, t)) << "frame " << i;
            continue;
        }
        ASSERT_TRUE(tracker->getPose(i, R, t)) << "frame " << i;
        EXPECT_EQ(tracker->getMap(i), 0) << "frame " << i;
        TrackedFrame now;
        now.R = R;
        now.t = t;
        const Errors e = poseErrors(now, scene.poses[sceneFrame[i]]);
        EXPECT_LT(e.rotationDeg, kRotationBoundDeg) << "frame " << i;
        EXPECT_LT(e.position, kTurningPositionBound) << "frame " << i;
    }
}

void expectThrowNaming(const std::function<void()>& f, const std::string& name)
{
    try
    {
        f();
        ADD_FAILURE() << "no exception; expected one naming " << name;
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}

TEST(Tripose_StereoTracker, bad_input_names_the_argument)
{
    const StereoSequence seq(3, 3);
    const Mat R(seq.rig.R), t(seq.rig.t), K(seq.K);
    expectThrowNaming([&] { StereoTracker::create(K, noArray(), K, noArray(), R, Mat::zeros(3, 1, CV_64F)); }, "t");
    expectThrowNaming([&] { StereoTracker::create(K, noArray(), K, noArray(), 2 * R, t); }, "R");
    expectThrowNaming([&] { StereoTracker::create(Mat::eye(2, 2, CV_64F), noArray(), K, noArray(), R, t); },
                      "leftCameraMatrix");
    expectThrowNaming([&] { StereoTracker::create(K, noArray(), Mat::zeros(3, 3, CV_64F), noArray(), R, t); },
                      "K_right");
    expectThrowNaming([&] { StereoTracker::create(K, Mat::zeros(1, 3, CV_64F), K, noArray(), R, t); }, "dist_left");
    TrackerParams params;
    params.minInliers = 0;
    expectThrowNaming([&] { StereoTracker::create(K, noArray(), K, noArray(), R, t, params); }, "params.min_inliers");

    Ptr<StereoTracker> tracker = makeTracker(seq);
    RNG rng(5);
    ImageFeatures left = seq.observe(seq.poses[0], rng, 0.5), right = seq.observe(seq.rightPose(0), rng, 0.5);
    ImageFeatures fewer = right;
    fewer.pointDescriptors = right.pointDescriptors.rowRange(0, right.pointDescriptors.rows - 1);
    expectThrowNaming([&] { tracker->addFrame(left, fewer); }, "right.pointDescriptors");
    ImageFeatures binary = right;
    binary.pointDescriptors = Mat::zeros(right.pointDescriptors.rows, 32, CV_8U);
    expectThrowNaming([&] { tracker->addFrame(left, binary); }, "right.point_descriptors");
    ImageFeatures infinite = left;
    infinite.points = left.points.clone();
    infinite.points.at<double>(0, 0) = std::numeric_limits<double>::infinity();
    expectThrowNaming([&] { tracker->addFrame(infinite, right); }, "left.points[0]");
    expectThrowNaming([&] { tracker->addFrame(left, right, R); }, "R and t");
    EXPECT_EQ(tracker->numFrames(), 0);

    Ptr<StereoTracker> linked = makeTracker(seq);
    const LinkedObservations o = observeLinked(seq, 0, rng, 0.5);
    expectThrowNaming([&] {
        linked->addObservations(o.points, o.pointIds, o.rightPoints.rowRange(1, o.rightPoints.rows), o.segments,
                                o.lineIds, o.rightSegments);
    }, "rightPoints");
    expectThrowNaming([&] {
        linked->addObservations(o.points, o.pointIds, o.rightPoints, o.segments, o.lineIds, Mat(o.rightSegments.rows, 3,
                                CV_64F, Scalar(0)));
    }, "rightSegments");
    expectThrowNaming([&] {
        linked->addObservations(o.points, noArray(), o.rightPoints, o.segments, o.lineIds, o.rightSegments);
    }, "pointIds");
    expectThrowNaming([&] {
        linked->addObservations(o.points, o.pointIds, o.rightPoints, o.segments, o.lineIds.rowRange(1, o.lineIds.rows),
                                o.rightSegments);
    }, "lineIds");
    EXPECT_EQ(linked->numFrames(), 0);
    EXPECT_EQ(linked->addObservations(o.points, o.pointIds, o.rightPoints, o.segments, o.lineIds, o.rightSegments).status,
              cv::tripose::FRAME_GIVEN);
    // A tracker takes either features or observations.
    expectThrowNaming([&] { linked->addFrame(left, right); }, "left: this tracker was given observations");

    EXPECT_EQ(tracker->addFrame(left, right).status, cv::tripose::FRAME_GIVEN);
    expectThrowNaming([&] {
        tracker->addObservations(o.points, o.pointIds, o.rightPoints, o.segments, o.lineIds, o.rightSegments);
    }, "point_ids");
}

} // namespace
} // namespace opencv_test
