// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "../generated/line_rows.hpp"
#include "../generated/point_rows.hpp"
#include "../generated/rig_rows.hpp"
#include "../geometry/conditioning.hpp"
#include "line_end_points.hpp"
#include "point_normalization.hpp"
#include "rig_system.hpp"

namespace tripose {

namespace {

//! Scales a block of rows to Frobenius norm kBalancedBlockNorm, its right-hand sides with it.
void balanceBlock(RigSystem& system, int row, int count)
{
    const double norm = system.A.middleRows(row, count).norm();
    if (!(norm > 0))
        return;
    const double scale = kBalancedBlockNorm / norm;
    system.A.middleRows(row, count) *= scale;
    system.b.segment(row, count) *= scale;
}

/** A line's two rows: weighted by the inverse of their predicted noise when they come from
lineEndPoints() (near-geometric rows, @p weights), else balanced like every block.
*/
void weighLineRows(RigSystem& system, int row, const double* weights)
{
    if (!weights)
    {
        balanceBlock(system, row, 2);
        return;
    }
    for (int k = 0; k < 2; ++k)
    {
        system.A.row(row + k) *= weights[k];
        system.b(row + k) *= weights[k];
    }
}

void countFeature(RigFeatureCounts& counts, bool point, bool in3, bool in4)
{
    if (in3 && in4)
        ++(point ? counts.pointsBoth : counts.linesBoth);
    else if (in3)
        ++(point ? counts.pointsOnly3 : counts.linesOnly3);
    else
        ++(point ? counts.pointsOnly4 : counts.linesOnly4);
}

} // namespace

bool buildRigSystem(const ViewSet& set, const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                    RigSystem& system)
{
    TRIPOSE_ASSERT(set.views.size() == 4);
    const View& view1 = set.views[ViewSet::kView1];
    const View& view2 = set.views[ViewSet::kView2];
    const View& view3 = set.views[ViewSet::kView3];
    const View& view4 = set.views[ViewSet::kRigRightB];
    system.counts = RigFeatureCounts();
    system.translationScale = set.pose12().t.norm();
    if (!(system.translationScale > 0) || !std::isfinite(system.translationScale))
        return false;
    CameraPose rig = set.pose12();
    rig.t /= system.translationScale;
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R12 = rig.R;

    // Features with rows: seen in views 1 and 2 and in at least one time-B view.
    std::vector<int> points, lines, points3, points4;
    const int numPoints = pointIndices ? (int)pointIndices->size() : set.numPoints;
    for (int k = 0; k < numPoints; ++k)
    {
        const int i = pointIndices ? (*pointIndices)[k] : k;
        const bool in3 = view3.seesPoint(i), in4 = view4.seesPoint(i);
        if (!view1.seesPoint(i) || !view2.seesPoint(i) || !(in3 || in4))
            continue;
        points.push_back(i);
        if (in3)
            points3.push_back(i);
        if (in4)
            points4.push_back(i);
    }
    const int numLines = lineIndices ? (int)lineIndices->size() : set.numLines;
    for (int k = 0; k < numLines; ++k)
    {
        const int i = lineIndices ? (*lineIndices)[k] : k;
        if (view1.seesLine(i) && view2.seesLine(i) && (view3.seesLine(i) || view4.seesLine(i)))
            lines.push_back(i);
    }

    int rows = 4 * (int)(points3.size() + points4.size());
    for (int i : lines)
        rows += 2 * ((view3.seesLine(i) ? 1 : 0) + (view4.seesLine(i) ? 1 : 0));
    system.A.setZero(rows, 12);
    system.b.setZero(rows);

    // Over-determined systems (from six features every mix leaves at most a one-dimensional kernel)
    // take the lines' noise-weighted end points, as the three-view system does: with noise the
    // orthonormal pair weighs lines with little parallax at time A as much as the others. Smaller
    // systems are solved exactly, where the orthonormal pair conditions A best.
    const bool overdetermined = points.size() + lines.size() >= 6;
    int row = 0;
    if (!points.empty())
    {
        const Eigen::Vector3d n1 = normalizingSimilarity(view1.calibratedPoints, &points);
        const Eigen::Vector3d n2 = normalizingSimilarity(view2.calibratedPoints, &points);
        const Eigen::Vector3d n3 = normalizingSimilarity(view3.calibratedPoints, &points3);
        const Eigen::Vector3d n4 = normalizingSimilarity(view4.calibratedPoints, &points4);
        for (int i : points)
        {
            const Eigen::Vector2d x1 = applySimilarity(n1, view1.calibratedPoints[i]);
            const Eigen::Vector2d x2 = applySimilarity(n2, view2.calibratedPoints[i]);
            const bool in3 = view3.seesPoint(i), in4 = view4.seesPoint(i);
            if (in3)
            {
                const Eigen::Vector2d x3 = applySimilarity(n3, view3.calibratedPoints[i]);
                generated::pointRows(x1.data(), x2.data(), x3.data(), n1.data(), n2.data(), n3.data(), R12.data(),
                                     rig.t.data(), system.A.row(row).data());
                balanceBlock(system, row, 4);
                row += 4;
            }
            if (in4)
            {
                const Eigen::Vector2d x4 = applySimilarity(n4, view4.calibratedPoints[i]);
                generated::rigPointRows(x1.data(), x2.data(), x4.data(), n1.data(), n2.data(), n4.data(), R12.data(),
                                        rig.t.data(), system.A.row(row).data(), system.b.data() + row);
                balanceBlock(system, row, 4);
                row += 4;
            }
            countFeature(system.counts, true, in3, in4);
        }
    }
    for (int i : lines)
    {
        const bool in3 = view3.seesLine(i), in4 = view4.seesLine(i);
        Eigen::Vector4d qa, qb;
        double weights[2] = { 1.0, 1.0 };
        const bool weighted = overdetermined && lineEndPoints(set, i, rig, qa, qb, weights);
        // A line in an epipolar plane of views 1-2 has no 3D position: it contributes nothing,
        // and is not counted, so that the kernel dimension stays that of the rows present.
        if (!weighted && !lineNullSpace(view1.calibratedLines[i], view2.calibratedLines[i], rig, qa, qb))
        {
            row += 2 * ((in3 ? 1 : 0) + (in4 ? 1 : 0));
            continue;
        }
        if (in3)
        {
            generated::lineRows(qa.data(), qb.data(), view3.calibratedLines[i].data(), system.A.row(row).data());
            weighLineRows(system, row, weighted ? weights : nullptr);
            row += 2;
        }
        if (in4)
        {
            generated::rigLineRows(qa.data(), qb.data(), view4.calibratedLines[i].data(), R12.data(), rig.t.data(),
                                   system.A.row(row).data(), system.b.data() + row);
            weighLineRows(system, row, weighted ? weights : nullptr);
            row += 2;
        }
        countFeature(system.counts, false, in3, in4);
    }
    TRIPOSE_DEBUG_ASSERT(row == rows);
    return true;
}

} // namespace tripose
