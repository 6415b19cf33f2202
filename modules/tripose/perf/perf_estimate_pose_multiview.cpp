// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

#include "tripose_support/random_draws.hpp"

#include "../src/opencv/opencv_compat.hpp" // Rodrigues: calib3d in OpenCV 4, geometry in 5

namespace opencv_test {
namespace {

using cv::tripose::support::SyntheticMultiViewScene;
using cv::tripose::support::uniformInCube;

//! 1 px of Gaussian noise on every observation and, in the new view, a fraction @p outliers of the
//! points moved 40 px away: a tracker's frame.
void perturb(SyntheticMultiViewScene& s, double outliers)
{
    s.addNoise(1.0, 17);
    Mat& newView = s.points.back();
    for (int i = 0; i < cvRound(outliers * newView.rows); ++i)
        newView.at<double>(i, 0) += 40.0;
}

// (known views, points, lines): registration of a new view, as the tracker does per frame.
typedef tuple<int, int, int> MultiViewCounts;
typedef perf::TestBaseWithParam<MultiViewCounts> Tripose_EstimatePoseMultiView;

PERF_TEST_P(Tripose_EstimatePoseMultiView, estimate, testing::Values(MultiViewCounts(2, 4, 4), MultiViewCounts(4, 20, 20)))
{
    SyntheticMultiViewScene s(get<0>(GetParam()), get<1>(GetParam()), get<2>(GetParam()), 5);
    perturb(s, 0.0);
    Mat R, t;
    int candidates = 0;
    declare.iterations(1000);
    TEST_CYCLE()
    {
        candidates = cv::tripose::estimatePoseMultiView(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, R, t);
    }
    // A time is only meaningful for a call that found a pose.
    ASSERT_GT(candidates, 0);
    ASSERT_EQ(R.size(), Size(3, 3));
    SANITY_CHECK_NOTHING();
}

typedef perf::TestBaseWithParam<MultiViewCounts> Tripose_EstimatePoseMultiViewRansac;

// 30 % of the points wrong in the new view.
PERF_TEST_P(Tripose_EstimatePoseMultiViewRansac, estimate, testing::Values(MultiViewCounts(4, 100, 40)))
{
    SyntheticMultiViewScene s(get<0>(GetParam()), get<1>(GetParam()), get<2>(GetParam()), 5);
    perturb(s, 0.3);
    Mat R, t;
    int inliers = 0;
    declare.iterations(100);
    TEST_CYCLE()
    {
        inliers = cv::tripose::estimatePoseMultiViewRansac(s.points, s.lines, s.K, noArray(), s.Rs, s.ts, R, t);
    }
    // A time is only meaningful for a call that found a pose.
    ASSERT_GT(inliers, 0);
    ASSERT_EQ(R.size(), Size(3, 3));
    SANITY_CHECK_NOTHING();
}

// (views, points, lines): the tracker's local adjustment, two views fixed, the others refined
// together with the structure from poses about 1 degree and 0.2 m off.
typedef perf::TestBaseWithParam<MultiViewCounts> Tripose_RefinePosesMultiView;

PERF_TEST_P(Tripose_RefinePosesMultiView, refine, testing::Values(MultiViewCounts(6, 100, 100)))
{
    SyntheticMultiViewScene s(get<0>(GetParam()) - 1, get<1>(GetParam()), get<2>(GetParam()), 5);
    perturb(s, 0.0);
    std::vector<Mat> Rs, ts;
    RNG rng(4);
    Mat fixed(get<0>(GetParam()), 1, CV_8U, Scalar(0));
    fixed.at<uchar>(0) = fixed.at<uchar>(1) = 1;
    for (int v = 0; v < fixed.rows; ++v)
    {
        Mat rvec;
        Rodrigues(v < fixed.rows - 1 ? s.Rs[v] : Mat(s.R), rvec);
        Mat t = v < fixed.rows - 1 ? s.ts[v].clone() : Mat(s.t).clone();
        if (v >= 2)
        {
            rvec += Mat(uniformInCube(rng, 0.02));
            t += Mat(uniformInCube(rng, 0.2));
        }
        Rs.push_back(rvec);
        ts.push_back(t);
    }
    std::vector<Mat> refinedRs, refinedTs;
    double rms = 0;
    declare.iterations(100);
    TEST_CYCLE()
    {
        // Every cycle from the same start: the poses are refined in place.
        refinedRs.assign(Rs.begin(), Rs.end());
        refinedTs.assign(ts.begin(), ts.end());
        rms = cv::tripose::adjustPosesMultiView(s.points, s.lines, s.K, noArray(), fixed, refinedRs, refinedTs);
    }
    // +inf when no feature entered the cost (the poses are then returned unchanged).
    ASSERT_TRUE(std::isfinite(rms));
    EXPECT_GT(cv::norm(refinedTs.back(), ts.back(), NORM_INF), 0.0) << "the refined view did not move";
    SANITY_CHECK_NOTHING();
}

} // namespace
} // namespace opencv_test
