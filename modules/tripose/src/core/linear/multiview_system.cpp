// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <Eigen/Dense>

#include "multiview_system.hpp"

namespace tripose {

namespace {

/** M with v_a = M v, where v = [r1; r2; r3; t / scale] is the unknown camera's pose relative to the
reference frame and v_a the same camera relative to view a, which is at @p a in the reference frame:
R_a = R R_a^T gives column j of R_a as sum_k R_a(j, k) r_k, and t_a = t - R_a t_a(ref) as
t - sum_k (R_a^T t_a)_k r_k.
*/
Matrix12d pairTransform(const CameraPose& a, double scale)
{
    Matrix12d M = Matrix12d::Zero();
    const Eigen::Vector3d c = a.R.transpose() * a.t / scale;
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
            M.block<3, 3>(3 * j, 3 * k) = a.R(j, k) * Eigen::Matrix3d::Identity();
    for (int k = 0; k < 3; ++k)
        M.block<3, 3>(9, 3 * k) = -c(k) * Eigen::Matrix3d::Identity();
    M.block<3, 3>(9, 9).setIdentity();
    return M;
}

//! Angle (rad) between the rays of a point in two views: the wider, the better conditioned its depth.
double rayAngle(const View& a, const View& b, int point)
{
    const Eigen::Vector3d da = a.pose.R.transpose() * a.calibratedPoints[point].homogeneous();
    const Eigen::Vector3d db = b.pose.R.transpose() * b.calibratedPoints[point].homogeneous();
    return std::atan2(da.cross(db).norm(), da.dot(db));
}

//! Sine of the angle between the back-projected planes of a line in two views: near zero, the
//! planes coincide and the line has no 3D position.
double planeSine(const View& a, const View& b, int line)
{
    const Eigen::Vector3d na = (a.pose.R.transpose() * a.calibratedLines[line]).normalized();
    const Eigen::Vector3d nb = (b.pose.R.transpose() * b.calibratedLines[line]).normalized();
    return na.cross(nb).norm();
}

// Known centres closer than this fraction of the system's scale form no baseline.
constexpr double kMinBaseline = 1e-9;

} // namespace

MultiViewSystem::MultiViewSystem(const ViewSet& set, PairSelection selection) : set_(set), selection_(selection)
{
    std::vector<int> known;
    for (int v = 0; v < (int)set.views.size(); ++v)
    {
        if (!set.views[v].estimated)
            known.push_back(v);
        else if (estimated_ < 0)
            estimated_ = v;
    }
    bestPointPair_.assign(set.numPoints, -1);
    bestLinePair_.assign(set.numLines, -1);
    allPointPairs_.assign(set.numPoints, std::vector<int>());
    allLinePairs_.assign(set.numLines, std::vector<int>());
    if (known.size() < 2 || estimated_ < 0)
        return;
    reference_ = set.views[known[0]].pose;
    for (int v : known)
        scale_ = std::max(scale_, (set.views[v].pose.centre() - reference_.centre()).norm());
    if (!(scale_ > 0) || !std::isfinite(scale_))
    {
        scale_ = 0; // no baseline: nothing fixes the scale, candidates() returns none
        return;
    }

    std::vector<int> seen;
    for (int kind = 0; kind < 2; ++kind)
    {
        const bool point = kind == 0;
        const int count = point ? set.numPoints : set.numLines;
        for (int i = 0; i < count; ++i)
        {
            seen.clear();
            bool seenByEstimated = false;
            for (int v = 0; v < (int)set.views.size(); ++v)
            {
                const bool sees = point ? set.views[v].seesPoint(i) : set.views[v].seesLine(i);
                if (set.views[v].estimated)
                    seenByEstimated = seenByEstimated || sees;
                else if (sees)
                    seen.push_back(v);
            }
            if (!seenByEstimated)
                continue;
            double bestScore = -1;
            int best = -1;
            for (size_t x = 0; x < seen.size(); ++x)
                for (size_t y = x + 1; y < seen.size(); ++y)
                {
                    const View& a = set.views[seen[x]];
                    const View& b = set.views[seen[y]];
                    if (!((a.pose.centre() - b.pose.centre()).norm() > kMinBaseline * scale_))
                        continue;
                    const double score = point ? rayAngle(a, b, i) : planeSine(a, b, i);
                    const bool all = selection_ == PairSelection::All;
                    if (!all && !(score > bestScore))
                        continue;
                    const int p = pairFor(seen[x], seen[y]);
                    if (all)
                    {
                        addFeature(p, point, i);
                        (point ? allPointPairs_ : allLinePairs_)[i].push_back(p);
                    }
                    if (score > bestScore)
                    {
                        bestScore = score;
                        best = p;
                    }
                }
            if (best < 0)
                continue;
            (point ? bestPointPair_ : bestLinePair_)[i] = best;
            if (selection_ == PairSelection::Best)
                addFeature(best, point, i);
        }
    }
}

int MultiViewSystem::pairFor(int a, int b)
{
    for (size_t p = 0; p < pairs_.size(); ++p)
        if (pairs_[p].a == a && pairs_[p].b == b)
            return (int)p;
    Pair pair;
    pair.a = a;
    pair.b = b;
    pair.views.views.resize(3);
    View& va = pair.views.views[ViewSet::kView1];
    View& vb = pair.views.views[ViewSet::kView2];
    View& vn = pair.views.views[ViewSet::kView3];
    va.camera = set_.views[a].camera;
    vb.camera = set_.views[b].camera;
    vb.pose = poseRelativeTo(set_.views[b].pose, set_.views[a].pose);
    vn.camera = set_.views[estimated_].camera;
    vn.estimated = true;
    pair.M = pairTransform(poseRelativeTo(set_.views[a].pose, reference_), scale_);
    pair.pointLocal.assign(set_.numPoints, -1);
    pair.lineLocal.assign(set_.numLines, -1);
    pairs_.push_back(pair);
    return (int)pairs_.size() - 1;
}

void MultiViewSystem::addFeature(int p, bool point, int feature)
{
    Pair& pair = pairs_[p];
    const int source[3] = { pair.a, pair.b, estimated_ };
    if (point)
    {
        pair.pointLocal[feature] = pair.views.numPoints++;
        for (int k = 0; k < 3; ++k)
        {
            const View& from = set_.views[source[k]];
            View& to = pair.views.views[k];
            to.points.push_back(from.points[feature]);
            to.calibratedPoints.push_back(from.calibratedPoints[feature]);
        }
        return;
    }
    pair.lineLocal[feature] = pair.views.numLines++;
    for (int k = 0; k < 3; ++k)
    {
        const View& from = set_.views[source[k]];
        View& to = pair.views.views[k];
        to.lineEnds.push_back(from.lineEnds[2 * feature]);
        to.lineEnds.push_back(from.lineEnds[2 * feature + 1]);
        to.calibratedLines.push_back(from.calibratedLines[feature]);
    }
}

std::pair<int, int> MultiViewSystem::bestPointPair(int i) const
{
    const int p = bestPointPair_[i];
    return p < 0 ? std::make_pair(-1, -1) : std::make_pair(pairs_[p].a, pairs_[p].b);
}

int MultiViewSystem::candidates(std::vector<CameraPose>& poses, const std::vector<int>* pointIndices,
                                const std::vector<int>* lineIndices, const CandidateOptions& options) const
{
    if (!(scale_ > 0))
        return 0;
    const int numPoints = pointIndices ? (int)pointIndices->size() : set_.numPoints;
    const int numLines = lineIndices ? (int)lineIndices->size() : set_.numLines;
    // Several pairs per feature only where the system is over-determined anyway: a minimal sample's
    // kernel dimension assumes two independent rows per feature.
    const bool all = selection_ == PairSelection::All && numPoints + numLines >= 6;

    std::vector<std::vector<int>> points(pairs_.size()), lines(pairs_.size());
    int features = 0, pointBlocks = 0, lineBlocks = 0;
    for (int k = 0; k < numPoints; ++k)
    {
        const int i = pointIndices ? (*pointIndices)[k] : k;
        if (bestPointPair_[i] < 0)
            continue; // not seen by the estimated view and two known views with a baseline
        ++features;
        const std::vector<int> best(1, bestPointPair_[i]);
        for (int p : all ? allPointPairs_[i] : best)
        {
            points[p].push_back(pairs_[p].pointLocal[i]);
            ++pointBlocks;
        }
    }
    for (int k = 0; k < numLines; ++k)
    {
        const int i = lineIndices ? (*lineIndices)[k] : k;
        if (bestLinePair_[i] < 0)
            continue;
        ++features;
        const std::vector<int> best(1, bestLinePair_[i]);
        for (int p : all ? allLinePairs_[i] : best)
        {
            lines[p].push_back(pairs_[p].lineLocal[i]);
            ++lineBlocks;
        }
    }
    if (features < 4)
        return 0;

    ConstraintMatrix A(4 * pointBlocks + 2 * lineBlocks, 12);
    int pointRow = 0, lineRow = 4 * pointBlocks;
    for (size_t p = 0; p < pairs_.size(); ++p)
    {
        if (points[p].empty() && lines[p].empty())
            continue;
        const ConstraintMatrix Ap = buildConstraintMatrix(pairs_[p].views, scale_, &points[p], &lines[p]);
        const int pr = 4 * (int)points[p].size(), lr = 2 * (int)lines[p].size();
        A.middleRows(pointRow, pr) = Ap.topRows(pr) * pairs_[p].M;
        A.middleRows(lineRow, lr) = Ap.bottomRows(lr) * pairs_[p].M;
        pointRow += pr;
        lineRow += lr;
    }

    std::vector<CameraPose> relative;
    poseCandidatesFromRows(A, pointBlocks, pointBlocks + lineBlocks, scale_, relative, options);
    for (const CameraPose& r : relative)
    {
        // x = R' (R_ref X + t_ref) + t'.
        CameraPose world;
        world.R = r.R * reference_.R;
        world.t = r.R * reference_.t + r.t;
        poses.push_back(world);
    }
    return (int)relative.size();
}

} // namespace tripose
