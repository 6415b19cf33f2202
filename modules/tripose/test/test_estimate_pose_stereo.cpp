// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The stereo-rig functions end to end (estimatePoseLinePointStereo, ...StereoRansac,
// refinePoseLinePointStereo) on the support library's rig scenes: exactness on noise-free data,
// features missing in one time-B view, the robust estimator against wrong matches, and the
// maximum-likelihood refinement against its own limit. The solver's internal suite is
// test_rig_solver.cpp.

#include "test_pose_common.hpp"

#include "../src/opencv/opencv_compat.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::SyntheticStereoParams;
using cv::tripose::support::SyntheticStereoScene;
using cv::tripose::support::generateSyntheticStereoScene;

//! Noise-free: far above the round-off of the stacked system, far below any real error (the bound
//! of the rig solver's suite and of the three-view tests).
const double kExactRadians = 1e-6;
const double kExactRelative = 1e-6;

int solveStereo(const SyntheticStereoScene& s, Mat& R, Mat& t, int method = cv::tripose::POSE_LINEAR,
                std::vector<Mat>* Rs = nullptr, std::vector<Mat>* ts = nullptr, Mat* errors = nullptr)
{
    return cv::tripose::estimatePoseLinePointStereo(s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2,
                                                s.lines3, s.lines4, s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                                method, Rs ? _OutputArray(*Rs) : _OutputArray(noArray()),
                                                ts ? _OutputArray(*ts) : _OutputArray(noArray()),
                                                errors ? _OutputArray(*errors) : _OutputArray(noArray()));
}

double refineStereo(const SyntheticStereoScene& s, Mat& R, Mat& t, OutputArray points3d = noArray(),
                    OutputArray lines3d = noArray())
{
    return cv::tripose::refinePoseLinePointStereo(s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2,
                                              s.lines3, s.lines4, s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                              cv::tripose::RefineParams(), points3d, lines3d);
}

int ransacStereo(const SyntheticStereoScene& s, Mat& R, Mat& t, Mat& pointMask, Mat& lineMask, int seed = 0,
                 int minInliers = cv::tripose::RansacParams().minInliers)
{
    cv::tripose::RansacParams params;
    params.seed = seed;
    params.minInliers = minInliers;
    return cv::tripose::estimatePoseLinePointStereoRansac(s.points1, s.points2, s.points3, s.points4, s.lines1,
                                                      s.lines2, s.lines3, s.lines4, s.cameraMatrices, noArray(),
                                                      s.R12, s.t12, R, t, params, pointMask, lineMask);
}

bool isExact(const Mat& R, const Mat& t, const SyntheticStereoScene& s)
{
    const PoseError e = poseError(R, t, s.R, s.t);
    return e.rotationDeg < degrees(kExactRadians) && e.relativeTranslation < kExactRelative;
}

//! A feature mix of the rig: counts and which time-B views see each feature.
struct StereoMix
{
    std::string name;
    int points, lines;
    int visibility;      //!< StereoVisibility of every feature, or 0: missingRatio decides.
    double missingRatio;
};

std::ostream& operator<<(std::ostream& os, const StereoMix& m)
{
    return os << m.name;
}

SyntheticStereoParams mixParams(const StereoMix& mix, int seed)
{
    SyntheticStereoParams p = stereoParams(mix.points, mix.lines, seed, 0, 0, mix.missingRatio);
    if (mix.visibility)
    {
        p.pointVisibility.assign(mix.points, mix.visibility);
        p.lineVisibility.assign(mix.lines, mix.visibility);
    }
    return p;
}

using cv::tripose::support::SEEN_IN_BOTH;
using cv::tripose::support::SEEN_IN_VIEW3;
using cv::tripose::support::SEEN_IN_VIEW4;

typedef testing::TestWithParam<StereoMix> Tripose_StereoExact;

