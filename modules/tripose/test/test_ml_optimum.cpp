// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Does the estimator reach the three-view maximum-likelihood optimum in the hard regimes (a narrow
// known pair, planar structure)? The reference is refinement started from the true pose. A small
// sample of each regime for CI; the full study (all regimes, 100+ scenes) is
// build/test/evaluation/tripose_ml_study, reported in doc/studies/accuracy.md.

#include "test_precomp.hpp"
#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::SyntheticScene;
using cv::tripose::support::SyntheticSceneParams;
using cv::tripose::support::generateSyntheticScene;

const int kScenes = 20;
// The refined RMS of an estimate at the optimum matches the reference to the refinement's
// convergence tolerance (1e-10 relative); 1e-3 px separates it from other minima, which the
// study finds 0.02 px or more above.
const double kRmsTolerance = 1e-3;

double refinedRms(const SyntheticScene& s, Mat& R, Mat& t)
{
    return cv::tripose::refinePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                        s.cameraMatrices, noArray(), s.R12, s.t12, R, t);
}

struct OptimumRegime
{
    const char* name;
    int motion;
    double baselineFraction;
    bool planar;
};

typedef testing::TestWithParam<OptimumRegime> Tripose_MlOptimum;

TEST_P(Tripose_MlOptimum, estimates_reach_the_optimum_from_the_truth)
{
    const OptimumRegime regime = GetParam();
    const int scenes = scenesToRun(kScenes);
    int ransacReached = 0, linearReached = 0;
    for (int seed = 0; seed < scenes; ++seed)
    {
        SyntheticSceneParams params;
        params.numPoints = 10;
        params.numLines = 10;
        params.motion = regime.motion;
        params.baseline12Fraction = regime.baselineFraction;
        params.planar = regime.planar;
        params.noiseSigma = 1.0;
        params.seed = 1000 + seed;
        const SyntheticScene s = generateSyntheticScene(params);
        Mat Rml = s.R.clone(), tml = s.t.clone();
        const double reference = refinedRms(s, Rml, tml);

        cv::tripose::RansacParams ransac;
        ransac.threshold = 4.0;
        Mat R, t;
        if (cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                 s.cameraMatrices, noArray(), s.R12, s.t12, R, t, ransac) > 0)
            ransacReached += refinedRms(s, R, t) <= reference + kRmsTolerance;

        R.release();
        t.release();
        if (cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                           s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                           cv::tripose::POSE_LINEAR_REFINE) > 0)
            linearReached += refinedRms(s, R, t) <= reference + kRmsTolerance;
    }
    std::cout << regime.name << " 10P+10L 1 px: RMS at or below the optimum from the truth: RANSAC "
              << ransacReached << "/" << scenes << ", linear + refine " << linearReached << "/" << scenes
              << std::endl;
    // The target, 95 %: at most one scene of twenty. Linear + refinement falls short of it in the
    // narrowest and planar large-motion regimes (doc/studies/accuracy.md): it is allowed one scene more, the
    // gap documented rather than hidden. (Bounds on the misses: they hold on any prefix of the seeds.)
    EXPECT_GE(ransacReached, scenes - 1);
    EXPECT_GE(linearReached, scenes - 2);
}

INSTANTIATE_TEST_CASE_P(Regimes, Tripose_MlOptimum,
    testing::Values(OptimumRegime{ "narrow 1 %", cv::tripose::support::MOTION_SMALL, 0.01, false },
                    OptimumRegime{ "narrow 0.5 %", cv::tripose::support::MOTION_SMALL, 0.005, false },
                    OptimumRegime{ "planar large", cv::tripose::support::MOTION_LARGE, 0.0, true },
                    OptimumRegime{ "planar small", cv::tripose::support::MOTION_SMALL, 0.0, true }));

TEST(Tripose_SyntheticRegimes, narrow_baseline_and_planar_structure)
{
    SyntheticSceneParams params;
    params.numPoints = 6;
    params.numLines = 6;
    params.motion = cv::tripose::support::MOTION_SMALL;
    params.baseline12Fraction = 0.01;
    params.planar = true;
    params.planeTilt = 30.0;
    const SyntheticScene s = generateSyntheticScene(params);
    // View 2's centre at 1 % of the 20 m camera distance from view 1 (at the origin).
    const Matx33d R12 = toMatx33(s.R12);
    const Vec3d c2 = -(R12.t() * toVec3(s.t12));
    EXPECT_NEAR(cv::norm(c2), 0.2, 1e-12);
    // Every point and segment end point on one plane: the smallest singular value of the centred
    // coordinates is zero to rounding.
    Mat all;
    all.push_back(s.points3d);
    all.push_back(s.lines3d.colRange(0, 3));
    all.push_back(s.lines3d.colRange(3, 6));
    Mat mean;
    reduce(all, mean, 0, REDUCE_AVG);
    Mat centred = all - repeat(mean, all.rows, 1);
    SVD svd(centred, SVD::NO_UV);
    EXPECT_LT(svd.w.at<double>(2), 1e-9 * svd.w.at<double>(0));
    // Tilted 30 degrees from facing view 1: the normal makes that angle with the direction from the
    // cube centre (0, 0, 20) to view 1.
    Mat vt;
    SVD::compute(centred, svd.w, noArray(), vt);
    const Vec3d normal(vt.at<double>(2, 0), vt.at<double>(2, 1), vt.at<double>(2, 2));
    EXPECT_NEAR(std::acos(std::abs(normal[2])) * 180.0 / CV_PI, 30.0, 1e-6);

    params.baseline12 = 0.3;
    EXPECT_THROW(generateSyntheticScene(params), cv::Exception); // both baselines set
    params.baseline12Fraction = 0;
    params.planeTilt = 90;
    EXPECT_THROW(generateSyntheticScene(params), cv::Exception);
}

}} // namespace
