// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>

#include "generated/line_rows.hpp"
#include "generated/point_rows.hpp"
#include "linear_system.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

//! Hartley normalisation of one view: x̂ = s (x - c), centroid at the origin, mean distance √2.
Eigen::Vector3d normalizingSimilarity(const std::vector<Eigen::Vector2d>& points, const std::vector<int>* indices)
{
    const int n = indices ? (int)indices->size() : (int)points.size();
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (int k = 0; k < n; ++k)
        centroid += points[indices ? (*indices)[k] : k];
    centroid /= std::max(n, 1);
    double meanDistance = 0;
    for (int k = 0; k < n; ++k)
        meanDistance += (points[indices ? (*indices)[k] : k] - centroid).norm();
    meanDistance /= std::max(n, 1);
    // A single point (or coincident points) keeps unit scale: only the centring is defined.
    const double scale = meanDistance > 1e-12 ? std::sqrt(2.0) / meanDistance : 1.0;
    return Eigen::Vector3d(scale, centroid.x(), centroid.y());
}

Eigen::Vector2d applySimilarity(const Eigen::Vector3d& n, const Eigen::Vector2d& x)
{
    return n(0) * (x - n.tail<2>());
}

} // namespace

bool lineNullSpace(const Eigen::Vector3d& l1, const Eigen::Vector3d& l2, const CameraPose& view2,
                   Eigen::Vector4d& qa, Eigen::Vector4d& qb)
{
    // The planes of views 1 and 2 meet in a line only if their normals are not parallel.
    const Eigen::Vector3d n2 = view2.R.transpose() * l2;
    if (!(l1.cross(n2).norm() > 1e-10 * l1.norm() * n2.norm()))
        return false;
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R0 = view2.R;
    generated::lineNullSpace(l1.data(), l2.data(), R0.data(), view2.t.data(), qa.data(), qb.data());
    return qa.allFinite() && qb.allFinite();
}

ConstraintMatrix buildConstraintMatrix(const TripletData& data, double translationScale,
                                       const std::vector<int>* pointIndices, const std::vector<int>* lineIndices)
{
    const int numPoints = pointIndices ? (int)pointIndices->size() : data.numPoints();
    const int numLines = lineIndices ? (int)lineIndices->size() : data.numLines();
    CameraPose view2 = data.view2;
    view2.t /= translationScale;

    ConstraintMatrix A(4 * numPoints + 2 * numLines, 12);
    int row = 0;
    if (numPoints > 0)
    {
        const Eigen::Vector3d n1 = normalizingSimilarity(data.points1, pointIndices);
        const Eigen::Vector3d n2 = normalizingSimilarity(data.points2, pointIndices);
        const Eigen::Vector3d n3 = normalizingSimilarity(data.points3, pointIndices);
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R0 = view2.R;
        for (int k = 0; k < numPoints; ++k)
        {
            const int i = pointIndices ? (*pointIndices)[k] : k;
            const Eigen::Vector2d x1 = applySimilarity(n1, data.points1[i]);
            const Eigen::Vector2d x2 = applySimilarity(n2, data.points2[i]);
            const Eigen::Vector2d x3 = applySimilarity(n3, data.points3[i]);
            generated::pointRows(x1.data(), x2.data(), x3.data(), n1.data(), n2.data(), n3.data(),
                                 R0.data(), view2.t.data(), A.row(row).data());
            // Balance: a point's rows (rank 2) get the weight of a line's two unit rows, so that
            // neither kind dominates the conditioning of A^T A whatever the normalising scales.
            const double blockNorm = A.middleRows(row, 4).norm();
            if (blockNorm > 0)
                A.middleRows(row, 4) *= std::sqrt(2.0) / blockNorm;
            row += 4;
        }
    }
    for (int k = 0; k < numLines; ++k)
    {
        const int i = lineIndices ? (*lineIndices)[k] : k;
        Eigen::Vector4d qa, qb;
        if (!lineNullSpace(data.lines1[i], data.lines2[i], view2, qa, qb))
        {
            // A line in an epipolar plane of views 1-2 has no 3D position: it contributes nothing.
            A.middleRows(row, 2).setZero();
        }
        else
        {
            const Eigen::Vector3d l3 = data.lines3[i].normalized(); // unit rows: q and l3 are unit vectors
            generated::lineRows(qa.data(), qb.data(), l3.data(), A.row(row).data());
        }
        row += 2;
    }
    return A;
}

} // namespace detail
} // namespace tripose
} // namespace cv