// Every mix here determines the motion uniquely (test_rig_solver.cpp lists the ones with several
// solutions): the best candidate must be the true pose in every scene.
TEST_P(Tripose_StereoExact, true_pose_first_in_every_scene)
{
    const StereoMix& mix = GetParam();
    const int scenes = 300;
    int exact = 0, candidates = 0;
    double worstRotation = 0, worstTranslation = 0;
    std::vector<int> failures;
    for (int seed = 0; seed < scenes; ++seed)
    {
        const SyntheticStereoScene s = generateSyntheticStereoScene(mixParams(mix, 1000 + seed));
        Mat R, t, errors;
        std::vector<Mat> Rs, ts;
        const int n = solveStereo(s, R, t, cv::tripose::POSE_LINEAR, &Rs, &ts, &errors);
        ASSERT_EQ((int)Rs.size(), n);
        ASSERT_EQ((int)errors.total(), n);
        candidates += n;
        if (n == 0 || !isExact(R, t, s))
        {
            failures.push_back(seed);
            continue;
        }
        ++exact;
        const PoseError e = poseError(R, t, s.R, s.t);
        worstRotation = std::max(worstRotation, e.rotationDeg);
        worstTranslation = std::max(worstTranslation, e.relativeTranslation);
        EXPECT_LT(errors.at<double>(0), 1e-6) << "seed " << seed; // pixels: the data fit exactly
    }
    std::cout << "[ stereo   ] " << mix.name << ": " << exact << "/" << scenes << " exact, max errors "
              << worstRotation << " deg, " << worstTranslation << " relative, mean candidates "
              << (double)candidates / scenes << std::endl;
    EXPECT_EQ(exact, scenes) << "failed seeds (+1000): " << testing::PrintToString(failures);
}

INSTANTIATE_TEST_CASE_P(/**/, Tripose_StereoExact, testing::Values(
    StereoMix{ "3P_both", 3, 0, SEEN_IN_BOTH, 0 },
    StereoMix{ "3L_both", 0, 3, SEEN_IN_BOTH, 0 },
    StereoMix{ "2P1L_both", 2, 1, SEEN_IN_BOTH, 0 },
    StereoMix{ "1P2L_both", 1, 2, SEEN_IN_BOTH, 0 },
    StereoMix{ "4P4L_both", 4, 4, SEEN_IN_BOTH, 0 },
    StereoMix{ "10P10L_both", 10, 10, SEEN_IN_BOTH, 0 },
    StereoMix{ "40P40L_both", 40, 40, SEEN_IN_BOTH, 0 },
    StereoMix{ "10P10L_half_missing", 10, 10, 0, 0.5 },
    StereoMix{ "10P10L_all_missing_one", 10, 10, 0, 1.0 },
    StereoMix{ "3P3L_view3_only", 3, 3, SEEN_IN_VIEW3, 0 },
    StereoMix{ "3P3L_view4_only", 3, 3, SEEN_IN_VIEW4, 0 }),
    [](const testing::TestParamInfo<StereoMix>& info) { return info.param.name; });

TEST(Tripose_Stereo, missing_rows_may_be_float_and_empty_views_see_nothing)
{
    // NaN rows in CV_32F arrays, and a view given as an empty array for a kind it does not see.
    SyntheticStereoParams p = stereoParams(6, 6, 7);
    p.pointVisibility.assign(6, SEEN_IN_VIEW3);
    p.lineVisibility.assign(6, SEEN_IN_VIEW4);
    const SyntheticStereoScene s = generateSyntheticStereoScene(p);
    Mat R, t;
    ASSERT_GE(cv::tripose::estimatePoseLinePointStereo(s.points1, s.points2, s.points3, Mat(), s.lines1, s.lines2, Mat(),
                                                   s.lines4, s.cameraMatrices, noArray(), s.R12, s.t12, R, t), 1);
    EXPECT_TRUE(isExact(R, t, s));
    Mat f[8];
    const Mat* in[8] = { &s.points1, &s.points2, &s.points3, &s.points4, &s.lines1, &s.lines2, &s.lines3, &s.lines4 };
    for (int i = 0; i < 8; ++i)
        in[i]->convertTo(f[i], CV_32F);
    ASSERT_TRUE(cvIsNaN(f[3].at<float>(0, 0)));
    ASSERT_GE(cv::tripose::estimatePoseLinePointStereo(f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], s.cameraMatrices[0],
                                                   noArray(), s.R12, s.t12, R, t), 1);
    // float32 pixels carry ~1e-5 px of rounding.
    const PoseError e = poseError(R, t, s.R, s.t);
    EXPECT_LT(e.rotationDeg, 1e-3);
    EXPECT_LT(e.relativeTranslation, 1e-3);
}

