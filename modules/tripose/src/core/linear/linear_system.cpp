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

#include "../generated/line_rows.hpp"
#include "../geometry/conditioning.hpp"
#include "../generated/point_rows.hpp"
#include "line_end_points.hpp"
#include "linear_system.hpp"
#include "point_normalization.hpp"

namespace tripose {

bool lineNullSpace(const Eigen::Vector3d& l1, const Eigen::Vector3d& l2, const CameraPose& pose12,
                   Eigen::Vector4d& qa, Eigen::Vector4d& qb)
{
    // The planes of views 1 and 2 meet in a line only if their normals are not parallel.
    const Eigen::Vector3d n2 = pose12.R.transpose() * l2;
    if (!(l1.cross(n2).norm() > 1e-10 * l1.norm() * n2.norm()))
        return false;
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R12 = pose12.R;
    generated::lineNullSpace(l1.data(), l2.data(), R12.data(), pose12.t.data(), qa.data(), qb.data());
    return qa.allFinite() && qb.allFinite();
}

ConstraintMatrix buildConstraintMatrix(const ViewSet& set, double translationScale,
                                       const std::vector<int>* pointIndices, const std::vector<int>* lineIndices)
{
    const int numPoints = pointIndices ? (int)pointIndices->size() : set.numPoints;
    const int numLines = lineIndices ? (int)lineIndices->size() : set.numLines;
    CameraPose pose12 = set.pose12();
    pose12.t /= translationScale;
    const std::vector<Eigen::Vector2d>& points1 = set.views[ViewSet::kView1].calibratedPoints;
    const std::vector<Eigen::Vector2d>& points2 = set.views[ViewSet::kView2].calibratedPoints;
    const std::vector<Eigen::Vector2d>& points3 = set.views[ViewSet::kView3].calibratedPoints;
    const std::vector<Eigen::Vector3d>& lines1 = set.views[ViewSet::kView1].calibratedLines;
    const std::vector<Eigen::Vector3d>& lines2 = set.views[ViewSet::kView2].calibratedLines;
    const std::vector<Eigen::Vector3d>& lines3 = set.views[ViewSet::kView3].calibratedLines;

    ConstraintMatrix A(4 * numPoints + 2 * numLines, 12);
    const bool overdetermined = numPoints + numLines >= 6;
    int row = 0;
    if (numPoints > 0)
    {
        const Eigen::Vector3d n1 = normalizingSimilarity(points1, pointIndices);
        const Eigen::Vector3d n2 = normalizingSimilarity(points2, pointIndices);
        const Eigen::Vector3d n3 = normalizingSimilarity(points3, pointIndices);
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R12 = pose12.R;
        for (int k = 0; k < numPoints; ++k)
        {
            const int i = pointIndices ? (*pointIndices)[k] : k;
            const Eigen::Vector2d x1 = applySimilarity(n1, points1[i]);
            const Eigen::Vector2d x2 = applySimilarity(n2, points2[i]);
            const Eigen::Vector2d x3 = applySimilarity(n3, points3[i]);
            generated::pointRows(x1.data(), x2.data(), x3.data(), n1.data(), n2.data(), n3.data(),
                                 R12.data(), pose12.t.data(), A.row(row).data());
            // Balance: a point's rows (rank 2) get the weight of a line's two unit rows, so that
            // neither kind dominates the conditioning of A^T A whatever the normalising scales.
            const double blockNorm = A.middleRows(row, 4).norm();
            if (blockNorm > 0)
                A.middleRows(row, 4) *= kBalancedBlockNorm / blockNorm;
            row += 4;
        }
    }
    for (int k = 0; k < numLines; ++k)
    {
        const int i = lineIndices ? (*lineIndices)[k] : k;
        // Over-determined systems take the noise-weighted end points; with four or five features
        // the kernel does not depend on the pair of points, and the orthonormal pair conditions it best.
        Eigen::Vector4d qa, qb;
        double weights[2] = { 1.0, 1.0 };
        const bool weighted = overdetermined && lineEndPoints(set, i, pose12, qa, qb, weights);
        if (!weighted && !lineNullSpace(lines1[i], lines2[i], pose12, qa, qb))
        {
            // A line in an epipolar plane of views 1-2 has no 3D position: it contributes nothing.
            A.middleRows(row, 2).setZero();
        }
        else
        {
            // Weighted rows read as image distances: l3 with unit normal. Otherwise unit rows
            // (q and l3 unit vectors) condition the small systems best.
            const Eigen::Vector3d l3 = weighted ? Eigen::Vector3d(lines3[i] / lines3[i].head<2>().norm())
                                                : Eigen::Vector3d(lines3[i].normalized());
            generated::lineRows(qa.data(), qb.data(), l3.data(), A.row(row).data());
            if (weighted)
            {
                A.row(row) *= weights[0];
                A.row(row + 1) *= weights[1];
            }
        }
        row += 2;
    }
    return A;
}

} // namespace tripose
