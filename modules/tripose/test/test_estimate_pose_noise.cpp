// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

// Accuracy of the linear solver under Gaussian pixel noise on the paper's protocol (Sec. IV-A),
// 300 seeded scenes per setting. The reference medians were measured with this code (table in
// doc/studies/accuracy.md); a median over 300 scenes varies by about 7 % between seeds sets, so the
// assertion allows 30 % above the reference: a real regression (a lost factor, a broken
// weighting) moves them by far more.
struct NoiseReference
{
    FeatureMix mix;
    int motion;
    double sigma;
    double medianRotationDeg;
    double medianTranslation; //!< relative
    int minSolved;            //!< scenes (of 300) that must return a pose
};

const NoiseReference kReferences[] = {
    { { 2, 2 }, cv::tripose::support::MOTION_LARGE, 0.5, 1.169, 0.0189, 290 },
    { { 2, 2 }, cv::tripose::support::MOTION_LARGE, 1.0, 2.727, 0.0457, 285 },
    { { 2, 2 }, cv::tripose::support::MOTION_LARGE, 2.0, 6.239, 0.1158, 285 },
    { { 3, 3 }, cv::tripose::support::MOTION_LARGE, 0.5, 0.412, 0.0051, 297 },
    { { 3, 3 }, cv::tripose::support::MOTION_LARGE, 1.0, 0.842, 0.0109, 297 },
    { { 3, 3 }, cv::tripose::support::MOTION_LARGE, 2.0, 2.010, 0.0324, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_LARGE, 0.5, 0.290, 0.0040, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_LARGE, 1.0, 0.583, 0.0084, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_LARGE, 2.0, 1.157, 0.0170, 297 },
    { { 10, 10 }, cv::tripose::support::MOTION_LARGE, 0.5, 0.160, 0.0022, 297 },
    { { 10, 10 }, cv::tripose::support::MOTION_LARGE, 1.0, 0.326, 0.0043, 297 },
    { { 10, 10 }, cv::tripose::support::MOTION_LARGE, 2.0, 0.669, 0.0086, 297 },
    { { 2, 2 }, cv::tripose::support::MOTION_SMALL, 0.5, 1.355, 0.1418, 290 },
    { { 2, 2 }, cv::tripose::support::MOTION_SMALL, 1.0, 3.133, 0.3357, 288 },
    { { 2, 2 }, cv::tripose::support::MOTION_SMALL, 2.0, 6.214, 0.6600, 288 },
    { { 3, 3 }, cv::tripose::support::MOTION_SMALL, 0.5, 0.425, 0.0446, 297 },
    { { 3, 3 }, cv::tripose::support::MOTION_SMALL, 1.0, 0.918, 0.0962, 297 },
    { { 3, 3 }, cv::tripose::support::MOTION_SMALL, 2.0, 2.145, 0.2241, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_SMALL, 0.5, 0.323, 0.0342, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_SMALL, 1.0, 0.679, 0.0722, 297 },
    { { 4, 4 }, cv::tripose::support::MOTION_SMALL, 2.0, 1.435, 0.1563, 296 },
    { { 10, 10 }, cv::tripose::support::MOTION_SMALL, 0.5, 0.169, 0.0164, 297 },
    { { 10, 10 }, cv::tripose::support::MOTION_SMALL, 1.0, 0.373, 0.0374, 297 },
    { { 10, 10 }, cv::tripose::support::MOTION_SMALL, 2.0, 0.878, 0.0943, 296 },
};

typedef testing::TestWithParam<NoiseReference> Tripose_LinearNoise;

TEST_P(Tripose_LinearNoise, median_errors_stay_at_the_measured_level)
{
    const NoiseReference ref = GetParam();
    const int scenes = 300;
    std::vector<double> rotation, translation;
    int solved = 0;
    double meanRotation = 0, meanTranslation = 0;
    for (int seed = 0; seed < scenes; ++seed)
    {
        const cv::tripose::support::SyntheticScene s = makeScene(ref.mix, ref.motion, ref.sigma, seed);
        std::vector<Mat> Rs, ts;
        Mat R, t;
        if (solveScene(s, Rs, ts, R, t) == 0)
        {
            // No pose counts as the worst possible error in the medians.
            rotation.push_back(180.0);
            translation.push_back(std::numeric_limits<double>::infinity());
            continue;
        }
        ++solved;
        const PoseError e = poseError(R, t, s.R, s.t);
        rotation.push_back(e.rotationDeg);
        translation.push_back(e.relativeTranslation);
        meanRotation += rotation.back();
        meanTranslation += translation.back();
    }
    const double medianRotation = median(rotation), medianTranslation = median(translation);
    std::cout << mixName(ref.mix) << (ref.motion == cv::tripose::support::MOTION_LARGE ? " large" : " small") << " sigma "
              << ref.sigma << ": median rotation " << medianRotation << " deg (mean " << meanRotation / std::max(solved, 1)
              << "), median translation " << medianTranslation << " (mean " << meanTranslation / std::max(solved, 1)
              << "), solved " << solved << "/" << scenes << std::endl;
    EXPECT_LE(medianRotation, 1.3 * ref.medianRotationDeg);
    EXPECT_LE(medianTranslation, 1.3 * ref.medianTranslation);
    EXPECT_GE(solved, ref.minSolved);
}

INSTANTIATE_TEST_CASE_P(/**/, Tripose_LinearNoise, testing::ValuesIn(kReferences));

// Noisy planar structure, large motion (the facade case): image noise makes the structure of views
// 1-2 slightly thick, and the general combinations then misread a kernel that is nearly as wide as
// the exactly planar one; the planar closed form, tried beside them, gives the pose. The references
// are the median over these 300 scenes and half as many gross errors (no pose, or more than 10
// degrees) again as they have (doc/studies/accuracy.md, "Noisy planar structure", gives the figures and
// those without the closed form, several times as many gross errors); the median may be 30 %
// higher. Losing the closed form breaks both bounds by far.
struct PlanarNoiseReference
{
    FeatureMix mix;
    double medianRotationDeg;
    int maxGross;
};

typedef testing::TestWithParam<PlanarNoiseReference> Tripose_LinearPlanarNoise;

TEST_P(Tripose_LinearPlanarNoise, near_planar_structure_keeps_the_planar_closed_form)
{
    const PlanarNoiseReference ref = GetParam();
    std::vector<double> rotation;
    int gross = 0;
    for (int seed = 0; seed < 300; ++seed)
    {
        cv::tripose::support::SyntheticSceneParams params = sceneParams(ref.mix, cv::tripose::support::MOTION_LARGE, 1.0, seed);
        params.planar = true;
        const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
        std::vector<Mat> Rs, ts;
        Mat R, t;
        const double error = solveScene(s, Rs, ts, R, t) > 0 ? poseError(R, t, s.R, s.t).rotationDeg : 180.0;
        rotation.push_back(error);
        gross += error > 10.0 ? 1 : 0;
    }
    const double medianRotation = median(rotation);
    std::cout << mixName(ref.mix) << " planar large sigma 1: median rotation " << medianRotation << " deg, "
              << gross << "/300 gross" << std::endl;
    EXPECT_LE(medianRotation, 1.3 * ref.medianRotationDeg);
    EXPECT_LE(gross, ref.maxGross);
}

const PlanarNoiseReference kPlanarReferences[] = { { { 4, 4 }, 0.823, 17 }, { { 10, 10 }, 0.469, 17 } };

INSTANTIATE_TEST_CASE_P(/**/, Tripose_LinearPlanarNoise, testing::ValuesIn(kPlanarReferences));

}} // namespace
