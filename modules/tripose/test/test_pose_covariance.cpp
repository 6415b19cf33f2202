// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The covariance that the refinement reports with a pose (doc/conventions.md, "Pose covariance"):
// that it is the covariance of the maximum-likelihood estimate, checked against first-order error
// propagation by finite differences and against Monte-Carlo draws of the noise; that every entry
// point returns it where documented and releases it where documented.
//
// The Monte-Carlo test takes its size from the environment: TRIPOSE_COVARIANCE_STUDY=SCENESxDRAWS
// (default 20x100, what CI runs, about a second). It prints its table; the full study of
// doc/studies/accuracy.md is
//   TRIPOSE_COVARIANCE_STUDY=20x500 opencv_test_tripose --gtest_filter='*PoseCovariance.*'

#include "test_precomp.hpp"
#include "test_pose_common.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "../src/core/refine/ml_refinement.hpp"
#include "../src/opencv/argument_reading.hpp"

namespace opencv_test {
namespace {

namespace ts = cv::tripose::support;

// The 95 % quantile of the chi-square distribution with 6 degrees of freedom.
const double kChiSquare6At95 = 12.591587243743977;
// Var(chi-square with 6 degrees of freedom) = 12, and the variance of the 95 % indicator.
const double kNeesVariance = 12.0, kCoverageVariance = 0.95 * 0.05;

//! A noise-free problem of the three-view or stereo-rig functions with its ground truth.
struct CovarianceProblem
{
    bool stereo = false;
    std::vector<Mat> points, lines; //!< Per view: Nx2, Mx4 (NaN rows where a view does not see a feature).
    std::vector<Mat> K;
    Mat R12, t12, R, t;
};

struct CovarianceRegime
{
    const char* name;
    bool stereo;
    int motion;
    double baselineFraction;
    int numPoints, numLines;
    double sigma;             //!< Noise (px) of the Monte-Carlo draws; the covariance is scaled by sigma^2.
    bool meetsTarget;         //!< Whether the study asserts the NEES and coverage targets.
};

CovarianceProblem makeProblem(const CovarianceRegime& regime, int seed)
{
    CovarianceProblem p;
    p.stereo = regime.stereo;
    if (regime.stereo)
    {
        ts::SyntheticStereoParams params;
        params.numPoints = regime.numPoints;
        params.numLines = regime.numLines;
        params.seed = 500 + seed;
        const ts::SyntheticStereoScene s = ts::generateSyntheticStereoScene(params);
        p.points = { s.points1, s.points2, s.points3, s.points4 };
        p.lines = { s.lines1, s.lines2, s.lines3, s.lines4 };
        p.K = s.cameraMatrices;
        p.R12 = s.R12, p.t12 = s.t12, p.R = s.R, p.t = s.t;
        return p;
    }
    ts::SyntheticSceneParams params;
    params.numPoints = regime.numPoints;
    params.numLines = regime.numLines;
    params.motion = regime.motion;
    params.baseline12Fraction = regime.baselineFraction;
    params.noiseSigma = 0.0;
    params.seed = 500 + seed;
    const ts::SyntheticScene s = ts::generateSyntheticScene(params);
    p.points = { s.points1, s.points2, s.points3 };
    p.lines = { s.lines1, s.lines2, s.lines3 };
    p.K = s.cameraMatrices;
    p.R12 = s.R12, p.t12 = s.t12, p.R = s.R, p.t = s.t;
    return p;
}

//! @p p with Gaussian noise of @p sigma px on every observed coordinate of every view.
CovarianceProblem addNoise(const CovarianceProblem& p, RNG& rng, double sigma = 1.0)
{
    CovarianceProblem noisy = p;
    for (std::vector<Mat>* observations : { &noisy.points, &noisy.lines })
        for (Mat& m : *observations)
        {
            m = m.clone();
            Mat noise(m.size(), CV_64F);
            rng.fill(noise, RNG::NORMAL, 0.0, sigma);
            m += noise; // NaN rows stay NaN
        }
    return noisy;
}

//! Refines from (R, t) in place; returns the RMS and fills the uncertainty outputs.
double refine(const CovarianceProblem& p, Mat& R, Mat& t, OutputArray covariance, OutputArray noiseVariance)
{
    if (p.stereo)
        return cv::tripose::refinePoseLinePointStereo(
            p.points[0], p.points[1], p.points[2], p.points[3], p.lines[0], p.lines[1], p.lines[2], p.lines[3], p.K,
            noArray(), p.R12, p.t12, R, t, cv::tripose::RefineParams(), noArray(), noArray(), covariance,
            noiseVariance);
    return cv::tripose::refinePoseLinePoint(p.points[0], p.points[1], p.points[2], p.lines[0], p.lines[1], p.lines[2],
                                            p.K, noArray(), p.R12, p.t12, R, t, cv::tripose::RefineParams(), noArray(),
                                            noArray(), covariance, noiseVariance);
}

//! The error of (R, t) in the order and sense of the covariance: [d; t - t_true], R = exp([d]x) R_true.
Vec6d poseErrorVector(const Mat& R, const Mat& t, const CovarianceProblem& truth)
{
    // The logarithm of the rotation, accurate at any small angle: cv::Rodrigues returns a zero
    // vector below 1e-5 rad, which would erase the rotation error of the finite differences.
    const Mat dR = R * truth.R.t();
    const Vec3d axis(dR.at<double>(2, 1) - dR.at<double>(1, 2), dR.at<double>(0, 2) - dR.at<double>(2, 0),
                     dR.at<double>(1, 0) - dR.at<double>(0, 1));
    const double sine = 0.5 * cv::norm(axis), cosine = 0.5 * (trace(dR)[0] - 1.0);
    const double angle = std::atan2(sine, cosine);
    const Vec3d d = axis * (sine > 1e-300 ? 0.5 * angle / sine : 0.5);
    const Mat dt = t - truth.t;
    return Vec6d(d[0], d[1], d[2], dt.at<double>(0), dt.at<double>(1), dt.at<double>(2));
}

struct Consistency
{
    int draws = 0, withoutCovariance = 0;
    double meanNees = 0, medianNees = 0, coverage = 0;
    double meanNoiseVariance = 0; //!< Relative to sigma^2.
};

/** The normalised estimation error squared e^T Sigma^-1 e of the maximum-likelihood estimate over
@p draws noise draws of sigma px on each of @p scenes scenes: the estimate is refinement from the
truth (the maximum-likelihood fit where the cost is near quadratic around it), Sigma the covariance
it reports times sigma^2. */
Consistency measureConsistency(const CovarianceRegime& regime, int scenes, int draws)
{
    Consistency c;
    std::vector<double> nees;
    const double variance = regime.sigma * regime.sigma;
    for (int scene = 0; scene < scenes; ++scene)
    {
        const CovarianceProblem p = makeProblem(regime, scene);
        RNG rng(77 + scene);
        for (int draw = 0; draw < draws; ++draw)
        {
            const CovarianceProblem noisy = addNoise(p, rng, regime.sigma);
            Mat R = p.R.clone(), t = p.t.clone(), covariance, noiseVariance;
            refine(noisy, R, t, covariance, noiseVariance);
            if (covariance.empty())
            {
                ++c.withoutCovariance;
                continue;
            }
            const Mat e(poseErrorVector(R, t, p));
            nees.push_back(Mat(e.t() * Mat(variance * covariance).inv(DECOMP_CHOLESKY) * e).at<double>(0));
            c.meanNees += nees.back();
            c.coverage += nees.back() <= kChiSquare6At95;
            c.meanNoiseVariance += noiseVariance.at<double>(0) / variance;
            ++c.draws;
        }
    }
    if (c.draws > 0)
    {
        c.meanNees /= c.draws;
        c.coverage /= c.draws;
        c.meanNoiseVariance /= c.draws;
        std::nth_element(nees.begin(), nees.begin() + nees.size() / 2, nees.end());
        c.medianNees = nees[nees.size() / 2];
    }
    return c;
}

/** The size of the study, and the noise (px) of the rows that the table runs at 1 px: from
TRIPOSE_COVARIANCE_STUDY=SCENESxDRAWS[xSIGMA], e.g. 20x500 or 20x500x0.1. */
void studySize(int& scenes, int& draws, double& sigma)
{
    // 2000 draws per regime: the whole table in about a second, three standard errors of 0.23 on
    // the mean NEES and 1.5 points on the coverage.
    scenes = 20;
    draws = 100;
    sigma = 1.0;
    const char* size = std::getenv("TRIPOSE_COVARIANCE_STUDY");
    if (size && *size)
        ASSERT_GE(std::sscanf(size, "%dx%dx%lf", &scenes, &draws, &sigma), 2)
            << "TRIPOSE_COVARIANCE_STUDY=SCENESxDRAWS[xSIGMA]";
    ASSERT_GT(scenes, 0);
    ASSERT_GT(draws, 0);
    ASSERT_GT(sigma, 0.0);
}

TEST(Tripose_PoseCovariance, consistent_with_monte_carlo)
{
    // The narrow regime (views 1 and 2 1 % of the scene depth apart) is far from linear at 1 px:
    // the depth of the structure, and with it the pose of view 3, is a reciprocal of a small noisy
    // disparity, and the estimate has heavy tails that no covariance describes (doc/studies/accuracy.md,
    // "Pose covariance"). Its 1 px rows are printed, not held to the targets; at 0.03 px, where the
    // first-order theory applies, it must meet them like the other regimes. A rare 1 px draw there
    // may also end with a line whose structure block is singular to rounding (its eigenvalues
    // spanning 1e20): the refinement then reports no covariance, as documented, and the row counts it.
    const CovarianceRegime regimes[] = {
        { "large", false, ts::MOTION_LARGE, 0.0, 10, 10, 1.0, true },
        { "large", false, ts::MOTION_LARGE, 0.0, 4, 4, 1.0, true },
        { "small", false, ts::MOTION_SMALL, 0.0, 10, 10, 1.0, true },
        { "small", false, ts::MOTION_SMALL, 0.0, 4, 4, 1.0, true },
        { "narrow 1 %", false, ts::MOTION_SMALL, 0.01, 10, 10, 1.0, false },
        { "narrow 1 %", false, ts::MOTION_SMALL, 0.01, 4, 4, 1.0, false },
        { "narrow 1 %", false, ts::MOTION_SMALL, 0.01, 10, 10, 0.03, true },
        { "narrow 1 %", false, ts::MOTION_SMALL, 0.01, 4, 4, 0.03, true },
        { "stereo rig", true, 0, 0.0, 10, 10, 1.0, true },
        { "stereo rig", true, 0, 0.0, 4, 4, 1.0, true },
    };
    int scenes = 0, draws = 0;
    double sigma = 1.0;
    studySize(scenes, draws, sigma);
    std::cout << "Pose covariance against Monte-Carlo, " << scenes << " scenes x " << draws
              << " draws per row (targets: mean NEES 6 +- 0.6, coverage 93-97 %; chi-square(6) median 5.35)\n"
              << "| regime | features | noise (px) | mean NEES | median NEES | 95 % coverage | mean s^2 / sigma^2 "
                 "| no covariance | targets |\n"
              << "|---|---|---|---|---|---|---|---|---|\n";
    for (CovarianceRegime regime : regimes)
    {
        if (regime.sigma == 1.0)
            regime.sigma = sigma;
        const Consistency c = measureConsistency(regime, scenes, draws);
        const std::string what = cv::format("%s %dP+%dL at %g px", regime.name, regime.numPoints, regime.numLines,
                                            regime.sigma);
        // The targets are a mean NEES within 10 % of 6 and a 95 % coverage between 93 and 97 %. A
        // finite sample measures them to within its own error, so each band is the target's
        // tolerance plus three standard errors of the sample (a draw's NEES has variance 12 when the
        // covariance is right, whatever the scene, its coverage indicator 0.95 x 0.05): at CI's
        // 2000 draws 6 +- 0.83 and 95 +- 3.5 %, still far from a covariance off by a factor of two
        // (NEES 3 or 12), with its blocks exchanged or its rotation in another frame.
        const double neesBand = 0.6 + 3 * std::sqrt(kNeesVariance / std::max(c.draws, 1));
        const double coverageBand = 0.02 + 3 * std::sqrt(kCoverageVariance / std::max(c.draws, 1));
        const bool met = std::abs(c.meanNees - 6.0) <= 0.6 && std::abs(c.coverage - 0.95) <= 0.02;
        const bool inBand = std::abs(c.meanNees - 6.0) <= neesBand && std::abs(c.coverage - 0.95) <= coverageBand;
        const char* verdict = met ? "met" : inBand ? "missed within 3 standard errors" : "missed";
        std::cout << "| " << regime.name << " | " << regime.numPoints << "P+" << regime.numLines << "L | "
                  << regime.sigma << " | " << cv::format("%.2f", c.meanNees) << " | "
                  << cv::format("%.2f", c.medianNees) << " | " << cv::format("%.1f %%", 100 * c.coverage) << " | "
                  << cv::format("%.3f", c.meanNoiseVariance) << " | " << c.withoutCovariance << " | " << verdict
                  << (regime.meetsTarget ? "" : " (not asserted)") << " |" << std::endl;
        ASSERT_GT(c.draws, 0) << what;
        if (regime.meetsTarget)
        {
            EXPECT_EQ(c.withoutCovariance, 0) << what;
            EXPECT_NEAR(c.meanNees, 6.0, neesBand) << what;
            EXPECT_NEAR(c.coverage, 0.95, coverageBand) << what;
        }
        // The noise-variance estimate is unbiased to first order, and its mean over the draws
        // (whose standard error is well below 1 %) close to sigma^2 even where the pose is not linear.
        EXPECT_NEAR(c.meanNoiseVariance, 1.0, 0.1) << what;
    }
}

TEST(Tripose_PoseCovarianceCheck, equals_first_order_error_propagation)
{
    // The first-order covariance of the maximum-likelihood estimate for unit noise is A A^T, A the
    // derivative of the estimate with respect to the observations: found here by central
    // differences of the refinement itself, without the normal equations.
    // The narrow regime too: its Monte-Carlo misses at 1 px (the estimate is not linear in the
    // noise there), but its first-order covariance is right.
    const CovarianceRegime regimes[] = { { "large", false, ts::MOTION_LARGE, 0.0, 5, 5 },
                               { "narrow 1 %", false, ts::MOTION_SMALL, 0.01, 5, 5 },
                               { "stereo", true, 0, 0.0, 5, 5 } };
    for (const CovarianceRegime& regime : regimes)
    {
        const CovarianceProblem p = makeProblem(regime, 3);
        Mat R = p.R.clone(), t = p.t.clone(), covariance;
        refine(p, R, t, covariance, noArray());
        ASSERT_EQ(covariance.size(), Size(6, 6));
        ASSERT_EQ(covariance.type(), CV_64F);

        const double h = 1e-3; // px: the estimate is linear in the noise to 1e-6 relative here
        Mat sum = Mat::zeros(6, 6, CV_64F);
        for (size_t kind = 0; kind < 2; ++kind)
            for (size_t v = 0; v < p.points.size(); ++v)
            {
                const Mat& observed = kind == 0 ? p.points[v] : p.lines[v];
                for (int i = 0; i < (int)observed.total(); ++i)
                {
                    if (cvIsNaN(observed.ptr<double>()[i]))
                        continue;
                    Vec6d sides[2];
                    for (int side = 0; side < 2; ++side)
                    {
                        CovarianceProblem moved = p;
                        Mat& m = kind == 0 ? moved.points[v] : moved.lines[v];
                        m = m.clone();
                        m.ptr<double>()[i] += side == 0 ? h : -h;
                        Mat Rm = p.R.clone(), tm = p.t.clone();
                        refine(moved, Rm, tm, noArray(), noArray());
                        sides[side] = poseErrorVector(Rm, tm, p);
                    }
                    const Mat column = Mat(sides[0] - sides[1]) / (2 * h);
                    sum += column * column.t();
                }
            }
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c)
            {
                const double scale = std::sqrt(covariance.at<double>(r, r) * covariance.at<double>(c, c));
                EXPECT_NEAR(sum.at<double>(r, c), covariance.at<double>(r, c), 1e-4 * scale)
                    << regime.name << " entry " << r << "," << c;
            }
    }
}

void expectSymmetricPositiveDefinite(const Mat& covariance, const char* what)
{
    ASSERT_EQ(covariance.size(), Size(6, 6)) << what;
    ASSERT_EQ(covariance.type(), CV_64F) << what;
    EXPECT_LE(cv::norm(covariance, covariance.t(), NORM_INF), 1e-12 * cv::norm(covariance, NORM_INF)) << what;
    Mat eigenvalues;
    eigen(covariance, eigenvalues);
    EXPECT_GT(eigenvalues.at<double>(5), 0.0) << what;
    EXPECT_TRUE(checkRange(covariance)) << what;
}

TEST(Tripose_PoseCovarianceCheck, every_estimator_returns_it_where_documented)
{
    const CovarianceRegime regime = { "large", false, ts::MOTION_LARGE, 0.0, 8, 8 };
    RNG rng(5);
    const CovarianceProblem p = addNoise(makeProblem(regime, 1), rng);
    const std::vector<Mat>& x = p.points;
    const std::vector<Mat>& l = p.lines;

    Mat Rref = p.R.clone(), tref = p.t.clone(), reference, referenceVariance;
    refine(p, Rref, tref, reference, referenceVariance);
    expectSymmetricPositiveDefinite(reference, "refinePoseLinePoint");
    ASSERT_EQ(referenceVariance.size(), Size(1, 1));
    EXPECT_GT(referenceVariance.at<double>(0), 0.2);
    EXPECT_LT(referenceVariance.at<double>(0), 5.0);

    // The estimators reach the same optimum: their covariance is the refinement's.
    Mat R, t, covariance, noiseVariance;
    ASSERT_GT(cv::tripose::estimatePoseLinePoint(x[0], x[1], x[2], l[0], l[1], l[2], p.K, noArray(), p.R12, p.t12, R,
                                                 t, cv::tripose::POSE_LINEAR_REFINE, noArray(), noArray(), noArray(),
                                                 covariance, noiseVariance),
              0);
    expectSymmetricPositiveDefinite(covariance, "POSE_LINEAR_REFINE");
    EXPECT_LE(cv::norm(covariance, reference, NORM_INF), 1e-6 * cv::norm(reference, NORM_INF));
    EXPECT_NEAR(noiseVariance.at<double>(0), referenceVariance.at<double>(0), 1e-6);

    ASSERT_GT(cv::tripose::estimatePoseLinePoint(x[0], x[1], x[2], l[0], l[1], l[2], p.K, noArray(), p.R12, p.t12, R,
                                                 t, cv::tripose::POSE_LINEAR, noArray(), noArray(), noArray(),
                                                 covariance, noiseVariance),
              0);
    EXPECT_TRUE(covariance.empty()) << "a linear estimate has no maximum-likelihood covariance";
    EXPECT_TRUE(noiseVariance.empty());

    cv::tripose::RansacParams ransac;
    ransac.threshold = 4.0;
    ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(x[0], x[1], x[2], l[0], l[1], l[2], p.K, noArray(), p.R12,
                                                       p.t12, R, t, ransac, noArray(), noArray(), noArray(),
                                                       noArray(), noArray(), covariance, noiseVariance),
              0);
    expectSymmetricPositiveDefinite(covariance, "estimatePoseLinePointRansac");
    EXPECT_LE(cv::norm(covariance, reference, NORM_INF), 1e-6 * cv::norm(reference, NORM_INF));

