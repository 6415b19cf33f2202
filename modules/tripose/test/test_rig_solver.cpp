// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The stereo-rig linear solver (src/linear/rig_solver.hpp) on the support library's rig scenes
// (generateSyntheticStereoScene: baseline 0.1-0.5 m roughly along x, cameras within 3 degrees of
// parallel, features 5-30 m in front of view 1 and inside all four 640x480 images at f = 800 px,
// the rig moving 0.3-3 m and turning up to 20 degrees between times A and B), the geometry of
// test/evaluation/codegen/stereo_rig.py, the solver's specification. Each feature's time-B visibility
// is given per mix; the ViewSet is read from the scene by the module's input function.

#include "test_precomp.hpp"
#include "test_pose_common.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/linear/rig_pose_solver.hpp"
#include "../src/core/linear/rig_solver.hpp"
#include "../src/core/linear/rig_system.hpp"

namespace opencv_test {
namespace {

using ::tripose::CameraPose;
using ::tripose::FeatureSubset;
using ::tripose::Intrinsics;
using ::tripose::RigPoseSolver;
using ::tripose::View;
using ::tripose::ViewSet;
const int kRigView4 = ::tripose::ViewSet::kRigRightB;
using ::tripose::rigPoseCandidates;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

//! A success: rotation within 1e-6 rad and translation within 1e-6 of its length.
const double kExactTolerance = 1e-6;

enum Kind
{
    POINT,
    LINE
};

//! A feature of a mix: its kind and the time-B views that see it (views 1 and 2 see every one).
struct FeatureSpec
{
    Kind kind;
    bool in3, in4;
};

struct RigMix
{
    std::string name;
    std::vector<FeatureSpec> features;
    int posesThatFit; //!< 1: the first candidate must be the true pose; more: any candidate.
};

std::ostream& operator<<(std::ostream& os, const RigMix& m)
{
    return os << m.name;
}

struct RigScene
{
    ViewSet set;
    CameraPose truth; //!< Pose of view 3.
    std::vector<CameraPose> cameras; //!< Poses of views 1-4.
};

Matrix3d toEigen33(const Mat& m)
{
    Matrix3d E;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            E(r, c) = m.at<double>(r, c);
    return E;
}

Vector3d toEigen3(const Mat& m)
{
    return Vector3d(m.at<double>(0), m.at<double>(1), m.at<double>(2));
}

/** A random rig scene with the features of @p features, observed with Gaussian noise of @p noise px
on points and segment end points. The ViewSet has the layout of rig_system.hpp. Features seen at
time A only, which the public functions reject, are made as seen by both time-B views and then
marked unseen there.
*/
RigScene makeRigScene(const std::vector<FeatureSpec>& features, int seed, double noise = 0)
{
    using namespace cv::tripose::support;
    SyntheticStereoParams params;
    params.seed = seed;
    params.noiseSigma = noise;
    std::vector<int> timeAOnlyPoints, timeAOnlyLines;
    for (const FeatureSpec& f : features)
    {
        std::vector<int>& visibility = f.kind == POINT ? params.pointVisibility : params.lineVisibility;
        if (!f.in3 && !f.in4)
            (f.kind == POINT ? timeAOnlyPoints : timeAOnlyLines).push_back((int)visibility.size());
        visibility.push_back(f.in3 && !f.in4 ? SEEN_IN_VIEW3 : !f.in3 && f.in4 ? SEEN_IN_VIEW4 : SEEN_IN_BOTH);
    }
    params.numPoints = (int)params.pointVisibility.size();
    params.numLines = (int)params.lineVisibility.size();
    const SyntheticStereoScene s = generateSyntheticStereoScene(params);

    RigScene scene;
    scene.set = cv::tripose::detail::readStereoRigInput(s.points1, s.points2, s.points3, s.points4, s.lines1,
                                                        s.lines2, s.lines3, s.lines4, s.cameraMatrices, noArray(),
                                                        s.R12, s.t12, 0);
    for (const int v : { (int)ViewSet::kView3, kRigView4 })
    {
        View& view = scene.set.views[v];
        if (!timeAOnlyPoints.empty() && view.pointSeen.empty())
            view.pointSeen.assign(params.numPoints, 1);
        for (int i : timeAOnlyPoints)
            view.pointSeen[i] = 0;
        if (!timeAOnlyLines.empty() && view.lineSeen.empty())
            view.lineSeen.assign(params.numLines, 1);
        for (int i : timeAOnlyLines)
            view.lineSeen[i] = 0;
    }
    CameraPose rig;
    rig.R = toEigen33(s.R12);
    rig.t = toEigen3(s.t12);
    scene.truth.R = toEigen33(s.R);
    scene.truth.t = toEigen3(s.t);
    scene.cameras = { CameraPose(), rig, scene.truth, ::tripose::composePose(rig, scene.truth) };
    return scene;
}

struct Error2
{
    double rotation;    //!< rad
    double translation; //!< relative to |t|
};

Error2 poseErrorOf(const CameraPose& truth, const CameraPose& pose)
{
    // Angle from |R - I|_F = 2 sqrt(2) sin(angle / 2): accurate near 0, unlike the trace.
    const double chord = (pose.R * truth.R.transpose() - Matrix3d::Identity()).norm();
    Error2 e;
    e.rotation = 2 * std::asin(std::min(1.0, chord / (2 * std::sqrt(2.0))));
    e.translation = (pose.t - truth.t).norm() / truth.t.norm();
    return e;
}

bool isTruePose(const CameraPose& truth, const CameraPose& pose)
{
    const Error2 e = poseErrorOf(truth, pose);
    return e.rotation < kExactTolerance && e.translation < kExactTolerance;
}

std::vector<FeatureSpec> repeat(const FeatureSpec& f, int n)
{
    return std::vector<FeatureSpec>(n, f);
}

std::vector<FeatureSpec> operator+(std::vector<FeatureSpec> a, const std::vector<FeatureSpec>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

const FeatureSpec kPointBoth = { POINT, true, true }, kPointOnly3 = { POINT, true, false },
                  kPointOnly4 = { POINT, false, true }, kLineBoth = { LINE, true, true },
                  kLineOnly3 = { LINE, true, false }, kLineOnly4 = { LINE, false, true };

std::vector<FeatureSpec> alternate(const FeatureSpec& a, const FeatureSpec& b, int pairs)
{
    std::vector<FeatureSpec> out;
    for (int i = 0; i < pairs; ++i)
    {
        out.push_back(a);
        out.push_back(b);
    }
    return out;
}

//! The mixes of the prototype's noise-free suite that determine the pose.
std::vector<RigMix> exactMixes()
{
    return {
        // Three features, all seen in both time-B views.
        { "3P_both", repeat(kPointBoth, 3), 1 },
        { "2P1L_both", repeat(kPointBoth, 2) + repeat(kLineBoth, 1), 1 },
        { "1P2L_both", repeat(kPointBoth, 1) + repeat(kLineBoth, 2), 1 },
        { "3L_both", repeat(kLineBoth, 3), 1 },
        // Larger sets.
        { "4P4L_both", repeat(kPointBoth, 4) + repeat(kLineBoth, 4), 1 },
        { "10P10L_both", repeat(kPointBoth, 10) + repeat(kLineBoth, 10), 1 },
        { "10P10L_half_only3_only4", alternate(kPointOnly3, kPointOnly4, 5) + alternate(kLineOnly3, kLineOnly4, 5), 1 },
        { "3P3L_view4_only", repeat(kPointOnly4, 3) + repeat(kLineOnly4, 3), 1 },
        { "3P3L_view3_only", repeat(kPointOnly3, 3) + repeat(kLineOnly3, 3), 1 },
        { "2P2L_view3_only", repeat(kPointOnly3, 2) + repeat(kLineOnly3, 2), 1 },
        // Some features missing a time-B view.
        { "2P_both_1P_only3", repeat(kPointBoth, 2) + repeat(kPointOnly3, 1), 1 },
        { "2P_both_1L_only4", repeat(kPointBoth, 2) + repeat(kLineOnly4, 1), 1 },
        { "1P1L_both_1L_only4", { kPointBoth, kLineBoth, kLineOnly4 }, 1 },
        { "1P_both_2L_single", { kPointBoth, kLineOnly3, kLineOnly4 }, 1 },
        { "2L_both_1P_only3", { kLineBoth, kLineBoth, kPointOnly3 }, 1 },
        { "4_single", { kPointOnly3, kPointOnly3, kLineOnly4, kLineOnly4 }, 1 },
        { "5_single", { kPointOnly3, kLineOnly3, kPointOnly3, kLineOnly4, kPointOnly4 }, 1 },
        // Two features seen in both views: the half turn about their common perpendicular fits too.
        { "1P1L_both", { kPointBoth, kLineBoth }, 2 },
        { "2L_both", repeat(kLineBoth, 2), 2 },
        // Minimal (kernel dimension 6): 8 or 4 poses fit.
        { "3_single_2P_only3_1P_only4", { kPointOnly3, kPointOnly3, kPointOnly4 }, 8 },
        { "3_single_1P2L_mixed", { kPointOnly4, kLineOnly3, kLineOnly4 }, 8 },
        { "3_single_2P1L_mixed", { kPointOnly3, kPointOnly4, kLineOnly4 }, 4 },
        { "3_single_3L_mixed", { kLineOnly3, kLineOnly4, kLineOnly3 }, 8 },
        { "1L_both_1P_only3", { kLineBoth, kPointOnly3 }, 4 },
        { "1L_both_1L_only4", { kLineBoth, kLineOnly4 }, 4 },
        { "3_view3_only_2P1L", { kPointOnly3, kPointOnly3, kLineOnly3 }, 4 },
        { "3_view3_only_3P", repeat(kPointOnly3, 3), 8 },
        { "3_view3_only_1P2L", { kPointOnly3, kLineOnly3, kLineOnly3 }, 8 },
        { "3_view4_only_3L", repeat(kLineOnly4, 3), 8 },
    };
}

typedef testing::TestWithParam<RigMix> Tripose_RigSolverExact;

TEST_P(Tripose_RigSolverExact, true_pose_among_candidates_in_999_of_1000_scenes)
{
    const RigMix& mix = GetParam();
    // At most one miss: 999 of 1000, and a bound that holds on any prefix of the seeds.
    const int scenes = scenesToRun(1000);
    int found = 0, candidates = 0;
    double worstRotation = 0, worstTranslation = 0;
    std::vector<int> failures;
    for (int s = 0; s < scenes; ++s)
    {
        const RigScene scene = makeRigScene(mix.features, 0x5eed0000 + s);
        std::vector<CameraPose> poses;
        const int n = rigPoseCandidates(scene.set, poses);
        ASSERT_EQ(n, (int)poses.size());
        ASSERT_LE(n, mix.posesThatFit) << "seed " << s;
        candidates += n;
        bool ok = false;
        Error2 best = { HUGE_VAL, HUGE_VAL };
        for (int i = 0; i < (mix.posesThatFit == 1 ? std::min(n, 1) : n); ++i)
        {
            ASSERT_TRUE(poses[i].allFinite());
            const Error2 e = poseErrorOf(scene.truth, poses[i]);
            if (std::max(e.rotation, e.translation) < std::max(best.rotation, best.translation))
                best = e;
            ok = ok || isTruePose(scene.truth, poses[i]);
        }
        if (ok)
        {
            ++found;
            worstRotation = std::max(worstRotation, best.rotation);
            worstTranslation = std::max(worstTranslation, best.translation);
        }
        else
            failures.push_back(s);
    }
    std::cout << "[ rig mix  ] " << mix.name << ": " << found << "/" << scenes << " found, max errors "
              << worstRotation << " rad, " << worstTranslation << " relative, mean candidates "
              << (double)candidates / scenes << std::endl;
    EXPECT_GE(found, scenes - 1) << "failed seeds: " << testing::PrintToString(failures);
}

INSTANTIATE_TEST_CASE_P(/**/, Tripose_RigSolverExact, testing::ValuesIn(exactMixes()),
                        [](const testing::TestParamInfo<RigMix>& info) { return info.param.name; });

TEST(Tripose_RigSolver, candidates_of_a_feature_subset_ignore_the_other_features)
{
    // Features outside the subset carry wrong observations at time B: they must not count.
    RigScene scene = makeRigScene(repeat(kPointBoth, 6) + repeat(kLineBoth, 4), 7);
    for (int i : { 1, 4 })
        scene.set.views[ViewSet::kView3].calibratedPoints[i] += Vector2d(0.01, -0.02);
    scene.set.views[kRigView4].calibratedLines[2] = Vector3d(1, 0, -0.1);
    const std::vector<int> points = { 0, 2, 3, 5 }, lines = { 0, 1, 3 };
    std::vector<CameraPose> poses;
    ASSERT_EQ(rigPoseCandidates(scene.set, poses, &points, &lines), 1);
    EXPECT_TRUE(isTruePose(scene.truth, poses[0]));

    // The adapter draws samples of three features and passes them on unchanged.
    const RigPoseSolver solver(scene.set);
    EXPECT_EQ(solver.sampleSize(), 3);
    FeatureSubset sample;
    sample.points = { 0, 3 };
    sample.lines = { 1 };
    std::vector<CameraPose> models;
    ASSERT_EQ(solver.estimateMinimal(sample, false, models), 1);
    EXPECT_TRUE(isTruePose(scene.truth, models[0]));
    FeatureSubset all;
    all.points = points;
    all.lines = lines;
    ASSERT_GE(all.size(), solver.nonMinimalSize());
    models.clear();
    ASSERT_EQ(solver.estimateNonMinimal(all, models), 1);
    EXPECT_TRUE(isTruePose(scene.truth, models[0]));
}

TEST(Tripose_RigSolver, translation_units_do_not_matter)
{
    // The system is balanced by the baseline: the same scene in millimetres gives the same pose.
    const RigScene scene = makeRigScene(repeat(kPointBoth, 2) + repeat(kLineOnly4, 1), 11);
    RigScene scaled = scene;
    scaled.set.views[ViewSet::kView2].pose.t *= 1000;
    scaled.set.views[kRigView4].pose.t *= 1000;
    std::vector<CameraPose> poses;
    ASSERT_EQ(rigPoseCandidates(scaled.set, poses), 1);
    EXPECT_LT(poseErrorOf(scene.truth, poses[0]).rotation, kExactTolerance);
    EXPECT_LT((poses[0].t / 1000 - scene.truth.t).norm() / scene.truth.t.norm(), kExactTolerance);
}

TEST(Tripose_RigSolver, features_that_do_not_fix_the_pose_give_no_candidate)
{
    std::vector<CameraPose> poses;
    // Two points seen in both time-B views: a turn about the line through them is free.
    EXPECT_EQ(rigPoseCandidates(makeRigScene(repeat(kPointBoth, 2), 1).set, poses), 0);
    // Features seen in view 3 only, too few: fewer than six constraints.
    EXPECT_EQ(rigPoseCandidates(makeRigScene({ kPointOnly3, kLineOnly3 }, 2).set, poses), 0);
    EXPECT_EQ(rigPoseCandidates(makeRigScene(repeat(kPointOnly3, 2), 3).set, poses), 0);
    // A single feature, or none.
    EXPECT_EQ(rigPoseCandidates(makeRigScene(repeat(kLineBoth, 1), 4).set, poses), 0);
    EXPECT_EQ(rigPoseCandidates(makeRigScene({}, 5).set, poses), 0);
    // Features seen at time A only contribute nothing.
    EXPECT_EQ(rigPoseCandidates(makeRigScene({ { POINT, false, false }, { LINE, false, false }, kPointBoth }, 6).set,
                                poses), 0);
    EXPECT_TRUE(poses.empty());
}

TEST(Tripose_RigSolver, degenerate_geometry_gives_no_candidate_and_never_nan)
{
    // Three collinear points seen in both time-B views leave a turn about their line free.
    RigScene scene = makeRigScene(repeat(kPointBoth, 3), 21);
    std::vector<CameraPose> poses;
    {
        // Rebuild the observations with the third point on the line of the first two.
        const Vector3d X0(0.5, -0.3, 12), X1(-1.0, 0.4, 15);
        const Vector3d X[3] = { X0, X1, X0 + 0.37 * (X1 - X0) };
        for (int v = 0; v < 4; ++v)
            for (int i = 0; i < 3; ++i)
            {
                View& view = scene.set.views[v];
                view.points[i] = view.camera.project(scene.cameras[v].toCamera(X[i]));
                view.calibratedPoints[i] = view.camera.calibrate(view.points[i]);
            }
    }
    EXPECT_EQ(rigPoseCandidates(scene.set, poses), 0);

    // Coincident observations and a rig without baseline: nothing finite to solve.
    RigScene same = makeRigScene(repeat(kPointBoth, 4), 22);
    for (View& view : same.set.views)
        for (Vector2d& x : view.calibratedPoints)
            x = view.calibratedPoints[0];
    poses.clear();
    EXPECT_EQ(rigPoseCandidates(same.set, poses), 0);
    EXPECT_TRUE(poses.empty());
    RigScene noBaseline = makeRigScene(repeat(kPointBoth, 4), 23);
    noBaseline.set.views[ViewSet::kView2].pose.t.setZero();
    noBaseline.set.views[kRigView4].pose.t.setZero();
    poses.clear();
    EXPECT_EQ(rigPoseCandidates(noBaseline.set, poses), 0);
}

TEST(Tripose_RigSolver, noise_one_pixel_ten_points_ten_lines)
{
    // A hypothesis for the robust loop and the refinement, not a final pose: with baselines of
    // 0.1-0.5 m at depths up to 30 m, stereo depth at time B is weak, lines most of all.
    const int scenes = 200;
    std::vector<double> rotation, translation;
    for (int s = 0; s < scenes; ++s)
    {
        const RigScene scene = makeRigScene(repeat(kPointBoth, 10) + repeat(kLineBoth, 10), 0xa0000 + s, 1.0);
        // One candidate, or two (both signs of the solution) where noise leaves its rotation block
        // far from a scaled rotation; the first fits the rows best.
        std::vector<CameraPose> poses;
        const int n = rigPoseCandidates(scene.set, poses);
        ASSERT_GE(n, 1);
        ASSERT_LE(n, 2);
        ASSERT_TRUE(poses[0].allFinite());
        const Error2 e = poseErrorOf(scene.truth, poses[0]);
        rotation.push_back(e.rotation * 180 / CV_PI);
        translation.push_back(e.translation);
    }
    std::nth_element(rotation.begin(), rotation.begin() + scenes / 2, rotation.end());
    std::nth_element(translation.begin(), translation.begin() + scenes / 2, translation.end());
    std::cout << "[ rig noise] 10P+10L both, 1 px: median rotation error " << rotation[scenes / 2]
              << " deg, median relative translation error " << translation[scenes / 2] << std::endl;
    EXPECT_LT(rotation[scenes / 2], 2.0);
}

} // namespace
} // namespace opencv_test