TEST(Tripose_Stereo, a_wrong_observation_marked_missing_does_no_harm)
{
    // A wrong view-4 point and view-3 line spoil the estimate; marked missing (NaN), they are not
    // read and the pose is exact again from the remaining observations.
    SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(5, 5, 8));
    s.points4.row(2) += Scalar(15, -10);
    s.lines3.row(1) += Scalar(0, 12, 0, -12);
    Mat R, t;
    ASSERT_GE(solveStereo(s, R, t), 1);
    EXPECT_FALSE(isExact(R, t, s));
    s.points4.row(2).setTo(std::numeric_limits<double>::quiet_NaN());
    s.lines3.row(1).setTo(std::numeric_limits<double>::quiet_NaN());
    ASSERT_GE(solveStereo(s, R, t), 1);
    EXPECT_TRUE(isExact(R, t, s));
}

TEST(Tripose_Stereo, linear_refine_is_exact_on_exact_data_and_improves_noisy_estimates)
{
    // The median comparison is made over the scenes run; under TRIPOSE_TEST_SCENE_LIMIT (3 in the
    // sanitizer run) it holds on the first ones as well.
    const int scenes = scenesToRun(40);
    std::vector<double> linear, refined;
    for (int seed = 0; seed < scenes; ++seed)
    {
        const SyntheticStereoScene exact = generateSyntheticStereoScene(stereoParams(4, 4, 200 + seed, 0, 0, 0.25));
        Mat R, t, errors;
        ASSERT_GE(solveStereo(exact, R, t, cv::tripose::POSE_LINEAR_REFINE, nullptr, nullptr, &errors), 1);
        EXPECT_TRUE(isExact(R, t, exact)) << "seed " << seed;
        EXPECT_LT(errors.at<double>(0), 1e-6);

        const SyntheticStereoScene noisy = generateSyntheticStereoScene(stereoParams(10, 10, 300 + seed, 1.0));
        ASSERT_GE(solveStereo(noisy, R, t, cv::tripose::POSE_LINEAR), 1);
        linear.push_back(poseError(R, t, noisy.R, noisy.t).rotationDeg);
        ASSERT_GE(solveStereo(noisy, R, t, cv::tripose::POSE_LINEAR_REFINE), 1);
        refined.push_back(poseError(R, t, noisy.R, noisy.t).rotationDeg);
    }
    std::cout << "[ stereo   ] 10P+10L, 1 px, " << scenes << " scenes: median rotation error linear " << median(linear)
              << " deg, linear + refine " << median(refined) << " deg" << std::endl;
    EXPECT_LT(median(refined), median(linear));
}

TEST(Tripose_Stereo, ransac_finds_the_pose_and_the_wrong_matches)
{
    // 100 points + 40 lines, 1 px noise, up to half of them wrong matches at time B (consistent in
    // views 3 and 4, as a stereo matcher would make them), a fifth seen by one time-B view only.
    // Not every scene succeeds: hypotheses are scored against structure triangulated from the rig
    // at time A alone, which a 0.1-0.5 m baseline places poorly at 5-30 m, so in some scenes the
    // consensus stops short of the truth (doc/studies/evaluation.md, "Stereo rig", counts them).
    // Where it succeeds the pose and the masks must be right.
    const int scenes = 10;
    for (double outliers : { 0.0, 0.25, 0.5 })
    {
        std::vector<double> rotation, translation;
        int accurate = 0, missedInliers = 0, acceptedOutliers = 0, inliers = 0, outlierCount = 0;
        for (int seed = 0; seed < scenes; ++seed)
        {
            const SyntheticStereoScene s =
                generateSyntheticStereoScene(stereoParams(100, 40, 400 + seed, 1.0, outliers, 0.2));
            Mat R, t, pointMask, lineMask;
            const int n = ransacStereo(s, R, t, pointMask, lineMask, seed);
            ASSERT_GT(n, 0);
            ASSERT_EQ(pointMask.total(), 100u);
            ASSERT_EQ(lineMask.total(), 40u);
            EXPECT_EQ(n, cv::countNonZero(pointMask) + cv::countNonZero(lineMask));
            const PoseError e = poseError(R, t, s.R, s.t);
            if (!(e.rotationDeg < 0.5 && e.relativeTranslation < 0.1))
            {
                std::cout << "[ stereo   ] RANSAC, " << outliers * 100 << " % outliers, seed " << 400 + seed
                          << ": off by " << e.rotationDeg << " deg, " << e.relativeTranslation << " relative, "
                          << n << " inliers" << std::endl;
                continue;
            }
            ++accurate;
            rotation.push_back(e.rotationDeg);
            translation.push_back(e.relativeTranslation);
            const Mat truth[2] = { s.pointInliers, s.lineInliers };
            const Mat found[2] = { pointMask.reshape(1, (int)pointMask.total()),
                                   lineMask.reshape(1, (int)lineMask.total()) };
            for (int k = 0; k < 2; ++k)
                for (int i = 0; i < truth[k].rows; ++i)
                {
                    const bool isInlier = truth[k].at<uchar>(i) != 0, marked = found[k].at<uchar>(i) != 0;
                    inliers += isInlier;
                    outlierCount += !isInlier;
                    missedInliers += isInlier && !marked;
                    acceptedOutliers += !isInlier && marked;
                }
        }
        std::cout << "[ stereo   ] RANSAC 100P+40L, 1 px, " << outliers * 100 << " % outliers: " << accurate << "/"
                  << scenes << " accurate, their median rotation error " << median(rotation)
                  << " deg, median relative translation error " << median(translation)
                  << "; true matches rejected " << missedInliers << "/" << inliers << ", wrong matches accepted "
                  << acceptedOutliers << "/" << outlierCount << std::endl;
        EXPECT_GE(accurate, scenes - 2);
        EXPECT_LT(median(rotation), 0.15);
        EXPECT_LT(median(translation), 0.03);
        // A true match beyond the 2 px threshold at 1 px noise is rare; a wrong match within it
        // is a coincidence of a 20 px or larger offset.
        EXPECT_LE(missedInliers, 0.02 * inliers);
        EXPECT_LE(acceptedOutliers, 0.02 * outlierCount + 1);
    }
}

