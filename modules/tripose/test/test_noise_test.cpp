// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

#include "tripose_support/synthetic_stereo_scene.hpp"

#include "../src/opencv/argument_reading.hpp"
#include "../src/core/scoring/noise_test.hpp"
#include "../src/core/scoring/pose_scorer.hpp"

namespace opencv_test {
namespace {

using ::tripose::PoseScorer;
using ::tripose::ViewSet;
using cv::tripose::support::SyntheticStereoScene;

struct PointCounts
{
    int truePassed = 0, trueRejected = 0, wrongPassed = 0, wrongRejected = 0;
};

/** The test of points on rig scenes at their true pose: the points within @p threshold (residuals
re-triangulated from the four views, as the estimator's final inlier test), then judged against
the noise they show. */
PointCounts judgePointsAtTruth(int points, int seeds, double threshold)
{
    PointCounts counts;
    for (int seed = 0; seed < seeds; ++seed)
    {
        const SyntheticStereoScene s =
            cv::tripose::support::generateSyntheticStereoScene(stereoParams(points, 40, 4100 + seed, 1.0, 0.6, 0.0));
        const ViewSet views = cv::tripose::detail::readStereoRigInput(
            s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2, s.lines3, s.lines4, s.cameraMatrices,
            noArray(), s.R12, s.t12, 3);
        const PoseScorer scorer(views, PoseScorer::KnownDepth::Slides);
        std::vector<double> pointResiduals, lineResiduals;
        scorer.refitResiduals(corePose(s.R, s.t), pointResiduals, lineResiduals);
        std::vector<unsigned char> mask(pointResiduals.size());
        for (size_t i = 0; i < mask.size(); ++i)
            mask[i] = pointResiduals[i] < threshold;
        const std::vector<unsigned char> passed = mask;
        ::tripose::rejectPointsAboveNoise(views, threshold, pointResiduals, mask);
        for (size_t i = 0; i < mask.size(); ++i)
        {
            if (!passed[i])
                continue;
            const bool isTrue = s.pointInliers.at<uchar>((int)i) != 0;
            (isTrue ? counts.truePassed : counts.wrongPassed) += 1;
            (isTrue ? counts.trueRejected : counts.wrongRejected) += mask[i] ? 0 : 1;
        }
    }
    return counts;
}

// Wrong rig matches (at least 20 px off at time B, but consistent between its two images) that the
// threshold lets in are far above the 1 px noise the true points show; 99.9 % of true points stay.
TEST(Tripose_NoiseTest, points_above_the_inlier_noise_are_the_wrong_matches)
{
    const PointCounts c = judgePointsAtTruth(100, 300, 4.0);
    std::cout << "[ noise    ] 300 rig scenes 100P+40L, 60 % wrong matches, 4 px: true points rejected "
              << c.trueRejected << "/" << c.truePassed << ", wrong points rejected " << c.wrongRejected << "/"
              << c.wrongPassed << std::endl;
    ASSERT_GT(c.truePassed, 10000);
    ASSERT_GE(c.wrongPassed, 10);
    EXPECT_LE(c.trueRejected, 0.005 * c.truePassed + 1);
    EXPECT_GE(c.wrongRejected, 0.8 * c.wrongPassed);
}

// With a few points the noise is not theirs to tell (fewer than 200 degrees of freedom): the test
// keeps what the threshold kept.
TEST(Tripose_NoiseTest, few_points_keep_the_thresholds_verdict)
{
    const PointCounts c = judgePointsAtTruth(20, 200, 4.0);
    // Wrong points within the threshold that the test, were it to judge, would find far off.
    ASSERT_GE(c.wrongPassed, 5);
    EXPECT_EQ(c.trueRejected + c.wrongRejected, 0);
}

} // namespace
} // namespace opencv_test
