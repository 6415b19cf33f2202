// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// With a narrow known pair the three-view maximum-likelihood cost has several minima, and the
// minimum refinement reaches from the true pose is not always the lowest: the measure of an
// estimator there is the cost. A reference search, independent of the estimators (maximum-likelihood
// refinement from ten starts: the truth, the truth moved by several degrees and tens of percent of
// its translation, and the linear solver's best candidates), gives the lowest minimum it finds; an
// estimate reaches it when refinement from the estimate ends at that cost (or lower). The test asks
// for 97 % of the scenes, for POSE_LINEAR_REFINE and for the RANSAC: every scene of 30 or fewer.
//
// CI runs seeds 0-4 of each regime and, at 4P+4L, the seeds of 0-99 where an estimator missed the
// lowest minimum before the search settled its minima (each miss of a different kind), every
// scene asserted; at 100P+40L five scenes the RANSAC missed before large sets were searched. The full check (100 scenes per regime from seed S; another mix with
// TRIPOSE_NARROW_MIX="P L") is
//
//     TRIPOSE_NARROW_STUDY=100 TRIPOSE_NARROW_FIRST_SEED=S build/modules/tripose/opencv_test_tripose \
//         --gtest_filter='Regimes/*NarrowMinima*'
//
// reported in doc/studies/accuracy.md, "Narrow known baselines: the lowest minimum".

#include <cstdio>
#include <cstdlib>

#include <Eigen/Geometry>

#include "test_pose_common.hpp"
#include "test_scene_views.hpp"

#include "../src/core/linear/linear_pose_solver.hpp"
#include "../src/core/pipeline/pose_pipelines.hpp"
#include "../src/core/refine/distinct_minima.hpp"
#include "../src/core/refine/hypothesis_starts.hpp"
#include "../src/core/refine/multi_start_refinement.hpp"

