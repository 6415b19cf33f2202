// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test {
namespace {

// (points, lines): the RANSAC sample (2+2), the paper's Fig. 5 sizes (4+4, 5+5) and larger.
typedef tuple<int, int> FeatureCounts;
typedef perf::TestBaseWithParam<FeatureCounts> Tripose_EstimatePoseLinear;

PERF_TEST_P(Tripose_EstimatePoseLinear, estimate,
            testing::Values(FeatureCounts(2, 2), FeatureCounts(4, 4), FeatureCounts(5, 5), FeatureCounts(10, 10),
                            FeatureCounts(45, 45)))
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = get<0>(GetParam());
    params.numLines = get<1>(GetParam());
    params.noiseSigma = 1.0;
    params.seed = 3;
    const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
    Mat R, t;
    int candidates = 0;
    declare.iterations(2000);
    TEST_CYCLE()
    {
        candidates = cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                       s.cameraMatrices, noArray(), s.R12, s.t12, R, t);
    }
    // A time is only meaningful for a call that found a pose.
    ASSERT_GT(candidates, 0);
    ASSERT_EQ(R.size(), Size(3, 3));
    SANITY_CHECK_NOTHING();
}

}} // namespace
