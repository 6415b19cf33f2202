// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"
#include "../support/random.hpp"

#include "../geometry/conditioning.hpp"
#include "../geometry/feature_refit.hpp"
#include "../geometry/residuals.hpp"
#include "../geometry/segment_cheirality.hpp"
#include "../geometry/triangulation.hpp"
#include "pose_scorer.hpp"

namespace tripose {

namespace {

// A slide divides an inverse depth by at most this much (10 times the depth): the feature stays
// in front of the first known view, well short of infinity.
constexpr double kMinInverseDepthShare = 0.1;
// The end points of a line slide together only where their two depths are pinned down: the
// 2x2 system of the slide is solved when det / trace^2 exceeds this.
constexpr double kSlideConditioning = 1e-10;
// Gauss-Newton steps of a slide: a feature that a short known baseline leaves loose in depth may
// move by a large part of it, where one linearisation of the projection falls short.
constexpr int kSlideIterations = 2;
// An observation whose residual without the slide is within this share of the inlier bound is
// scored as it is: the slide could only lower a cost that already counts it an inlier.
constexpr double kSettledShare = 0.25;
// Seed of the sequential test's order of the observations (any: the order is fixed per scorer).
constexpr uint64_t kTestOrderSeed = 0x5851F42D4C957F2Dull;

/** Moment, in a camera, of the line through the points at inverse depths rho on two rays from one
origin (e: the origin in the camera; fA, fB: the rays' directions rotated into it), times
rhoA rhoB: (rhoA e + fA) x (rhoB e + fB) = rhoA (e x fB) + rhoB (fA x e) + fA x fB, linear in rho. */
Eigen::Vector3d slidMoment(const Eigen::Vector3d& e, const Eigen::Vector3d& fA, const Eigen::Vector3d& fB,
                           const Eigen::Vector2d& rho)
{
    return rho(0) * e.cross(fB) + rho(1) * fA.cross(e) + fA.cross(fB);
}

} // namespace

double PoseScore::rms() const
{
    return residuals > 0 ? std::sqrt(sumSquares / residuals) : std::numeric_limits<double>::infinity();
}

PoseScorer::PoseScorer(const ViewSet& set, KnownDepth depth)
    : set_(set), slides_(depth == KnownDepth::Slides), minDepth_(1e-9 * set.knownBaseline())
{
    triangulateKnown();
    // A feature's slide is the same for every estimated view: computed once.
    std::vector<KnownSlide<1>> pointSlides(slides_ ? set.numPoints : 0);
    std::vector<KnownSlide<2>> lineSlides(slides_ ? set.numLines : 0);
    const std::vector<CameraPose> knownPoses = viewPoses(set, CameraPose());
    for (int i = 0; i < (int)pointSlides.size(); ++i)
        if (pointValid_[i])
            knownPointSlide(knownPoses, i, pointSlides[i]);
    for (int i = 0; i < (int)lineSlides.size(); ++i)
        if (lineValid_[i])
            knownLineSlide(knownPoses, i, lineSlides[i]);
    for (int v = 0; v < (int)set.views.size(); ++v)
    {
        const View& view = set.views[v];
        if (!view.estimated)
            continue;
        EstimatedView e;
        e.view = v;
        for (int i = 0; i < set.numPoints; ++i)
        {
            if (!view.seesPoint(i))
                continue;
            if (!pointValid_[i])
            {
                ++e.unmeasured;
                continue;
            }
            PointTerm term = { i, points_[i], view.points[i] };
            e.points.push_back(term);
            if (slides_)
                e.pointSlides.push_back(pointSlides[i]);
        }
        for (int i = 0; i < set.numLines; ++i)
        {
            if (!view.seesLine(i))
                continue;
            if (!lineValid_[i])
            {
                ++e.unmeasured;
                continue;
            }
            LineTerm term = { i,
                              lineEnds_[2 * i],
                              lineEnds_[2 * i + 1],
                              view.lineEnds[2 * i],
                              view.lineEnds[2 * i + 1],
                              view.calibratedLineEnd(i, 0),
                              view.calibratedLineEnd(i, 1) };
            e.lines.push_back(term);
            if (slides_)
                e.lineSlides.push_back(lineSlides[i]);
        }
        estimated_.push_back(e);
    }
    // The sequential test's order: every observation, shuffled once (the same for every pose), so
    // that wrong matches gathered in one range of the features do not reject a good pose.
    std::vector<TestedObservation> order;
    for (int v = 0; v < (int)estimated_.size(); ++v)
    {
        for (int k = 0; k < (int)estimated_[v].points.size(); ++k)
            order.push_back(TestedObservation{ v, SequentialTest::Point, k });
        for (int k = 0; k < (int)estimated_[v].lines.size(); ++k)
            order.push_back(TestedObservation{ v, SequentialTest::Line, k });
        observations_[SequentialTest::Point] += (int)estimated_[v].points.size();
        observations_[SequentialTest::Line] += (int)estimated_[v].lines.size();
    }
    Random random(kTestOrderSeed);
    const int tested = (int)order.size() < kMinTestedObservations ? 0 : std::min((int)order.size(), kMaxTested);
    for (int i = 0; i < tested; ++i)
        std::swap(order[i], order[random.uniform(i, (int)order.size())]);
    testOrder_.assign(order.begin(), order.begin() + tested);
}

void PoseScorer::triangulateKnown()
{
    const ViewSet& set = set_;
    // The known views' poses do not depend on the estimated one.
    const std::vector<CameraPose> poses = viewPoses(set, CameraPose());
    points_.assign(set.numPoints, Eigen::Vector3d::Zero());
    pointValid_.assign(set.numPoints, 0);
    for (int i = 0; i < set.numPoints; ++i)
    {
        Eigen::Vector3d X;
        if (!(triangulatePoint(set, poses.data(), i, ViewSelection::Known, X, kPointTriangulationConditioning,
                               minDepth_) > 0))
            continue;
        // A point triangulated behind a known view is noise, not structure: it must not vote.
        bool inFront = true;
        for (size_t v = 0; v < set.views.size() && inFront; ++v)
            if (!set.views[v].estimated && set.views[v].seesPoint(i))
                inFront = poses[v].toCamera(X).z() > minDepth_;
        points_[i] = X;
        pointValid_[i] = inFront;
    }

    lineEnds_.assign(2 * set.numLines, Eigen::Vector3d::Zero());
    lineValid_.assign(set.numLines, 0);
    std::vector<int> known;
    for (int i = 0; i < set.numLines; ++i)
    {
        known.clear();
        for (int v = 0; v < (int)set.views.size(); ++v)
            if (!set.views[v].estimated && set.views[v].seesLine(i))
                known.push_back(v);
        if (known.size() < 2)
            continue;
        // The end points observed in the first known view, lifted onto the 3D line: with two known
        // views, exactly where their rays cut the other view's plane.
        const View& first = set.views[known[0]];
        const Eigen::Vector3d origin = poses[known[0]].centre();
        PluckerLine L;
        bool valid = known.size() > 2 &&
                     triangulateLine(set, poses.data(), i, ViewSelection::Known, L, kLineTriangulationConditioning);
        const Eigen::Vector4d plane = backProjectLine(poses[known[1]], 1.0, set.views[known[1]].calibratedLines[i]);
        if (known.size() == 2)
            valid = true;
        for (int end = 0; end < 2 && valid; ++end)
        {
            const Eigen::Vector2d x = first.calibratedLineEnd(i, end);
            Eigen::Vector3d X = Eigen::Vector3d::Zero();
            double depth;
            if (known.size() == 2)
                valid = liftLineEnd(poses[known[0]], x, plane, X, depth);
            else
                X = closestPointToRay(L, poses[known[0]].R.transpose() * x.homogeneous(), origin);
            // Ends lifted behind a known view (grazing rays under noise) are not structure.
            for (size_t k = 0; k < known.size() && valid; ++k)
                valid = poses[known[k]].toCamera(X).z() > minDepth_;
            lineEnds_[2 * i + end] = X;
        }
        lineValid_[i] = valid;
    }
}

bool PoseScorer::pointTermResidual2(const EstimatedView& e, size_t k, const Intrinsics& camera, const CameraPose& p,
                                    double threshold2, double& e2) const
{
    const PointTerm& term = e.points[k];
    if (slides_)
        return slidPointResidual2(camera, p, term, e.pointSlides[k], threshold2, e2);
    Eigen::Vector2d r;
    if (!pointResidual(camera, p.toCamera(term.X), term.observed, r))
        return false;
    e2 = r.squaredNorm();
    return true;
}

bool PoseScorer::lineTermResidual2(const EstimatedView& e, size_t k, const Intrinsics& camera, const CameraPose& p,
                                   double threshold2, double& e2, bool& behind) const
{
    const LineTerm& term = e.lines[k];
    if (slides_)
        // A line is an inlier for 0.5 e2 < threshold2 (the mean of its two distances).
        return slidLineResidual2(camera, p, term, e.lineSlides[k], 2 * threshold2, e2, behind);
    const Eigen::Vector3d a = p.toCamera(term.A), b = p.toCamera(term.B);
    const Eigen::Vector3d moment = a.cross(b);
    // The residuals alone would accept the line reflected through the camera centre.
    behind = segmentBehindCamera(moment, b - a, term.calibratedEnd0, term.calibratedEnd1);
    Eigen::Vector2d r;
    if (behind || !lineResidual(camera, moment, term.end0, term.end1, r))
        return false;
    e2 = r.squaredNorm();
    return true;
}

bool PoseScorer::passesSequentialTest(const CameraPose& pose, double threshold2, const SequentialTest& test,
                                      PoseScore& s) const
{
    // The estimated views' poses, once per test (one for three views and registration, two for a rig).
    constexpr int kLocalViews = 4;
    CameraPose local[kLocalViews];
    std::vector<CameraPose> many;
    CameraPose* poses = local;
    if (estimated_.size() > (size_t)kLocalViews)
    {
        many.resize(estimated_.size());
        poses = many.data();
    }
    for (size_t v = 0; v < estimated_.size(); ++v)
        poses[v] = set_.views[estimated_[v].view].poseFor(pose);
    double logRatio = 0;
    for (const TestedObservation& o : testOrder_)
    {
        const EstimatedView& e = estimated_[o.view];
        const Intrinsics& camera = set_.views[e.view].camera;
        double e2 = 0;
        bool consistent;
        if (o.kind == SequentialTest::Point)
            consistent = pointTermResidual2(e, o.term, camera, poses[o.view], threshold2, e2) && e2 < threshold2;
        else
        {
            bool behind = false;
            consistent = lineTermResidual2(e, o.term, camera, poses[o.view], threshold2, e2, behind) &&
                         0.5 * e2 < threshold2;
        }
        ++s.tested[o.kind];
        s.testedConsistent[o.kind] += consistent;
        logRatio += test.step(o.kind, consistent);
        if (logRatio > test.logThreshold())
            return false;
    }
    return true;
}

PoseScore PoseScorer::score(const CameraPose& pose, double threshold, double bound, FeatureSubset* inliers,
                            const SequentialTest* test) const
{
    const double threshold2 = threshold * threshold;
    PoseScore s;
    if (inliers)
        inliers->clear();
    if (test && test->active() && !testOrder_.empty() && !passesSequentialTest(pose, threshold2, *test, s))
    {
        s.cost = std::numeric_limits<double>::infinity();
        s.rejected = true;
        return s;
    }
    for (const EstimatedView& e : estimated_)
    {
        const View& view = set_.views[e.view];
        const CameraPose p = view.poseFor(pose);
        const Intrinsics& camera = view.camera;
        s.cost += e.unmeasured * threshold2;
        for (size_t k = 0; k < e.points.size(); ++k)
        {
            ++s.considered;
            double r2 = threshold2, e2 = 0;
            if (pointTermResidual2(e, k, camera, p, threshold2, e2))
            {
                s.sumSquares += e2;
                ++s.residuals;
                if (e2 < threshold2)
                {
                    r2 = e2;
                    ++s.inliers;
                    ++s.pointInliers;
                    if (inliers)
                        inliers->points.push_back(e.points[k].feature);
                }
            }
            else
                ++s.behind;
            s.cost += r2;
            if (s.cost > bound)
            {
                s.cost = std::numeric_limits<double>::infinity();
                return s;
            }
        }
        for (size_t k = 0; k < e.lines.size(); ++k)
        {
            s.considered += 2;
            double r2 = threshold2, e2 = 0;
            bool behind = false;
            const bool measured = lineTermResidual2(e, k, camera, p, threshold2, e2, behind);
            s.behind += behind ? 2 : 0;
            if (measured)
            {
                s.sumSquares += e2;
                s.residuals += 2;
                if (0.5 * e2 < threshold2)
                {
                    r2 = 0.5 * e2;
                    ++s.inliers;
                    if (inliers)
                        inliers->lines.push_back(e.lines[k].feature);
                }
            }
            s.cost += r2;
            if (s.cost > bound)
            {
                s.cost = std::numeric_limits<double>::infinity();
                return s;
            }
        }
    }
    if (inliers && estimated_.size() > 1)
        inliers->removeDuplicates();
    return s;
}

void PoseScorer::knownPointSlide(const std::vector<CameraPose>& poses, int i, KnownSlide<1>& slide) const
{
    slide.H.setZero();
    slide.g.setZero();
    bool first = true;
    for (size_t v = 0; v < set_.views.size(); ++v)
    {
        const View& view = set_.views[v];
        if (view.estimated || !view.seesPoint(i))
            continue;
        if (first)
        {
            slide.origin = poses[v].centre();
            const Eigen::Vector3d ray = points_[i] - slide.origin;
            slide.inverseDepth(0) = 1.0 / ray.norm();
            slide.rays.col(0) = ray * slide.inverseDepth(0);
            first = false;
        }
        // The point in this camera, times the inverse depth: rho e + f (slidEnds()).
        const Eigen::Vector3d e = poses[v].toCamera(slide.origin), f = poses[v].R * slide.rays.col(0);
        Eigen::Vector2d r;
        Matrix23d J;
        if (!pointResidual(view.camera, slide.inverseDepth(0) * e + f, view.points[i], r, &J))
            continue;
        const Eigen::Vector2d d = J * e;
        slide.H(0, 0) += d.squaredNorm();
        slide.g(0) += d.dot(r);
    }
}

void PoseScorer::knownLineSlide(const std::vector<CameraPose>& poses, int i, KnownSlide<2>& slide) const
{
    slide.H.setZero();
    slide.g.setZero();
    bool first = true;
    for (size_t v = 0; v < set_.views.size(); ++v)
    {
        const View& view = set_.views[v];
        if (view.estimated || !view.seesLine(i))
            continue;
        if (first)
        {
            // The end points lie on the first known view's rays through its observed end points.
            slide.origin = poses[v].centre();
            for (int end = 0; end < 2; ++end)
            {
                const Eigen::Vector3d ray = lineEnds_[2 * i + end] - slide.origin;
                slide.inverseDepth(end) = 1.0 / ray.norm();
                slide.rays.col(end) = ray * slide.inverseDepth(end);
            }
            first = false;
        }
        const Eigen::Vector3d e = poses[v].toCamera(slide.origin);
        const Eigen::Vector3d fA = poses[v].R * slide.rays.col(0), fB = poses[v].R * slide.rays.col(1);
        Eigen::Vector2d r;
        Matrix23d Jm;
        if (!lineResidual(view.camera, slidMoment(e, fA, fB, slide.inverseDepth), view.lineEnds[2 * i],
                          view.lineEnds[2 * i + 1], r, &Jm))
            continue;
        Eigen::Matrix2d J;
        J.col(0) = Jm * e.cross(fB);
        J.col(1) = Jm * fA.cross(e);
        slide.H += J.transpose() * J;
        slide.g += J.transpose() * r;
    }
}

bool PoseScorer::slidPointResidual2(const Intrinsics& camera, const CameraPose& pose, const PointTerm& term,
                                    const KnownSlide<1>& slide, double bound2, double& r2) const
{
    // In a camera at pose, the point at inverse depth rho on the ray (origin c, direction u) is
    // (R c + t) + R u / rho: rho e + f up to the scale its projection ignores.
    const Eigen::Vector3d e = pose.toCamera(slide.origin), f = pose.R * slide.rays.col(0);
    const double rho0 = slide.inverseDepth(0);
    Eigen::Vector2d r;
    Matrix23d Jh;
    if (!pointResidual(camera, rho0 * e + f, term.observed, r, &Jh, 0.0))
        return false;
    r2 = r.squaredNorm();
    if (std::isfinite(bound2) && r2 <= kSettledShare * bound2)
        return true;
    double rho = rho0;
    for (int iteration = 0; iteration < kSlideIterations; ++iteration)
    {
        if (iteration > 0 && !pointResidual(camera, rho * e + f, term.observed, r, &Jh, 0.0))
            return true;
        // Gauss-Newton on |r(rho)|^2 plus the known views' growth H (rho - rho0)^2 + 2 g (rho - rho0).
        const Eigen::Vector2d J = Jh * e;
        const double a = J.squaredNorm() + slide.H(0, 0), b = J.dot(r) + slide.H(0, 0) * (rho - rho0) + slide.g(0);
        if (!(a > 0))
            break;
        // The first step's model minimum r.r - b^2 / a: past the bound, the observation is taken for an
        // outlier without further steps, which at the true pose loses only a rare true observation.
        if (iteration == 0 && r2 - b * b / a >= bound2)
            return true;
        // The point stays in front of the first known view (rho > 0; rho = 0 is the point at infinity).
        rho = std::max(rho - b / a, kMinInverseDepthShare * rho0);
    }
    Eigen::Vector2d rs;
    if (pointResidual(camera, rho * e + f, term.observed, rs, nullptr, 0.0))
    {
        const double step = rho - rho0;
        r2 = std::min(r2, std::max(0.0, rs.squaredNorm() + slide.H(0, 0) * step * step + 2 * slide.g(0) * step));
    }
    return true;
}

bool PoseScorer::slidLineResidual2(const Intrinsics& camera, const CameraPose& pose, const LineTerm& term,
                                   const KnownSlide<2>& slide, double bound2, double& r2, bool& behind) const
{
    const Eigen::Vector3d e = pose.toCamera(slide.origin);
    const Eigen::Vector3d fA = pose.R * slide.rays.col(0), fB = pose.R * slide.rays.col(1);
    // The line through the end points at inverse depths rho: its moment is linear in rho
    // (slidMoment()), its direction times rhoA rhoB is rhoA fB - rhoB fA.
    const auto behindAt = [&](const Eigen::Vector2d& rho) {
        return segmentBehindCamera(slidMoment(e, fA, fB, rho), rho(0) * fB - rho(1) * fA, term.calibratedEnd0,
                                   term.calibratedEnd1);
    };
    const Eigen::Vector2d rho0 = slide.inverseDepth;
    Eigen::Vector2d r;
    Matrix23d Jm;
    // A segment seen behind the camera from the triangulated structure stays so: a slide could
    // carry it through infinity to the other side.
    behind = behindAt(rho0);
    if (behind || !lineResidual(camera, slidMoment(e, fA, fB, rho0), term.end0, term.end1, r, &Jm))
        return false;
    r2 = r.squaredNorm();
    if (std::isfinite(bound2) && r2 <= kSettledShare * bound2)
        return true;
    Eigen::Vector2d rho = rho0;
    for (int iteration = 0; iteration < kSlideIterations; ++iteration)
    {
        if (iteration > 0 && !lineResidual(camera, slidMoment(e, fA, fB, rho), term.end0, term.end1, r, &Jm))
            break;
        Eigen::Matrix2d J;
        J.col(0) = Jm * e.cross(fB);
        J.col(1) = Jm * fA.cross(e);
        const Eigen::Matrix2d M = J.transpose() * J + slide.H;
        const Eigen::Vector2d v = J.transpose() * r + slide.H * (rho - rho0) + slide.g;
        const double det = M.determinant(), trace = M.trace();
        if (!(det > kSlideConditioning * trace * trace))
            break;
        Eigen::Matrix2d inverse;
        inverse << M(1, 1), -M(0, 1), -M(1, 0), M(0, 0);
        const Eigen::Vector2d step = -(inverse * v) / det;
        // The first step's model minimum r.r + v . step: past the bound, an outlier (as for points).
        if (iteration == 0 && r2 + v.dot(step) >= bound2)
            return true;
        const Eigen::Vector2d next = rho + step;
        for (int end = 0; end < 2; ++end)
            rho(end) = std::max(next(end), kMinInverseDepthShare * rho0(end));
    }
    Eigen::Vector2d rs;
    if (!behindAt(rho) && lineResidual(camera, slidMoment(e, fA, fB, rho), term.end0, term.end1, rs))
    {
        const Eigen::Vector2d step = rho - rho0;
        const double slid2 = rs.squaredNorm() + step.dot(slide.H * step) + 2 * slide.g.dot(step);
        r2 = std::min(r2, std::max(0.0, slid2));
    }
    return true;
}

void PoseScorer::refitResiduals(const CameraPose& pose, std::vector<double>& pointResiduals,
                                std::vector<double>& lineResiduals) const
{
    const std::vector<CameraPose> poses = viewPoses(set_, pose);
    std::vector<Eigen::Vector2d> residuals;
    // RMS over every coordinate of the views that see the feature (two per view).
    const auto rms = [&](bool point, int i) {
        double sum = 0;
        int count = 0;
        for (size_t v = 0; v < set_.views.size(); ++v)
            if (point ? set_.views[v].seesPoint(i) : set_.views[v].seesLine(i))
            {
                sum += residuals[v].squaredNorm();
                count += 2;
            }
        return std::sqrt(sum / count);
    };
    const double inf = std::numeric_limits<double>::infinity();
    pointResiduals.assign(set_.numPoints, inf);
    for (int i = 0; i < set_.numPoints; ++i)
    {
        Eigen::Vector3d X;
        if (refitPoint(set_, poses.data(), i, minDepth_, X, residuals))
            pointResiduals[i] = rms(true, i);
    }
    lineResiduals.assign(set_.numLines, inf);
    for (int i = 0; i < set_.numLines; ++i)
    {
        PluckerLine L;
        if (refitLine(set_, poses.data(), i, L, residuals))
            lineResiduals[i] = rms(false, i);
    }
}

} // namespace tripose