namespace opencv_test {
namespace {

namespace ts = cv::tripose::support;
using ::tripose::CameraPose;
using ::tripose::LocalMinimum;
using ::tripose::ViewSet;

// The reference refinements run to convergence: in a narrow scene the cost creeps along a valley for
// tens of iterations (doc/studies/accuracy.md), and the default 30 could stop short of the minimum.
const int kReferenceIterations = 300;
/** Two refinements reach the same cost when their sums of squares agree within this fraction.
Convergence leaves about 1e-9 of the cost (the stopping tolerance is 1e-10 per step); distinct
minima of these scenes lie 1e-2 or more apart (the smallest gap is printed by the study). */
const double kSameCost = 1e-4;
/** Minima whose rotations differ by less than this (Frobenius norm of the difference, about the angle
in radians times 1.4) are one minimum reached twice, as in the estimators' report (the study prints
the spread of one minimum reached from several starts and the distance of distinct ones). */
const double kDistinctRotation = 1e-3;

struct NarrowRegime
{
    const char* name;
    double baselineFraction;
    int points, lines;
    //! The seeds CI runs.
    std::vector<int> ciSeeds;
};

void PrintTo(const NarrowRegime& r, std::ostream* os)
{
    *os << r.name << " " << r.points << "P+" << r.lines << "L";
}

::tripose::RefineOptions referenceOptions()
{
    ::tripose::RefineOptions o;
    o.maxIterations = kReferenceIterations;
    return o;
}

//! Sum of squared residuals of a minimum: the cost the estimators minimise.
double squares(const LocalMinimum& m)
{
    return m.squares();
}

/** The lowest minimum of the reference search: the truth; the truth turned by 2 to 15 degrees about
random axes, its translation moved by 10 to 50 % of its norm; the linear solver's three best
candidates (more perturbed starts when it has fewer). None of them is an estimator's answer. */
LocalMinimum referenceMinimum(const ts::SyntheticScene& s, const ViewSet& views, int seed,
                              std::vector<LocalMinimum>* minima = nullptr)
{
    std::vector<CameraPose> starts(1, corePose(s.R, s.t));
    const ::tripose::LinearPoseSolver linear(views);
    const std::vector<::tripose::ScoredPose> ranked = ::tripose::estimateCandidates(views, linear, false);
    for (size_t i = 0; i < ranked.size() && i < 3; ++i)
        starts.push_back(ranked[i].pose);
    static const double kDegrees[] = { 2, 5, 5, 10, 10, 15, 15, 20, 20 };
    static const double kFractions[] = { 0.1, 0.2, 0.3, 0.3, 0.5, 0.5, 0.3, 0.5, 0.2 };
    RNG rng(7919 * (uint64)seed + 17);
    for (int k = 0; starts.size() < 10; ++k)
    {
        Mat R, t;
        perturbPose(s.R, s.t, kDegrees[k], kFractions[k], rng, R, t);
        starts.push_back(corePose(R, t));
    }
    if (std::getenv("TRIPOSE_NARROW_VERBOSE"))
    {
        std::cout << "  seed " << seed << " starts' costs (truth, linear, perturbed):";
        for (const CameraPose& start : starts)
        {
            const LocalMinimum m = ::tripose::refineRetriangulating(views, start, referenceOptions());
            std::cout << " " << m.squares() << "/" << m.used;
        }
        std::cout << std::endl;
    }
    return ::tripose::refineFromStarts(views, starts, referenceOptions(), nullptr, nullptr, minima);
}

//! The minimum that refinement from an estimator's pose ends in.
LocalMinimum minimumFrom(const ViewSet& views, const Mat& R, const Mat& t)
{
    return ::tripose::refineRetriangulating(views, corePose(R, t), referenceOptions());
}

//! True when @p m is at @p reference's cost or below it, using as many features.
bool reaches(const LocalMinimum& m, const LocalMinimum& reference)
{
    if (!m.finite())
        return false;
    if (m.used != reference.used)
        return m.used > reference.used;
    return squares(m) <= squares(reference) * (1 + kSameCost);
}

int studySize()
{
    const char* size = std::getenv("TRIPOSE_NARROW_STUDY");
    return size ? std::atoi(size) : 0;
}

//! First seed of the study (TRIPOSE_NARROW_FIRST_SEED, default 0): other seed sets than the CI's.
int firstSeed()
{
    const char* first = std::getenv("TRIPOSE_NARROW_FIRST_SEED");
    return first ? std::atoi(first) : 0;
}

typedef testing::TestWithParam<NarrowRegime> Tripose_NarrowMinima;

TEST_P(Tripose_NarrowMinima, estimators_return_the_lowest_minimum)
{
    NarrowRegime regime = GetParam();
    // TRIPOSE_NARROW_MIX="P L" studies another mix of points and lines at the regime's baseline.
    if (const char* mix = std::getenv("TRIPOSE_NARROW_MIX"))
        if (std::sscanf(mix, "%d %d", &regime.points, &regime.lines) != 2)
            FAIL() << "TRIPOSE_NARROW_MIX: two numbers, points and lines";
    std::vector<int> seeds = regime.ciSeeds;
    if (studySize() > 0)
    {
        seeds.clear();
        for (int k = 0; k < studySize(); ++k)
            seeds.push_back(firstSeed() + k);
    }
    const int scenes = (int)seeds.size();
    int linearReached = 0, ransacReached = 0, truthIsLowest = 0;
    std::vector<int> linearMissed, ransacMissed;
    double smallestGap = std::numeric_limits<double>::infinity(), closestDistinct = smallestGap, widestSame = 0;
    for (int seed : seeds)
    {
        ts::SyntheticSceneParams params;
        params.numPoints = regime.points;
        params.numLines = regime.lines;
        params.motion = ts::MOTION_SMALL;
        params.baseline12Fraction = regime.baselineFraction;
        params.noiseSigma = 1.0;
        params.seed = seed;
        const ts::SyntheticScene s = generateSyntheticScene(params);
        const ViewSet views = readScene(s);
        std::vector<LocalMinimum> minima;
        const LocalMinimum lowest = referenceMinimum(s, views, seed, &minima);
        ASSERT_TRUE(lowest.finite()) << "seed " << seed;
        truthIsLowest += reaches(minima.front(), lowest);
        for (size_t i = 0; i < minima.size(); ++i)
        {
            const double gap = squares(minima[i]) / squares(lowest) - 1;
            if (minima[i].used == lowest.used && gap > kSameCost)
                smallestGap = std::min(smallestGap, gap);
            // How far apart the refinements put one minimum reached twice, and distinct ones.
            for (size_t j = 0; j < i; ++j)
            {
                if (minima[i].used != minima[j].used)
                    continue;
                const double apart = (minima[i].pose.R - minima[j].pose.R).norm();
                const double costs = std::abs(squares(minima[i]) / squares(minima[j]) - 1);
                if (costs < 1e-6)
                    widestSame = std::max(widestSame, apart);
                else if (costs > kSameCost)
                    closestDistinct = std::min(closestDistinct, apart);
            }
        }

        // Prints where a missed estimate ended (TRIPOSE_NARROW_VERBOSE): a study aid.
        const auto explain = [&](const char* estimator, const Mat& R, const Mat& t) {
            if (R.empty() || !std::getenv("TRIPOSE_NARROW_VERBOSE"))
                return;
            const LocalMinimum m = minimumFrom(views, R, t);
            std::cout << "  " << estimator << " seed " << seed << ": cost " << m.squares() << " (used " << m.used
                      << ") against " << lowest.squares() << " (used " << lowest.used << "), "
                      << degrees(Eigen::AngleAxisd(Eigen::Matrix3d(m.pose.R * lowest.pose.R.transpose())).angle())
                      << " deg from the lowest; truth " << poseError(R, t, s.R, s.t).rotationDeg << " deg"
                      << std::endl;
        };
        // Study aid (TRIPOSE_NARROW_VERBOSE): the minima of POSE_LINEAR_REFINE's search, each with its
        // cost at the search's iterations and refined to convergence.
        const auto searchMinima = [&]() {
            const ::tripose::LinearPoseSolver linear(views);
            const std::vector<::tripose::ScoredPose> ranked = ::tripose::estimateCandidates(views, linear, false);
            std::vector<CameraPose> starts;
            for (const ::tripose::ScoredPose& c : ranked)
                starts.push_back(c.pose);
            const size_t linearStarts = starts.size();
            ::tripose::appendHypothesisStarts(views, linear, ::tripose::FeatureSubset::all(views.numPoints, views.numLines),
                                              starts);
            std::vector<LocalMinimum> found;
            ::tripose::searchBasins(views, starts, ::tripose::RefineOptions(), nullptr, nullptr, &found);
            const std::vector<LocalMinimum> distinct = ::tripose::distinctMinima(found, kDistinctRotation);
            std::cout << "    search: " << linearStarts << " linear + " << starts.size() - linearStarts
                      << " hypothesis starts, " << found.size() << " minima, " << distinct.size() << " distinct:";
            for (const LocalMinimum& m : distinct)
            {
                const LocalMinimum c = ::tripose::refineRetriangulating(views, m.pose, referenceOptions());
                std::cout << " " << m.squares() << "/" << m.used << "->" << c.squares() << "/" << c.used
                          << (reaches(c, lowest) ? "*" : "");
            }
            std::cout << std::endl;
        };
        Mat R, t;
        if (cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                               s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                               cv::tripose::POSE_LINEAR_REFINE) > 0 &&
            reaches(minimumFrom(views, R, t), lowest))
            ++linearReached;
        else
        {
            linearMissed.push_back(seed);
            explain("linear + refine", R, t);
            if (std::getenv("TRIPOSE_NARROW_VERBOSE"))
                searchMinima();
        }

        cv::tripose::RansacParams ransac;
        ransac.threshold = 4.0;
        ransac.minInliers = 0; // a few features, all right: no floor on the inliers above them
        R.release();
        t.release();
        if (cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                     s.cameraMatrices, noArray(), s.R12, s.t12, R, t, ransac) > 0 &&
            reaches(minimumFrom(views, R, t), lowest))
            ++ransacReached;
        else
        {
            ransacMissed.push_back(seed);
            explain("RANSAC", R, t);
            if (std::getenv("TRIPOSE_NARROW_VERBOSE"))
                searchMinima();
        }
    }
    std::cout << regime.name << " " << regime.points << "P+" << regime.lines << "L, 1 px, " << scenes
              << " scenes: lowest minimum reached by linear + refine " << linearReached << ", RANSAC "
              << ransacReached << "; by refinement from the truth " << truthIsLowest
              << "; smallest gap to another minimum " << smallestGap << " of the cost" << std::endl;
    std::cout << "  rotations (Frobenius) of one minimum reached twice up to " << widestSame
              << " apart, of distinct minima at least " << closestDistinct << std::endl;
    std::cout << "  missed (seeds): linear + refine";
    for (int seed : linearMissed)
        std::cout << " " << seed;
    std::cout << "; RANSAC";
    for (int seed : ransacMissed)
        std::cout << " " << seed;
    std::cout << std::endl;
    // 97 % of the scenes, rounded up: every scene of 30 or fewer.
    const int required = (97 * scenes + 99) / 100;
    EXPECT_GE(linearReached, required);
    EXPECT_GE(ransacReached, required);
}

