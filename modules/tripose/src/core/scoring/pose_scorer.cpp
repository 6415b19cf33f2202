// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "../geometry/conditioning.hpp"
#include "../geometry/residuals.hpp"
#include "../geometry/segment_cheirality.hpp"
#include "../geometry/triangulation.hpp"
#include "pose_scorer.hpp"

namespace tripose {

double PoseScore::rms() const
{
    return residuals > 0 ? std::sqrt(sumSquares / residuals) : std::numeric_limits<double>::infinity();
}

PoseScorer::PoseScorer(const ViewSet& set) : set_(set), minDepth_(1e-9 * set.knownBaseline())
{
    triangulateKnown();
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
        }
        estimated_.push_back(e);
    }
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

PoseScore PoseScorer::score(const CameraPose& pose, double threshold, double bound, FeatureSubset* inliers) const
{
    const double threshold2 = threshold * threshold;
    PoseScore s;
    if (inliers)
        inliers->clear();
    for (const EstimatedView& e : estimated_)
    {
        const View& view = set_.views[e.view];
        const CameraPose p = view.poseFor(pose);
        const Intrinsics& camera = view.camera;
        s.cost += e.unmeasured * threshold2;
        Eigen::Vector2d r;
        for (const PointTerm& term : e.points)
        {
            ++s.considered;
            double r2 = threshold2;
            if (pointResidual(camera, p.toCamera(term.X), term.observed, r))
            {
                const double e2 = r.squaredNorm();
                s.sumSquares += e2;
                ++s.residuals;
                if (e2 < threshold2)
                {
                    r2 = e2;
                    ++s.inliers;
                    if (inliers)
                        inliers->points.push_back(term.feature);
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
        for (const LineTerm& term : e.lines)
        {
            s.considered += 2;
            double r2 = threshold2;
            const Eigen::Vector3d a = p.toCamera(term.A), b = p.toCamera(term.B);
            const Eigen::Vector3d moment = a.cross(b);
            // The residuals alone would accept the line reflected through the camera centre.
            const bool behind = segmentBehindCamera(moment, b - a, term.calibratedEnd0, term.calibratedEnd1);
            s.behind += behind ? 2 : 0;
            if (!behind && lineResidual(camera, moment, term.end0, term.end1, r))
            {
                const double e2 = r.squaredNorm();
                s.sumSquares += e2;
                s.residuals += 2;
                if (0.5 * e2 < threshold2)
                {
                    r2 = 0.5 * e2;
                    ++s.inliers;
                    if (inliers)
                        inliers->lines.push_back(term.feature);
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

void PoseScorer::refitResiduals(const CameraPose& pose, std::vector<double>& pointResiduals,
                                std::vector<double>& lineResiduals) const
{
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<CameraPose> poses = viewPoses(set_, pose);
    const int numViews = (int)set_.views.size();
    pointResiduals.assign(set_.numPoints, inf);
    for (int i = 0; i < set_.numPoints; ++i)
    {
        Eigen::Vector3d X;
        if (!(triangulatePoint(set_, poses.data(), i, ViewSelection::All, X, kPointTriangulationConditioning,
                               minDepth_) > 0))
            continue;
        double sum = 0;
        int count = 0;
        bool ok = true;
        Eigen::Vector2d r;
        for (int v = 0; v < numViews && ok; ++v)
        {
            const View& view = set_.views[v];
            if (!view.seesPoint(i))
                continue;
            ok = pointResidual(view.camera, poses[v].toCamera(X), view.points[i], r, nullptr, minDepth_);
            sum += r.squaredNorm();
            count += 2;
        }
        if (ok)
            pointResiduals[i] = std::sqrt(sum / count);
    }
    lineResiduals.assign(set_.numLines, inf);
    for (int i = 0; i < set_.numLines; ++i)
    {
        PluckerLine L;
        if (!triangulateLine(set_, poses.data(), i, ViewSelection::All, L, 0.0))
            continue;
        double sum = 0;
        int count = 0;
        bool ok = true;
        Eigen::Vector2d r;
        for (int v = 0; v < numViews && ok; ++v)
        {
            const View& view = set_.views[v];
            if (!view.seesLine(i))
                continue;
            ok = !segmentBehindCamera(poses[v], L, view.calibratedLineEnd(i, 0), view.calibratedLineEnd(i, 1)) &&
                 lineResidual(view.camera, lineMomentInCamera(poses[v], L), view.lineEnds[2 * i],
                              view.lineEnds[2 * i + 1], r);
            sum += r.squaredNorm();
            count += 2;
        }
        if (ok)
            lineResiduals[i] = std::sqrt(sum / count);
    }
}

} // namespace tripose