// The rig's robust estimate reports its candidates as the three-view one does, and the rig's
// refinement descends from the estimator's pose alone: the one candidate is the returned pose, its
// error the RMS over the inliers' residuals in the four views; none without refinement.
TEST(Tripose_Stereo, ransac_reports_its_pose_as_the_one_candidate)
{
    for (int seed = 0; seed < 4; ++seed)
    {
        SCOPED_TRACE(cv::format("seed %d", 500 + seed));
        const SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(60, 30, 500 + seed, 1.0, 0.25, 0.2));
        cv::tripose::RansacParams params;
        params.seed = seed;
        Mat R, t, pointMask, lineMask, errors, covariance, noiseVariance;
        std::vector<Mat> Rs, ts;
        ASSERT_GT(cv::tripose::estimatePoseLinePointStereoRansac(
                      s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2, s.lines3, s.lines4,
                      s.cameraMatrices, noArray(), s.R12, s.t12, R, t, params, pointMask, lineMask, Rs, ts, errors,
                      covariance, noiseVariance),
                  0);
        ASSERT_EQ(1u, Rs.size());
        ASSERT_EQ(1u, ts.size());
        ASSERT_EQ(1, errors.rows);
        EXPECT_EQ(0, cv::norm(Rs[0], R, NORM_INF));
        EXPECT_EQ(0, cv::norm(ts[0], t, NORM_INF));
        // 1 px noise: the inliers' RMS over their coordinates near 1 px.
        EXPECT_GT(errors.at<double>(0), 0.5);
        EXPECT_LT(errors.at<double>(0), 1.5);
        EXPECT_EQ(6, covariance.rows);

        params.refine = false;
        ASSERT_GT(cv::tripose::estimatePoseLinePointStereoRansac(
                      s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2, s.lines3, s.lines4,
                      s.cameraMatrices, noArray(), s.R12, s.t12, R, t, params, pointMask, lineMask, Rs, ts, errors),
                  0);
        EXPECT_TRUE(Rs.empty());
        EXPECT_TRUE(ts.empty());
        EXPECT_TRUE(errors.empty());
    }
}

//! The scene without its wrong matches: the rows that s.pointInliers / s.lineInliers mark, in every view.
SyntheticStereoScene trueMatchesOnly(const SyntheticStereoScene& s)
{
    SyntheticStereoScene out = s;
    const auto select = [](const Mat& rows, const Mat& keep) {
        Mat kept;
        for (int i = 0; i < rows.rows; ++i)
            if (keep.at<uchar>(i))
                kept.push_back(rows.row(i));
        return kept;
    };
    Mat* points[4] = { &out.points1, &out.points2, &out.points3, &out.points4 };
    Mat* lines[4] = { &out.lines1, &out.lines2, &out.lines3, &out.lines4 };
    for (int v = 0; v < 4; ++v)
    {
        *points[v] = select(*points[v], s.pointInliers);
        *lines[v] = select(*lines[v], s.lineInliers);
    }
    return out;
}