    ransac.refine = false;
    ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(x[0], x[1], x[2], l[0], l[1], l[2], p.K, noArray(), p.R12,
                                                       p.t12, R, t, ransac, noArray(), noArray(), noArray(),
                                                       noArray(), noArray(), covariance, noiseVariance),
              0);
    EXPECT_TRUE(covariance.empty()) << "no refinement, no covariance";
    EXPECT_TRUE(noiseVariance.empty());

    // The same views as a multi-view problem: views 1 and 2 known in the world frame of view 1.
    const std::vector<Mat> Rs = { Mat::eye(3, 3, CV_64F), p.R12 }, tss = { Mat::zeros(3, 1, CV_64F), p.t12 };
    R = p.R.clone();
    t = p.t.clone();
    cv::tripose::refinePoseMultiView(x, l, p.K, noArray(), Rs, tss, R, t, cv::tripose::RefineParams(), noArray(),
                                     noArray(), covariance, noiseVariance);
    EXPECT_LE(cv::norm(covariance, reference, NORM_INF), 1e-6 * cv::norm(reference, NORM_INF));
    ASSERT_GT(cv::tripose::estimatePoseMultiView(x, l, p.K, noArray(), Rs, tss, R, t,
                                                 cv::tripose::POSE_LINEAR_REFINE, noArray(), noArray(), noArray(),
                                                 covariance, noiseVariance),
              0);
    EXPECT_LE(cv::norm(covariance, reference, NORM_INF), 1e-6 * cv::norm(reference, NORM_INF));
    ransac.refine = true;
    ASSERT_GT(cv::tripose::estimatePoseMultiViewRansac(x, l, p.K, noArray(), Rs, tss, R, t, ransac, noArray(),
                                                       noArray(), noArray(), noArray(), noArray(), covariance,
                                                       noiseVariance),
              0);
    EXPECT_LE(cv::norm(covariance, reference, NORM_INF), 1e-6 * cv::norm(reference, NORM_INF));

    // The stereo rig's functions.
    const CovarianceRegime rig = { "stereo", true, 0, 0.0, 8, 8 };
    const CovarianceProblem s = addNoise(makeProblem(rig, 2), rng);
    Mat Rs0 = s.R.clone(), ts0 = s.t.clone(), rigReference;
    refine(s, Rs0, ts0, rigReference, noArray());
    expectSymmetricPositiveDefinite(rigReference, "refinePoseLinePointStereo");
    ASSERT_GT(cv::tripose::estimatePoseLinePointStereo(
                  s.points[0], s.points[1], s.points[2], s.points[3], s.lines[0], s.lines[1], s.lines[2], s.lines[3],
                  s.K, noArray(), s.R12, s.t12, R, t, cv::tripose::POSE_LINEAR_REFINE, noArray(), noArray(), noArray(),
                  covariance, noArray()),
              0);
    EXPECT_LE(cv::norm(covariance, rigReference, NORM_INF), 1e-6 * cv::norm(rigReference, NORM_INF));
    ASSERT_GT(cv::tripose::estimatePoseLinePointStereoRansac(
                  s.points[0], s.points[1], s.points[2], s.points[3], s.lines[0], s.lines[1], s.lines[2], s.lines[3],
                  s.K, noArray(), s.R12, s.t12, R, t, ransac, noArray(), noArray(), noArray(), noArray(), noArray(),
                  covariance, noArray()),
              0);
    EXPECT_LE(cv::norm(covariance, rigReference, NORM_INF), 1e-6 * cv::norm(rigReference, NORM_INF));
}

