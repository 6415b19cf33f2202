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

/** Two points of the 3D line of views 1-2, as the null-space pair of the line rows: where the rays
of the view-1 end points meet the plane of view 2, X = lambda [x; 1], written as q = [x; 1; 1/lambda]
(X / lambda). Any two points of the line span the same null space, so exact data gives the same
rows; this pair makes each row (R x + t / lambda) . l3 = (depth in view 3 / lambda) times the
distance of the projected end point to l3 (calibrated units), close to a geometric residual.

The depth lambda inherits the noise of l2 amplified by 1 / sin(beta), beta the angle between the
ray and the plane of view 2, and a depth error moves the projection in view 3 by about sin(alpha)
times as much, alpha the triangulation angle at X (views 1-2 stand in for views 1-3, unknown
here). Against the floor of the noise of l3 itself, the row's standard deviation is therefore
proportional to sqrt(1 + (sin alpha / sin beta)^2): @p weights receives its inverse per row.
Returns false when a ray is nearly parallel to the plane or meets it behind view 1.
*/
bool lineEndPoints(const TripletData& data, int line, const CameraPose& view2, Eigen::Vector4d& qa, Eigen::Vector4d& qb,
                   double weights[2])
{
    const Eigen::Vector3d normal2 = view2.R.transpose() * data.lines2[line];
    const double offset2 = view2.t.dot(data.lines2[line]);
    const Eigen::Vector3d centre2 = -view2.R.transpose() * view2.t;
    Eigen::Vector4d* q[2] = { &qa, &qb };
    for (int end = 0; end < 2; ++end)
    {
        const Eigen::Vector3d ray = data.calibratedLineEnd(0, line, end).homogeneous();
        const double denominator = normal2.dot(ray);
        const double lambda = -offset2 / denominator;
        const double sinBeta = std::abs(denominator) / (normal2.norm() * ray.norm());
        if (!(sinBeta > 1e-6) || !(lambda > 0) || !std::isfinite(lambda))
            return false;
        *q[end] << ray, 1.0 / lambda;
        const Eigen::Vector3d X = lambda * ray;
        const double sinAlpha = ray.normalized().cross((X - centre2).normalized()).norm();
        weights[end] = sinBeta / std::sqrt(sinBeta * sinBeta + sinAlpha * sinAlpha);
    }
    return true;
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
    const bool overdetermined = numPoints + numLines >= 6;
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
        // Over-determined systems take the noise-weighted end points; with four or five features
        // the kernel does not depend on the pair of points, and the orthonormal pair conditions it best.
        Eigen::Vector4d qa, qb;
        double weights[2] = { 1.0, 1.0 };
        const bool weighted = overdetermined && lineEndPoints(data, i, view2, qa, qb, weights);
        if (!weighted && !lineNullSpace(data.lines1[i], data.lines2[i], view2, qa, qb))
        {
            // A line in an epipolar plane of views 1-2 has no 3D position: it contributes nothing.
            A.middleRows(row, 2).setZero();
        }
        else
        {
            // Weighted rows read as image distances: l3 with unit normal. Otherwise unit rows
            // (q and l3 unit vectors) condition the small systems best.
            const Eigen::Vector3d l3 = weighted ? Eigen::Vector3d(data.lines3[i] / data.lines3[i].head<2>().norm())
                                                : Eigen::Vector3d(data.lines3[i].normalized());
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

} // namespace detail
} // namespace tripose
} // namespace cv
