// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

cv::tripose::support::SyntheticScene outlierScene(double outlierRatio, int seed)
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = 100;
    params.numLines = 40;
    params.noiseSigma = 1.0;
    params.outlierRatio = outlierRatio;
    params.seed = seed;
    return cv::tripose::support::generateSyntheticScene(params);
}

int runRansac(const cv::tripose::support::SyntheticScene& s, const cv::tripose::RansacParams& params, Mat& R, Mat& t,
              Mat& pointMask, Mat& lineMask)
{
    return cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                s.cameraMatrices, noArray(), s.R12, s.t12, R, t, params,
                                                pointMask, lineMask);
}

typedef testing::TestWithParam<double> Tripose_Ransac;

// Up to 50 % outliers (random wrong matches in view 3), 100 points + 40 lines at
// 1 px noise: at least 99 % of trials within 1 degree and 5 % translation, masks at least 95 % right.
TEST_P(Tripose_Ransac, recovers_the_pose_and_the_inliers)
{
    const double outlierRatio = GetParam();
    const int trials = 100;
    int accurate = 0, masksRight = 0;
    std::vector<double> rotationErrors;
    for (int seed = 0; seed < trials; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = outlierScene(outlierRatio, seed);
        cv::tripose::RansacParams params;
        params.seed = seed;
        Mat R, t, pointMask, lineMask;
        const int inliers = runRansac(s, params, R, t, pointMask, lineMask);
        if (inliers == 0)
            continue;
        const PoseError e = poseError(R, t, s.R, s.t);
        rotationErrors.push_back(e.rotationDeg);
        accurate += e.rotationDeg < 1.0 && e.relativeTranslation < 0.05;
        ASSERT_EQ(pointMask.total(), (size_t)s.points1.rows);
        ASSERT_EQ(lineMask.total(), (size_t)s.lines1.rows);
        EXPECT_EQ(inliers, cv::countNonZero(pointMask) + cv::countNonZero(lineMask));
        const int agree = (int)(pointMask.total() + lineMask.total()) -
                          cv::countNonZero(pointMask.reshape(1, 1) != s.pointInliers.reshape(1, 1)) -
                          cv::countNonZero(lineMask.reshape(1, 1) != s.lineInliers.reshape(1, 1));
        masksRight += agree >= 0.95 * (pointMask.total() + lineMask.total());
    }
    std::sort(rotationErrors.begin(), rotationErrors.end());
    std::cout << "outliers " << outlierRatio * 100 << " %: accurate " << accurate << "/" << trials
              << ", masks >= 95 % right " << masksRight << "/" << trials << ", median rotation error "
              << (rotationErrors.empty() ? -1.0 : rotationErrors[rotationErrors.size() / 2]) << " deg" << std::endl;
    EXPECT_GE(accurate, 99);
    EXPECT_GE(masksRight, 99);
}

INSTANTIATE_TEST_CASE_P(/**/, Tripose_Ransac, testing::Values(0.0, 0.1, 0.3, 0.5));

// Few features: the distinct samples are enumerated (four features: one sample), so the estimator
// sees each once and stops, instead of solving the same sample until maxIterations.
TEST(Tripose_RansacFewFeatures, minimal_and_near_minimal_sets_give_the_pose)
{
    const FeatureMix mixes[] = { { 4, 0 }, { 2, 2 }, { 0, 4 }, { 3, 2 }, { 3, 3 } };
    for (const FeatureMix& mix : mixes)
        for (int seed = 0; seed < 20; ++seed)
        {
            const cv::tripose::support::SyntheticScene s = makeScene(mix, cv::tripose::support::MOTION_LARGE, 0.0, seed);
            cv::tripose::RansacParams params;
            params.seed = seed;
            params.minInliers = mix.points + mix.lines; // every feature is right: no floor above them
            Mat R, t, pointMask, lineMask;
            const int inliers = runRansac(s, params, R, t, pointMask, lineMask);
            ASSERT_EQ(inliers, mix.points + mix.lines) << mixName(mix) << " seed " << seed;
            const PoseError e = poseError(R, t, s.R, s.t);
            EXPECT_LT(e.rotationDeg, degrees(1e-6)) << mixName(mix) << " seed " << seed;
            EXPECT_LT(e.relativeTranslation, 1e-6) << mixName(mix) << " seed " << seed;
        }
}

// Every view-3 observation a wrong match, as an unrelated third image gives: without a floor on the
// inliers (minInliers 0) a pose is returned only with four inliers at least, a minimal sample (which
// fits any observations) and one more feature that agrees. Before, the refinement could settle on
// one or two inliers, which leave the pose free, and return it as found.
TEST(Tripose_RansacUnrelatedView, no_pose_rests_on_fewer_than_four_inliers)
{
    const FeatureMix mixes[] = { { 2, 5 }, { 7, 0 }, { 0, 7 }, { 3, 3 }, { 10, 10 } };
    for (const FeatureMix& mix : mixes)
        for (int seed = 0; seed < 20; ++seed)
        {
            const cv::tripose::support::SyntheticScene s =
                makeScene(mix, cv::tripose::support::MOTION_LARGE, 1.0, seed, 0.99);
            cv::tripose::RansacParams params;
            params.seed = seed;
            params.minInliers = 0;
            Mat R, t, pointMask, lineMask;
            const int inliers = runRansac(s, params, R, t, pointMask, lineMask);
            if (inliers == 0)
            {
                EXPECT_TRUE(R.empty() && t.empty()) << mixName(mix) << " seed " << seed;
                EXPECT_EQ(cv::countNonZero(pointMask) + cv::countNonZero(lineMask), 0) << mixName(mix) << " seed " << seed;
                continue;
            }
            EXPECT_GE(inliers, 4) << mixName(mix) << " seed " << seed;
            EXPECT_EQ(inliers, cv::countNonZero(pointMask) + cv::countNonZero(lineMask)) << mixName(mix) << " seed " << seed;
        }
}