INSTANTIATE_TEST_CASE_P(Regimes, Tripose_NarrowMinima,
    // Missed before (seeds 0-99): at 1 %, 20 and 80 (linear + refine: a minimum below the lowest at 30
    // iterations, one that drops a line when refined further) and 67 (RANSAC); at 0.5 %, 16 (both: a
    // line behind a view), 29 and 55 (RANSAC: the choice between its two settlings, the starts around
    // its pose alone), 44 (linear + refine: no candidate), 61 (both: the lowest stopped at 3.2 times
    // the best cost at 30 iterations).
    // 100P+40L: the RANSAC missed 20, 23, 27, 29 and 31 when sets over 60 features were refined once
    // from its pose (the basin of its samples).
    testing::Values(NarrowRegime{ "narrow 1 %", 0.01, 4, 4, { 0, 1, 2, 3, 4, 20, 67, 80 } },
                    NarrowRegime{ "narrow 0.5 %", 0.005, 4, 4, { 0, 1, 2, 3, 4, 16, 29, 44, 55, 61 } },
                    NarrowRegime{ "narrow 1 %", 0.01, 10, 10, { 0, 1, 2, 3, 4 } },
                    NarrowRegime{ "narrow 1 %", 0.01, 100, 40, { 20, 23, 27, 29, 31 } }));