TEST(Tripose_Stereo, ransac_is_not_pulled_off_by_wrong_lines_that_pass_the_inlier_test)
{
    // Scenes of the outlier experiment (tripose_evaluate stereo --points 100 --lines 40 --noise 1
    // --outliers 0.5 --threshold 3 --seed 4000, trials 55, 94, 161 and 177) in which the estimate was
    // 0.6-2.7 degrees off while the four-view refinement from the truth on the true matches is within
    // 0.1: wrong line matches consistent between the two time-B images pass the re-triangulated
    // inlier test, and the least-squares settle followed them (doc/studies/evaluation.md, Stereo rig).
    for (int trial : { 55, 94, 161, 177 })
    {
        const SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(100, 40, 4000 + trial, 1.0, 0.5));
        Mat R = s.R.clone(), t = s.t.clone();
        ASSERT_TRUE(std::isfinite(refineStereo(trueMatchesOnly(s), R, t)));
        const double limit = poseError(R, t, s.R, s.t).rotationDeg;
        ASSERT_LT(limit, 0.1) << "trial " << trial;

        cv::tripose::RansacParams params;
        params.threshold = 3;
        params.seed = 4000;
        Mat pointMask, lineMask;
        ASSERT_GT(cv::tripose::estimatePoseLinePointStereoRansac(s.points1, s.points2, s.points3, s.points4,
                                                                 s.lines1, s.lines2, s.lines3, s.lines4,
                                                                 s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                                                 params, pointMask, lineMask),
                  0);
        const PoseError e = poseError(R, t, s.R, s.t);
        std::cout << "[ stereo   ] outlier experiment, 50 %, trial " << trial << ": " << e.rotationDeg
                  << " deg (limit " << limit << " deg)" << std::endl;
        EXPECT_LT(e.rotationDeg, 0.5) << "trial " << trial;
    }
}

TEST(Tripose_Stereo, refinement_from_a_perturbed_pose_returns_the_truth)
{
    RNG rng(31);
    cv::tripose::RefineParams params;
    // From 2 degrees and 10 % off, the weakly determined depth of far features (a 0.1-0.5 m rig
    // at up to 30 m) makes the descent slow: one of these scenes needs more than the default 30 steps.
    params.maxIterations = 100;
    for (int seed = 0; seed < 20; ++seed)
    {
        const SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(8, 8, 500 + seed, 0, 0, 0.3));
        Mat R, t;
        perturbPose(s.R, s.t, 2.0, 0.1, rng, R, t);
        const double rms = cv::tripose::refinePoseLinePointStereo(s.points1, s.points2, s.points3, s.points4, s.lines1,
                                                              s.lines2, s.lines3, s.lines4, s.cameraMatrices,
                                                              noArray(), s.R12, s.t12, R, t, params);
        EXPECT_LT(rms, 1e-6) << "seed " << seed;
        EXPECT_TRUE(isExact(R, t, s)) << "seed " << seed << ": " << poseError(R, t, s.R, s.t).rotationDeg << " deg";

        // The structure as well, from a start close enough that every feature's first triangulation
        // (from all four views at the start pose) is in front of the cameras: from farther, a point
        // triangulated behind a camera stays out of the cost and its row is that triangulation.
        perturbPose(s.R, s.t, 0.2, 0.01, rng, R, t);
        Mat points3d, lines3d;
        EXPECT_LT(refineStereo(s, R, t, points3d, lines3d), 1e-6) << "seed " << seed;
        EXPECT_TRUE(isExact(R, t, s)) << "seed " << seed;
        ASSERT_EQ(points3d.size(), Size(3, 8));
        ASSERT_EQ(lines3d.size(), Size(6, 8));
        EXPECT_LT(cv::norm(points3d, s.points3d, NORM_INF), 1e-6) << "seed " << seed;
    }
}

