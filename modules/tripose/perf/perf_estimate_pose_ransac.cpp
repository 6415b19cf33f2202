// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test {
namespace {

// (points, lines, outlier ratio): the accuracy test's size, and the speed target of 1000 points
// + 400 lines with half of them wrong matches in view 3. End to end: sampling, local optimisation
// and the final refinement over the three views.
typedef tuple<int, int, double> RansacCase;
typedef perf::TestBaseWithParam<RansacCase> Tripose_EstimatePoseRansac;

PERF_TEST_P(Tripose_EstimatePoseRansac, estimate,
            testing::Values(RansacCase(100, 40, 0.5), RansacCase(1000, 400, 0.0), RansacCase(1000, 400, 0.5)))
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = get<0>(GetParam());
    params.numLines = get<1>(GetParam());
    params.outlierRatio = get<2>(GetParam());
    params.noiseSigma = 1.0;
    params.seed = 3;
    const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
    cv::tripose::RansacParams ransac; // default: threshold 2 px, confidence 0.999, refinement on, seed 0
    Mat R, t, pointMask, lineMask;
    int inliers = 0;
    declare.iterations(100);
    TEST_CYCLE()
    {
        inliers = cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                             s.cameraMatrices, noArray(), s.R12, s.t12, R, t, ransac, pointMask,
                                             lineMask);
    }
    // A time is only meaningful for a call that found a pose.
    ASSERT_GT(inliers, 0);
    ASSERT_EQ(R.size(), Size(3, 3));
    SANITY_CHECK_NOTHING();
}

}} // namespace