// The same chance correspondences under the default floor (RansacParams::minInliers, 15): no pose,
// where without it some scenes give one.
TEST(Tripose_RansacUnrelatedView, chance_correspondences_give_no_pose_under_the_default_floor)
{
    const FeatureMix mixes[] = { { 2, 5 }, { 7, 0 }, { 0, 7 }, { 3, 3 }, { 10, 10 } };
    int withoutFloor = 0;
    for (const FeatureMix& mix : mixes)
        for (int seed = 0; seed < 20; ++seed)
        {
            const cv::tripose::support::SyntheticScene s =
                makeScene(mix, cv::tripose::support::MOTION_LARGE, 1.0, seed, 0.99);
            cv::tripose::RansacParams params;
            params.seed = seed;
            Mat R, t, pointMask, lineMask;
            EXPECT_EQ(runRansac(s, params, R, t, pointMask, lineMask), 0) << mixName(mix) << " seed " << seed;
            EXPECT_TRUE(R.empty() && t.empty()) << mixName(mix) << " seed " << seed;
            EXPECT_EQ(cv::countNonZero(pointMask) + cv::countNonZero(lineMask), 0) << mixName(mix) << " seed " << seed;
            params.minInliers = 0;
            withoutFloor += runRansac(s, params, R, t, pointMask, lineMask) > 0 ? 1 : 0;
        }
    EXPECT_GT(withoutFloor, 0) << "the scenes hold chance agreement that the floor removes";
}

TEST(Tripose_RansacDeterminism, same_seed_same_result)
{
    const cv::tripose::support::SyntheticScene s = outlierScene(0.4, 77);
    cv::tripose::RansacParams params;
    params.seed = 5;
    Mat R1, t1, p1, l1, R2, t2, p2, l2;
    runRansac(s, params, R1, t1, p1, l1);
    runRansac(s, params, R2, t2, p2, l2);
    ASSERT_FALSE(R1.empty());
    EXPECT_EQ(cv::norm(R1, R2, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(t1, t2, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(p1, p2, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(l1, l2, NORM_INF), 0.0);
}

TEST(Tripose_RansacParams, invalid_parameters_are_named)
{
    const cv::tripose::support::SyntheticScene s = outlierScene(0.0, 1);
    Mat R, t, pm, lm;
    auto expectNamed = [&](const cv::tripose::RansacParams& p, const std::string& name) {
        try
        {
            runRansac(s, p, R, t, pm, lm);
            ADD_FAILURE() << "no exception for " << name;
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(e.err.find(name), std::string::npos) << e.err;
        }
    };
    cv::tripose::RansacParams p;
    p.threshold = 0;
    expectNamed(p, "params.threshold");
    p = cv::tripose::RansacParams();
    p.threshold = -1;
    expectNamed(p, "params.threshold");
    p = cv::tripose::RansacParams();
    p.confidence = 1.0;
    expectNamed(p, "params.confidence");
    p = cv::tripose::RansacParams();
    p.confidence = 0.0;
    expectNamed(p, "params.confidence");
    p = cv::tripose::RansacParams();
    p.maxIterations = 0;
    expectNamed(p, "params.maxIterations");
    p = cv::tripose::RansacParams();
    p.minInliers = -1;
    expectNamed(p, "params.minInliers");
}

// An all-inlier probability below 1e-16 (here about 4e-5 ^ 4) rounds 1 - p to 1, which makes the
// adaptive iteration bound -inf, and converting that to an integer is undefined (the sanitizer build,
// scripts/test_sanitizers.sh, reports it): the estimator must still draw its samples.
TEST(Tripose_RansacRegression, iteration_bound_with_a_tiny_inlier_ratio)
{
    cv::tripose::support::SyntheticSceneParams sp;
    sp.numPoints = 100000;
    sp.numLines = 0;
    sp.outlierRatio = 0.99995;   // 5 true matches
    sp.seed = 3;
    const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(sp);
    cv::tripose::RansacParams params;
    params.threshold = 1.0;      // a few wrong matches fall within it by chance
    params.maxIterations = 20;
    params.refine = false;
    params.minInliers = 0; // five true matches: below the default floor
    Mat R, t, pointMask, lineMask;
    const int inliers = runRansac(s, params, R, t, pointMask, lineMask);
    EXPECT_GT(inliers, 0) << "the five true matches are there to be found";
    EXPECT_LT(inliers, 100) << "1 px gathers a few random matches, not hundreds";
    EXPECT_EQ(inliers, cv::countNonZero(pointMask));
}

}} // namespace
