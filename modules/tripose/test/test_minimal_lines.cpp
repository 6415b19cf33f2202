// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <functional>
#include <map>

#include <Eigen/Geometry>

#include "../src/minimal/p1p2l.hpp"
#include "../src/minimal/p2p1l.hpp"
#include "../src/minimal/p3l.hpp"

namespace opencv_test {
namespace {

using tripose::detail::CameraPose;
using tripose::detail::solveP1P2L;
using tripose::detail::solveP2P1L;
using tripose::detail::solveP3L;
using tripose::detail::WorldLine;

// A noise-free instance counts as solved when a returned pose is this close to the true one.
constexpr double kRotationToleranceRad = 1e-6;
constexpr double kRelativeTranslationTolerance = 1e-6;
// Sine of the angle by which a returned pose may miss an input ray or plane: rounding only.
constexpr double kIncidenceTolerance = 1e-8;

CameraPose randomPose(RNG& rng)
{
    CameraPose pose;
    pose.R = Eigen::Quaterniond(rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0), rng.gaussian(1.0))
                 .normalized()
                 .toRotationMatrix();
    pose.t = Eigen::Vector3d(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
    return pose;
}

//! A point in the camera frame in a 90 degree field of view, at depth 2..10.
Eigen::Vector3d randomPointInView(RNG& rng)
{
    return rng.uniform(2.0, 10.0) * Eigen::Vector3d(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), 1.0);
}

Eigen::Vector3d toWorld(const CameraPose& pose, const Eigen::Vector3d& Xc)
{
    return pose.R.transpose() * (Xc - pose.t);
}

//! The calibrated image line through the projections of two camera-frame points, (a, b) unit.
Eigen::Vector3d imageLineThrough(const Eigen::Vector3d& Ac, const Eigen::Vector3d& Bc)
{
    const Eigen::Vector3d l = (Ac / Ac.z()).cross(Bc / Bc.z());
    return l / l.head<2>().norm();
}

struct PointObservation
{
    Eigen::Vector3d bearing; // [x; 1]
    Eigen::Vector3d world;
};

struct LineObservation
{
    Eigen::Vector3d imageLine;
    WorldLine world;
    Eigen::Vector3d ends[2]; // world end points, both in front of the camera
};

PointObservation observePoint(const CameraPose& pose, const Eigen::Vector3d& Xc)
{
    return PointObservation{ Xc / Xc.z(), toWorld(pose, Xc) };
}

LineObservation observeLine(const CameraPose& pose, const Eigen::Vector3d& Ac, const Eigen::Vector3d& Bc)
{
    LineObservation o;
    o.imageLine = imageLineThrough(Ac, Bc);
    o.ends[0] = toWorld(pose, Ac);
    o.ends[1] = toWorld(pose, Bc);
    o.world = WorldLine::throughPoints(o.ends[0], o.ends[1]);
    return o;
}

//! The sine of the angle between the ray of @p o and the point placed by @p pose.
double pointIncidenceSine(const CameraPose& pose, const PointObservation& o)
{
    const Eigen::Vector3d Xc = pose.toCamera(o.world);
    return o.bearing.normalized().cross(Xc.normalized()).norm();
}

//! The largest sine of the angle between the plane of @p o's image line and its end points' rays.
double lineIncidenceSine(const CameraPose& pose, const LineObservation& o)
{
    const Eigen::Vector3d n = o.imageLine.normalized();
    double worst = 0;
    for (const Eigen::Vector3d& end : o.ends)
        worst = std::max(worst, std::abs(n.dot(pose.toCamera(end).normalized())));
    return worst;
}

tripose::support::PoseError errorOf(const CameraPose& p, const CameraPose& truth)
{
    auto matx = [](const Eigen::Matrix3d& R) {
        return Matx33d(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
    };
    return tripose::support::poseError(matx(p.R), Vec3d(p.t.x(), p.t.y(), p.t.z()), matx(truth.R),
                                       Vec3d(truth.t.x(), truth.t.y(), truth.t.z()));
}

//! The returned pose closest to @p truth (rotation first), or false when none was returned.
bool closestPose(const std::vector<CameraPose>& poses, const CameraPose& truth, tripose::support::PoseError& best)
{
    bool any = false;
    for (const CameraPose& p : poses)
    {
        const tripose::support::PoseError e = errorOf(p, truth);
        if (!any || e.rotationDeg + e.relativeTranslation < best.rotationDeg + best.relativeTranslation)
            best = e;
        any = true;
    }
    return any;
}

bool isTruePose(const tripose::support::PoseError& e)
{
    return e.rotationDeg * CV_PI / 180.0 < kRotationToleranceRad &&
           e.relativeTranslation < kRelativeTranslationTolerance;
}

void expectValidRotations(const std::vector<CameraPose>& poses)
{
    for (const CameraPose& p : poses)
    {
        ASSERT_TRUE(p.allFinite());
        EXPECT_LT((p.R * p.R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9);
        EXPECT_GT(p.R.determinant(), 0);
    }
}

//! Success counts of one exact suite, and why the failures failed.
struct SuiteResult
{
    int trials = 0, found = 0, noSolution = 0, notAmongSolutions = 0, maxSolutions = 0;
    double worstMissRotationDeg = 0;
    std::map<int, int> solutionCounts;

    void print(const char* name) const
    {
        std::cout << name << ": true pose found in " << found << " of " << trials << "; failures: " << noSolution
                  << " without any solution, " << notAmongSolutions << " with solutions none within tolerance"
                  << " (the worst of these " << worstMissRotationDeg << " deg off); solutions per instance:";
        for (const auto& c : solutionCounts)
            std::cout << " " << c.first << "x" << c.second;
        std::cout << std::endl;
    }
};

/** Runs @p solve on @p trials random instances made by @p make (which returns the true pose and
fills the observations), checks every returned pose against every observation and counts the
instances whose true pose is among the solutions.
*/
SuiteResult runExactSuite(
    RNG& rng, int trials, int maxSolutions,
    const std::function<CameraPose(RNG&, std::vector<PointObservation>&, std::vector<LineObservation>&)>& make,
    const std::function<int(const std::vector<PointObservation>&, const std::vector<LineObservation>&,
                            std::vector<CameraPose>&)>& solve)
{
    SuiteResult result;
    result.trials = trials;
    for (int trial = 0; trial < trials; ++trial)
    {
        std::vector<PointObservation> points;
        std::vector<LineObservation> lines;
        const CameraPose truth = make(rng, points, lines);
        std::vector<CameraPose> poses;
        const int n = solve(points, lines, poses);
        EXPECT_EQ(n, (int)poses.size());
        EXPECT_LE(n, maxSolutions);
        expectValidRotations(poses);
        for (const CameraPose& p : poses)
        {
            for (const PointObservation& o : points)
            {
                EXPECT_LT(pointIncidenceSine(p, o), kIncidenceTolerance) << "trial " << trial;
                EXPECT_GT(o.bearing.dot(p.toCamera(o.world)), 0) << "trial " << trial;
            }
            for (const LineObservation& o : lines)
                EXPECT_LT(lineIncidenceSine(p, o), kIncidenceTolerance) << "trial " << trial;
        }
        result.solutionCounts[n]++;
        result.maxSolutions = std::max(result.maxSolutions, n);
        tripose::support::PoseError best;
        if (!closestPose(poses, truth, best))
            result.noSolution++;
        else if (isTruePose(best))
            result.found++;
        else
        {
            result.notAmongSolutions++;
            result.worstMissRotationDeg = std::max(result.worstMissRotationDeg, best.rotationDeg);
        }
    }
    return result;
}

CameraPose makeP2P1L(RNG& rng, std::vector<PointObservation>& points, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    for (int i = 0; i < 2; ++i)
        points.push_back(observePoint(truth, randomPointInView(rng)));
    lines.push_back(observeLine(truth, randomPointInView(rng), randomPointInView(rng)));
    return truth;
}

int solveP2P1LObservations(const std::vector<PointObservation>& points, const std::vector<LineObservation>& lines,
                           std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d bearings[2] = { points[0].bearing, points[1].bearing };
    const Eigen::Vector3d worlds[2] = { points[0].world, points[1].world };
    return solveP2P1L(bearings, worlds, lines[0].imageLine, lines[0].world, poses);
}

CameraPose makeP1P2L(RNG& rng, std::vector<PointObservation>& points, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    points.push_back(observePoint(truth, randomPointInView(rng)));
    for (int j = 0; j < 2; ++j)
        lines.push_back(observeLine(truth, randomPointInView(rng), randomPointInView(rng)));
    return truth;
}

int solveP1P2LObservations(const std::vector<PointObservation>& points, const std::vector<LineObservation>& lines,
                           std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d imageLines[2] = { lines[0].imageLine, lines[1].imageLine };
    const WorldLine worlds[2] = { lines[0].world, lines[1].world };
    return solveP1P2L(points[0].bearing, points[0].world, imageLines, worlds, poses);
}

CameraPose makeP3L(RNG& rng, std::vector<PointObservation>&, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    for (int j = 0; j < 3; ++j)
        lines.push_back(observeLine(truth, randomPointInView(rng), randomPointInView(rng)));
    return truth;
}

int solveP3LObservations(const std::vector<PointObservation>&, const std::vector<LineObservation>& lines,
                         std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d imageLines[3] = { lines[0].imageLine, lines[1].imageLine, lines[2].imageLine };
    const WorldLine worlds[3] = { lines[0].world, lines[1].world, lines[2].world };
    return solveP3L(imageLines, worlds, poses);
}

// At least 99.5 % of random noise-free instances must be solved.
void expectHighSuccess(const SuiteResult& r)
{
    EXPECT_GE(r.found * 1000, r.trials * 995) << r.found << " of " << r.trials;
}

TEST(Tripose_MinimalLines, p2p1l_true_pose_among_solutions_noise_free)
{
    RNG rng(2101);
    const SuiteResult r = runExactSuite(rng, 1000, 8, makeP2P1L, solveP2P1LObservations);
    r.print("P2P1L");
    expectHighSuccess(r);
}

TEST(Tripose_MinimalLines, p1p2l_true_pose_among_solutions_noise_free)
{
    RNG rng(1201);
    const SuiteResult r = runExactSuite(rng, 1000, 8, makeP1P2L, solveP1P2LObservations);
    r.print("P1P2L");
    expectHighSuccess(r);
}

TEST(Tripose_MinimalLines, p3l_true_pose_among_solutions_noise_free)
{
    RNG rng(301);
    const SuiteResult r = runExactSuite(rng, 1000, 8, makeP3L, solveP3LObservations);
    r.print("P3L");
    expectHighSuccess(r);
}

} // namespace
} // namespace opencv_test