/** The report of several minima. Where the reference search finds a second distinct minimum
clearly within the noise of the lowest (its cost gap below half the bound of
refine/distinct_minima.hpp), the RANSAC lists it (candidateRs has two entries or more) and
POSE_LINEAR_REFINE ranks a second candidate within the bound. Whatever the RANSAC lists besides its
pose is a minimum of the cost (refinement from it stays at its cost) within the bound. With a wide
baseline the RANSAC lists its pose alone. */
TEST(Tripose_NarrowMinima, several_minima_within_the_noise_are_reported)
{
    // The aggregate bounds below hold on the first three seeds too (two of them are ambiguous), the
    // reduced suite's prefix.
    const int scenes = studySize() > 0 ? studySize() : scenesToRun(12);
    int clearlyAmbiguous = 0, reportedByRansac = 0, reportedByMultiView = 0, reportedByLinear = 0, listed = 0,
        confirmedMinima = 0;
    for (int seed = 0; seed < scenes; ++seed)
    {
        ts::SyntheticSceneParams params;
        params.numPoints = 4;
        params.numLines = 4;
        params.motion = ts::MOTION_SMALL;
        params.baseline12Fraction = 0.005;
        params.noiseSigma = 1.0;
        params.seed = seed;
        const ts::SyntheticScene s = generateSyntheticScene(params);
        const ViewSet views = readScene(s);
        std::vector<LocalMinimum> all;
        referenceMinimum(s, views, seed, &all);
        const std::vector<LocalMinimum> ranked = ::tripose::distinctMinima(all, kDistinctRotation);
        ASSERT_FALSE(ranked.empty());
        const double bound = ::tripose::kChiSquare6Quantile95 * ranked[0].noiseVariance();
        const bool ambiguous = ranked.size() > 1 && ranked[1].squares() - ranked[0].squares() < 0.5 * bound;

        cv::tripose::RansacParams ransac;
        ransac.threshold = 4.0;
        ransac.minInliers = 0; // a few features, all right: no floor on the inliers above them
        Mat R, t, inlierPoints, inlierLines;
        std::vector<Mat> Rs, ts_;
        Mat rms;
        ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                           s.lines3, s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                                           ransac, inlierPoints, inlierLines, Rs, ts_, rms),
                  0);
        ASSERT_GE(Rs.size(), 1u);
        ASSERT_EQ(Rs.size(), ts_.size());
        ASSERT_EQ((int)Rs.size(), rms.rows);
        EXPECT_EQ(0, cv::norm(Rs[0], R, NORM_INF));
        EXPECT_EQ(0, cv::norm(ts_[0], t, NORM_INF));
        const bool allInliers = countNonZero(inlierPoints) == params.numPoints && countNonZero(inlierLines) == params.numLines;
        if (allInliers && Rs.size() > 1)
        {
            // Each listed minimum is one: refinement from it keeps its cost, within the bound of the
            // first's, apart from the first. (A few sit in valleys so flat that 300 iterations
            // still move them: counted, not asserted one by one.)
            const LocalMinimum first = minimumFrom(views, Rs[0], ts_[0]);
            for (size_t k = 1; k < Rs.size(); ++k)
            {
                const LocalMinimum other = minimumFrom(views, Rs[k], ts_[k]);
                const bool confirmed =
                    std::abs(other.rms - rms.at<double>((int)k)) <= 1e-3 * rms.at<double>((int)k) &&
                    other.squares() - first.squares() <
                        ::tripose::kChiSquare6Quantile95 * first.noiseVariance() * (1 + kSameCost) &&
                    (other.pose.R - first.pose.R).norm() > kDistinctRotation;
                ++listed;
                if (confirmed)
                    ++confirmedMinima;
                else
                    std::cout << "  seed " << seed << ": listed minimum " << k << " (RMS " << rms.at<double>((int)k)
                              << ") refines to RMS " << other.rms << ", "
                              << (other.pose.R - first.pose.R).norm() << " from the first" << std::endl;
            }
        }
        // The same problem as two known views and a new one: the multi-view RANSAC reports its
        // minima likewise, its pose first.
        const std::vector<Mat> points = { s.points1, s.points2, s.points3 }, lines = { s.lines1, s.lines2, s.lines3 };
        const std::vector<Mat> knownRs = { Mat::eye(3, 3, CV_64F), s.R12 }, knownTs = { Mat::zeros(3, 1, CV_64F), s.t12 };
        Mat Rm, tm, rmsMultiView;
        std::vector<Mat> RsMultiView, tsMultiView;
        ASSERT_GT(cv::tripose::estimatePoseMultiViewRansac(points, lines, s.cameraMatrices, noArray(), knownRs, knownTs,
                                                           Rm, tm, ransac, noArray(), noArray(), RsMultiView,
                                                           tsMultiView, rmsMultiView),
                  0);
        ASSERT_GE(RsMultiView.size(), 1u);
        ASSERT_EQ(RsMultiView.size(), tsMultiView.size());
        ASSERT_EQ((int)RsMultiView.size(), rmsMultiView.rows);
        EXPECT_EQ(0, cv::norm(RsMultiView[0], Rm, NORM_INF));
        EXPECT_EQ(0, cv::norm(tsMultiView[0], tm, NORM_INF));
        if (!ambiguous)
            continue;
        ++clearlyAmbiguous;
        reportedByRansac += Rs.size() > 1;
        reportedByMultiView += RsMultiView.size() > 1;

        std::vector<Mat> candidateRs, candidateTs;
        Mat errors, variance;
        R.release();
        t.release();
        cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                           s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                           cv::tripose::POSE_LINEAR_REFINE, candidateRs, candidateTs, errors);
        // The candidates' costs from their RMS over the same residuals as the reference's.
        // A candidate within the noise of the first counts only if it is another minimum: refinement
        // reaches one minimum from several candidates, 1e-7 to 1e-6 apart (the RANSAC's report merges
        // minima within 1e-3, as here).
        const int n = ranked[0].residuals;
        bool reported = false;
        for (int k = 1; k < errors.rows && !reported; ++k)
            reported = n * (errors.at<double>(k) * errors.at<double>(k) - errors.at<double>(0) * errors.at<double>(0)) < bound &&
                       cv::norm(candidateRs[k] - candidateRs[0]) > 1e-3;
        reportedByLinear += reported;
    }
    std::cout << "narrow 0.5 % 4P+4L, " << scenes << " scenes: a second minimum clearly within the noise in "
              << clearlyAmbiguous << "; reported by the RANSAC in " << reportedByRansac << ", by the multi-view RANSAC in "
              << reportedByMultiView << ", by linear + refine in " << reportedByLinear << "; other minima listed by the RANSAC: " << listed
              << ", confirmed by further refinement: " << confirmedMinima << std::endl;
    // Not vacuous: the sample holds such scenes (half of them at 0.5 %, 4P+4L).
    EXPECT_GE(clearlyAmbiguous, 2);
    // Where the RANSAC stops in another minimum (at most 3 % of the scenes, the test above) it may
    // not see the second one: 90 % of the ambiguous scenes, rounded down.
    EXPECT_GE(reportedByRansac, 9 * clearlyAmbiguous / 10);
    EXPECT_GE(reportedByMultiView, 9 * clearlyAmbiguous / 10);
    EXPECT_GE(reportedByLinear, 9 * clearlyAmbiguous / 10);
    // 95 % of what is listed holds up under further refinement.
    EXPECT_GT(listed, 0);
    EXPECT_GE(20 * confirmedMinima, 19 * listed);

    // A wide baseline (the paper's small motion) has one basin: the RANSAC, three-view or multi-view,
    // lists its pose alone.
    for (int seed = 0; seed < 5; ++seed)
    {
        ts::SyntheticSceneParams params;
        params.numPoints = 10;
        params.numLines = 10;
        params.motion = ts::MOTION_SMALL;
        params.noiseSigma = 1.0;
        params.seed = seed;
        const ts::SyntheticScene s = generateSyntheticScene(params);
        cv::tripose::RansacParams ransac;
        ransac.threshold = 4.0;
        ransac.minInliers = 0; // a few features, all right: no floor on the inliers above them
        Mat R, t;
        std::vector<Mat> Rs, ts_;
        ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                           s.lines3, s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                                           ransac, noArray(), noArray(), Rs, ts_),
                  0);
        EXPECT_EQ(1u, Rs.size()) << "seed " << seed;
        const std::vector<Mat> points = { s.points1, s.points2, s.points3 }, lines = { s.lines1, s.lines2, s.lines3 };
        const std::vector<Mat> knownRs = { Mat::eye(3, 3, CV_64F), s.R12 }, knownTs = { Mat::zeros(3, 1, CV_64F), s.t12 };
        ASSERT_GT(cv::tripose::estimatePoseMultiViewRansac(points, lines, s.cameraMatrices, noArray(), knownRs, knownTs,
                                                           R, t, ransac, noArray(), noArray(), Rs, ts_),
                  0);
        EXPECT_EQ(1u, Rs.size()) << "seed " << seed << ", multi-view";
    }
}

}} // namespace