TEST(Tripose_Stereo, refinement_of_noisy_data_reaches_the_maximum_likelihood_limit)
{
    // The limit: refinement started from the true pose. Started in its basin (1 degree, 5 % off)
    // the refinement must reach the same accuracy. From the linear estimate it gains a factor of
    // several, but the linear estimate at 1 px is sometimes degrees off, outside the basin: the
    // median refined from it stays above the limit, so it is required only to halve the linear error.
    std::vector<double> linear, fromLinear, fromNear, fromTruth;
    RNG rng(17);
    const int scenes = 60;
    for (int seed = 0; seed < scenes; ++seed)
    {
        const SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(10, 10, 600 + seed, 1.0, 0, 0.2));
        Mat R, t;
        ASSERT_GE(solveStereo(s, R, t), 1);
        linear.push_back(poseError(R, t, s.R, s.t).rotationDeg);
        ASSERT_TRUE(std::isfinite(refineStereo(s, R, t)));
        fromLinear.push_back(poseError(R, t, s.R, s.t).rotationDeg);
        perturbPose(s.R, s.t, 1.0, 0.05, rng, R, t);
        ASSERT_TRUE(std::isfinite(refineStereo(s, R, t)));
        fromNear.push_back(poseError(R, t, s.R, s.t).rotationDeg);
        Mat Rt = s.R.clone(), tt = s.t.clone();
        ASSERT_TRUE(std::isfinite(refineStereo(s, Rt, tt)));
        fromTruth.push_back(poseError(Rt, tt, s.R, s.t).rotationDeg);
    }
    std::cout << "[ stereo   ] 10P+10L, 1 px, " << scenes << " scenes: median rotation error linear " << median(linear)
              << " deg, refined from linear " << median(fromLinear) << " deg, from 1 deg / 5 % off "
              << median(fromNear) << " deg, from the truth (the limit) " << median(fromTruth) << " deg" << std::endl;
    EXPECT_LT(std::abs(median(fromNear) - median(fromTruth)), 0.02 * median(fromTruth));
    EXPECT_LT(median(fromLinear), 0.5 * median(linear));
}

TEST(Tripose_Stereo, ransac_reaches_the_four_view_limit_and_beats_the_alternatives)
{
    // The regime of issue 14 (the scene generator's defaults: a 0.1-0.5 m rig, structure at 5-30 m,
    // motion 0.3-3 m), 1 px noise, every feature seen in both time-B views. The criterion: the
    // median rotation error of the robust estimate within 5 % of the four-view limit (refinement
    // from the true pose), and below the three-view estimate on views 1-3 (the right image at B
    // must help) and triangulation from the rig at A + SQPnP on the left image at B. Measured
    // over 500 scenes per mix (doc/studies/evaluation.md, Stereo rig): 1.00x the limit. A single
    // refinement from the linear estimate (refinePoseLinePointStereo) does not meet it with
    // 10 + 10 features: the linear estimate is degrees off in some scenes, in another basin.
    const int scenes = 30;
    for (int n : { 4, 10 })
    {
        std::vector<double> ransac, limit, threeView, pnp;
        for (int seed = 0; seed < scenes; ++seed)
        {
            const SyntheticStereoScene s = generateSyntheticStereoScene(stereoParams(n, n, 900 + seed, 1.0));
            Mat R, t, pointMask, lineMask;
            // 4 + 4 features, all right: no floor on the inliers above them.
            ASSERT_GT(ransacStereo(s, R, t, pointMask, lineMask, seed, 0), 0) << "seed " << 900 + seed;
            ransac.push_back(poseError(R, t, s.R, s.t).rotationDeg);

            R = s.R.clone();
            t = s.t.clone();
            ASSERT_TRUE(std::isfinite(refineStereo(s, R, t)));
            limit.push_back(poseError(R, t, s.R, s.t).rotationDeg);

            cv::tripose::RansacParams params;
            params.seed = seed;
            params.minInliers = 0;
            const std::vector<Mat> K123(s.cameraMatrices.begin(), s.cameraMatrices.begin() + 3);
            ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                           s.lines3, K123, noArray(), s.R12, s.t12, R, t, params),
                      0);
            threeView.push_back(poseError(R, t, s.R, s.t).rotationDeg);

            const Mat X = triangulateFromKnownPair(s.cameraMatrices, s.R12, s.t12, s.points1, s.points2);
            Mat rvec;
            ASSERT_TRUE(solvePnP(X, s.points3, s.cameraMatrices[2], noArray(), rvec, t, false, SOLVEPNP_SQPNP));
            Rodrigues(rvec, R);
            pnp.push_back(poseError(R, t, s.R, s.t).rotationDeg);
        }
        std::cout << "[ stereo   ] " << n << "P+" << n << "L, 1 px, " << scenes
                  << " scenes: median rotation error RANSAC " << median(ransac) << " deg, four-view limit "
                  << median(limit) << " deg, three-view RANSAC on views 1-3 " << median(threeView)
                  << " deg, triangulation + SQPnP " << median(pnp) << " deg" << std::endl;
        EXPECT_LE(median(ransac), 1.05 * median(limit)) << n << "P+" << n << "L";
        EXPECT_LT(median(ransac), median(threeView)) << n << "P+" << n << "L";
        EXPECT_LT(median(ransac), median(pnp)) << n << "P+" << n << "L";
    }
}