TEST(Tripose_PoseCovarianceCheck, undetermined_pose_gives_no_covariance)
{
    const CovarianceRegime regime = { "large", false, ts::MOTION_LARGE, 0.0, 4, 0 };
    const CovarianceProblem p = makeProblem(regime, 4);
    const ::tripose::ViewSet views = cv::tripose::detail::readThreeViewInput(
        p.points[0], p.points[1], p.points[2], p.lines[0], p.lines[1], p.lines[2], p.K, noArray(), p.R12, p.t12, 3);
    ::tripose::CameraPose pose;
    for (int r = 0; r < 3; ++r)
    {
        pose.t(r) = p.t.at<double>(r);
        for (int c = 0; c < 3; ++c)
            pose.R(r, c) = p.R.at<double>(r, c);
    }
    // Two points give view 3 four residuals for six pose parameters: the pose is not determined,
    // though the refinement itself runs (their structure is fixed by views 1 and 2).
    const std::vector<int> twoPoints = { 0, 1 }, noLines;
    ::tripose::PoseCovariance uncertainty;
    uncertainty.valid = true;
    const ::tripose::RefinementSummary summary =
        ::tripose::refinePoseAndStructure(views, pose, ::tripose::RefineOptions(), &twoPoints, &noLines, nullptr,
                                          &uncertainty);
    EXPECT_TRUE(std::isfinite(summary.finalRms));
    EXPECT_FALSE(uncertainty.valid);
    EXPECT_TRUE(uncertainty.covariance.allFinite()) << "never NaN, even when not valid";

    // Three points determine it.
    const std::vector<int> threePoints = { 0, 1, 2 };
    ::tripose::refinePoseAndStructure(views, pose, ::tripose::RefineOptions(), &threePoints, &noLines, nullptr,
                                      &uncertainty);
    EXPECT_TRUE(uncertainty.valid);
    EXPECT_TRUE(uncertainty.covariance.allFinite());

    // No feature in the cost (view 3 turned half a turn about its y axis: every point behind it):
    // the public function releases the outputs.
    const Mat halfTurn = Mat(Matx33d(-1, 0, 0, 0, 1, 0, 0, 0, -1));
    Mat R = halfTurn * p.R, t = halfTurn * p.t;
    Mat covariance = Mat::ones(6, 6, CV_64F), noiseVariance = Mat::ones(1, 1, CV_64F);
    const double rms = refine(p, R, t, covariance, noiseVariance);
    EXPECT_TRUE(std::isinf(rms));
    EXPECT_TRUE(covariance.empty());
    EXPECT_TRUE(noiseVariance.empty());
}

}} // namespace
