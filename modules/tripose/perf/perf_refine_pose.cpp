// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

#include "../src/opencv/opencv_compat.hpp"

#include "../src/core/refine/ml_refinement.hpp"
#include "../src/opencv/argument_reading.hpp"

namespace opencv_test {
namespace {

// (points, lines): a small problem, a typical frame, and the inliers of the robust estimator's
// 1000-point + 400-line target (about 700 + 280).
typedef std::tuple<int, int> FeatureCounts;
typedef perf::TestBaseWithParam<FeatureCounts> Tripose_RefinePose;
typedef perf::TestBaseWithParam<FeatureCounts> Tripose_RefinePoseEngine;

const FeatureCounts kSizes[] = { FeatureCounts(10, 10), FeatureCounts(100, 40), FeatureCounts(700, 280) };

cv::tripose::support::SyntheticScene makeScene(const FeatureCounts& counts)
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = std::get<0>(counts);
    params.numLines = std::get<1>(counts);
    params.noiseSigma = 1.0;
    params.seed = 5;
    return cv::tripose::support::generateSyntheticScene(params);
}

//! A start like the robust estimator's: the truth off by 0.5 degrees and 2 % of |t|.
void startingPose(const cv::tripose::support::SyntheticScene& s, Mat& R, Mat& t)
{
    Mat dR;
    Rodrigues(Vec3d(0.5, -0.5, 0.5) * (0.5 * CV_PI / 180.0 / std::sqrt(0.75)), dR);
    R = dR * s.R;
    t = s.t + Mat(Vec3d(0.02, -0.01, 0.01) * (cv::norm(s.t) / cv::norm(Vec3d(0.02, -0.01, 0.01)) * 0.02));
}

//! The public function: input validation, undistortion and the refinement.
PERF_TEST_P(Tripose_RefinePose, refinePoseLinePoint, testing::ValuesIn(kSizes))
{
    const cv::tripose::support::SyntheticScene s = makeScene(GetParam());
    Mat R0, t0;
    startingPose(s, R0, t0);
    Mat R, t;
    double rms = 0;
    declare.iterations(500);
    TEST_CYCLE()
    {
        R0.copyTo(R);
        t0.copyTo(t);
        rms = cv::tripose::refinePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                     s.cameraMatrices, noArray(), s.R12, s.t12, R, t);
    }
    // +inf when no feature entered the cost (R, t are then returned unchanged).
    ASSERT_TRUE(std::isfinite(rms));
    EXPECT_GT(cv::norm(R, R0, NORM_INF), 0.0) << "the refinement did not move the start";
    SANITY_CHECK_NOTHING();
}

//! The engine alone, as the robust estimator calls it on already parsed data.
PERF_TEST_P(Tripose_RefinePoseEngine, refinePoseAndStructure, testing::ValuesIn(kSizes))
{
    const cv::tripose::support::SyntheticScene s = makeScene(GetParam());
    Mat R0, t0;
    startingPose(s, R0, t0);
    const ::tripose::ViewSet data = cv::tripose::detail::readThreeViewInput(
        s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3, s.cameraMatrices, noArray(), s.R12, s.t12, 3);
    ::tripose::CameraPose start;
    for (int r = 0; r < 3; ++r)
    {
        start.t(r) = t0.at<double>(r);
        for (int c = 0; c < 3; ++c)
            start.R(r, c) = R0.at<double>(r, c);
    }
    ::tripose::RefinementSummary summary;
    declare.iterations(500);
    TEST_CYCLE()
    {
        ::tripose::CameraPose pose = start;
        summary = ::tripose::refinePoseAndStructure(data, pose, ::tripose::RefineOptions());
    }
    std::printf("[ PERFINFO ] %d iterations, RMS %.3f -> %.3f px\n", summary.iterations, summary.initialRms,
                summary.finalRms);
    // The start is 0.5 degrees off: a refinement that works lowers the cost from it.
    ASSERT_TRUE(std::isfinite(summary.finalRms));
    EXPECT_LT(summary.finalRms, summary.initialRms);
    SANITY_CHECK_NOTHING();
}

}} // namespace