//! Moves the points @p which of @p s onto the 3D line through points 0 and 1, observed exactly in all four views.
void placeOnLine(SyntheticStereoScene& s, const std::vector<int>& which)
{
    const Vec3d X0(s.points3d.ptr<double>(0)), X1(s.points3d.ptr<double>(1));
    const Matx33d K = toMatx33(s.cameraMatrices[0]);
    const Matx33d R12 = toMatx33(s.R12), R = toMatx33(s.R);
    const Vec3d t12 = toVec3(s.t12), t = toVec3(s.t);
    const Matx33d Rv[4] = { Matx33d::eye(), R12, R, R12 * R };
    const Vec3d tv[4] = { Vec3d(), t12, t, R12 * t + t12 };
    Mat* obs[4] = { &s.points1, &s.points2, &s.points3, &s.points4 };
    for (size_t k = 0; k < which.size(); ++k)
    {
        const Vec3d X = X0 + (0.37 + 0.29 * (double)k) * (X1 - X0);
        for (int v = 0; v < 4; ++v)
        {
            const Vec3d p = K * (Rv[v] * X + tv[v]);
            obs[v]->at<double>(which[k], 0) = p[0] / p[2];
            obs[v]->at<double>(which[k], 1) = p[1] / p[2];
        }
    }
}

TEST(Tripose_Stereo, degenerate_input_gives_no_candidate)
{
    Mat R, t;
    std::vector<Mat> Rs, ts;
    // Two points seen in both time-B views: a turn about the line through them is free.
    const SyntheticStereoScene two = generateSyntheticStereoScene(stereoParams(2, 0, 41));
    EXPECT_EQ(solveStereo(two, R, t, cv::tripose::POSE_LINEAR, &Rs, &ts), 0);
    EXPECT_TRUE(R.empty() && t.empty() && Rs.empty() && ts.empty());

    // Four points on one 3D line, seen by both time-B views: the robust estimator finds no pose.
    SyntheticStereoScene line = generateSyntheticStereoScene(stereoParams(4, 0, 45));
    placeOnLine(line, { 2, 3 });
    Mat pointMask, lineMask;
    EXPECT_EQ(ransacStereo(line, R, t, pointMask, lineMask), 0);
    EXPECT_TRUE(R.empty() && t.empty());
    EXPECT_EQ(cv::countNonZero(pointMask), 0);

    // Three collinear points: a turn about their line is free.
    SyntheticStereoScene collinear = generateSyntheticStereoScene(stereoParams(3, 0, 42));
    placeOnLine(collinear, { 2 });
    EXPECT_EQ(solveStereo(collinear, R, t), 0);

    // Two features seen by view 3 only: fewer constraints than unknowns.
    SyntheticStereoParams few = stereoParams(1, 1, 43);
    few.pointVisibility = { SEEN_IN_VIEW3 };
    few.lineVisibility = { SEEN_IN_VIEW3 };
    EXPECT_EQ(solveStereo(generateSyntheticStereoScene(few), R, t), 0);

    // Every observation the same pixel: nothing finite to solve, and never NaN.
    SyntheticStereoScene same = generateSyntheticStereoScene(stereoParams(5, 0, 44));
    for (Mat* m : { &same.points1, &same.points2, &same.points3, &same.points4 })
        *m = Mat(5, 2, CV_64F, Scalar(320, 240));
    EXPECT_EQ(solveStereo(same, R, t, cv::tripose::POSE_LINEAR, &Rs, &ts), 0);
    EXPECT_TRUE(R.empty() && t.empty() && Rs.empty() && ts.empty());
}

}} // namespace
