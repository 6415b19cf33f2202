// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/Dense>

#include "../geometry/plane_fit.hpp"
#include "line_end_points.hpp"
#include "planar_kernel_solutions.hpp"

namespace tripose {

namespace {

// Thickness of the structure (standard deviation across its best plane) relative to its extent
// within the plane, below which the structure counts as planar. Exact data triangulates to about
// 1e-13 of the extent; image noise of a tenth of a pixel at the paper's geometry leaves about 1e-4.
constexpr double kPlanarTolerance = 1e-6;
// Relative thickness below which noisy data may come from planar structure, whose kernel the general
// combinations misread: pixel-level noise on planar scenes leaves a few hundredths (large motion,
// after trimming; doc/studies/accuracy.md), while structure in general position is near 1.
constexpr double kNearPlanarTolerance = 0.1;
// Rounds of trimming the positions far from the plane before judging near-planarity, and the
// relative thickness of all positions above which no trimming is tried (general structure).
constexpr int kTrimRounds = 3;
constexpr double kTrimGate = 0.5;

// Relative singular value below which a direction of the restricted system counts as a kernel
// direction (as kRankTolerance of the general case: rounding leaves about 1e-15).
constexpr double kKernelTolerance = 1e-9;

//! Rotation block of a solution vector: columns r1, r2, r3.
Eigen::Matrix3d rotationBlock(const Vector12d& w)
{
    return Eigen::Map<const Eigen::Matrix3d>(w.data());
}

/** Appends the rotations (as solution vectors with t = 0) whose action on the plane's directions
e1, e2 matches the rotation block @p M up to a common scale, for both signs of that scale.
*/
int appendPlanarRotations(const Eigen::Matrix3d& M, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                          std::vector<Vector12d>& solutions)
{
    const Eigen::Vector3d a = M * e1, b = M * e2;
    const double scale = std::sqrt(0.5 * (a.squaredNorm() + b.squaredNorm()));
    if (!(scale > 0) || !std::isfinite(scale))
        return 0;
    Eigen::Matrix3d frame;
    frame << e1, e2, e1.cross(e2);
    int added = 0;
    for (const double sign : { 1.0, -1.0 })
    {
        Eigen::Matrix3d images;
        images << sign * a, sign * b, a.cross(b) / scale;
        Vector12d v = Vector12d::Zero();
        Eigen::Map<Eigen::Matrix3d>(v.data()) = images * frame.transpose();
        if (!v.allFinite())
            continue;
        solutions.push_back(v);
        ++added;
    }
    return added;
}

/** Calls @p visit with every position of the structure the selected features have in views 1-2:
points triangulated from views 1-2, each line by two of its points. False when a feature has none.
*/
template <typename Visit>
bool visitStructure(const ViewSet& set, const CameraPose& pose12, const std::vector<int>* pointIndices,
                    const std::vector<int>* lineIndices, Visit&& visit)
{
    const int numPoints = pointIndices ? (int)pointIndices->size() : set.numPoints;
    const int numLines = lineIndices ? (int)lineIndices->size() : set.numLines;
    const std::vector<Eigen::Vector2d>& points1 = set.views[ViewSet::kView1].calibratedPoints;
    const std::vector<Eigen::Vector2d>& points2 = set.views[ViewSet::kView2].calibratedPoints;
    for (int k = 0; k < numPoints; ++k)
    {
        const int i = pointIndices ? (*pointIndices)[k] : k;
        // X = lambda x1 with lambda minimising |x2 x (lambda R12 x1 + t12)|.
        const Eigen::Vector3d x1 = points1[i].homogeneous(), x2 = points2[i].homogeneous();
        const Eigen::Vector3d a = x2.cross(pose12.R * x1), b = x2.cross(pose12.t);
        const double denominator = a.squaredNorm();
        if (!(denominator > 0))
            return false;
        visit(Eigen::Vector3d(-a.dot(b) / denominator * x1));
    }
    for (int k = 0; k < numLines; ++k)
    {
        const int i = lineIndices ? (*lineIndices)[k] : k;
        Eigen::Vector4d qa, qb;
        double weights[2];
        if (!lineEndPoints(set, i, pose12, qa, qb, weights))
            return false;
        visit(Eigen::Vector3d(qa.head<3>() / qa(3)));
        visit(Eigen::Vector3d(qb.head<3>() / qb(3)));
    }
    return true;
}

} // namespace

StructureFlatness structurePlane(const ViewSet& set, const CameraPose& pose12, const std::vector<int>* pointIndices,
                                 const std::vector<int>* lineIndices, Eigen::Vector4d& plane)
{
    // Planar to rounding: every position counts.
    PlaneAccumulator all;
    Plane fit;
    if (!visitStructure(set, pose12, pointIndices, lineIndices, [&](const Eigen::Vector3d& X) { all.add(X); }) ||
        !all.fit(fit))
        return STRUCTURE_GENERAL;
    // A line of structure (second extent near zero too) lies on many planes and fixes none.
    if (!(fit.extents(1) > kPlanarTolerance * kPlanarTolerance * fit.extents(2)))
        return STRUCTURE_GENERAL;
    StructureFlatness flatness = STRUCTURE_PLANAR;
    if (!(fit.extents(0) <= kPlanarTolerance * kPlanarTolerance * fit.extents(1)))
    {
        if (!(fit.extents(0) <= kTrimGate * kTrimGate * fit.extents(1)))
            return STRUCTURE_GENERAL;
        // Near a plane: judged on the bulk of the positions (trimPlaneFit()). They are computed a
        // second time here rather than stored by the first pass, which every call makes and which
        // then needs no allocation.
        std::vector<Eigen::Vector3d> structure;
        visitStructure(set, pose12, pointIndices, lineIndices,
                       [&](const Eigen::Vector3d& X) { structure.push_back(X); });
        if (!trimPlaneFit(structure, kTrimRounds, fit) ||
            !(fit.extents(0) <= kNearPlanarTolerance * kNearPlanarTolerance * fit.extents(1)) ||
            !(fit.extents(1) > kPlanarTolerance * kPlanarTolerance * fit.extents(2)))
            return STRUCTURE_GENERAL;
        flatness = STRUCTURE_NEAR_PLANAR;
    }
    plane << fit.normal, -fit.normal.dot(fit.centre);
    return plane.allFinite() ? flatness : STRUCTURE_GENERAL;
}

int planarKernelSolutions(const ConstraintMatrix& A, const Eigen::Vector4d& plane, std::vector<Vector12d>& solutions)
{
    // The family a pi^T: column j of P3 = [r1 r2 r3 t] moves by pi_j a, so its basis vectors are
    // pi_j at entries 3 j + i (i = 0..2), mutually orthogonal.
    Eigen::Matrix<double, 12, 3> family = Eigen::Matrix<double, 12, 3>::Zero();
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i)
            family(3 * j + i, i) = plane(j);
    const Eigen::HouseholderQR<Eigen::Matrix<double, 12, 3>> qr(family);
    const Eigen::Matrix<double, 12, 9> complement =
        (qr.householderQ() * Eigen::Matrix<double, 12, 12>::Identity()).rightCols<9>();

    // At least nine rows (zero rows added): with fewer constraints than unknowns (four lines: eight
    // rows) the missing singular values are zeros, part of the kernel.
    Eigen::Matrix<double, Eigen::Dynamic, 9> restricted =
        Eigen::Matrix<double, Eigen::Dynamic, 9>::Zero(std::max<Eigen::Index>(A.rows(), 9), 9);
    restricted.topRows(A.rows()).noalias() = A * complement;
    const Eigen::JacobiSVD<Eigen::Matrix<double, Eigen::Dynamic, 9>> svd(restricted, Eigen::ComputeFullV);
    const Eigen::Matrix<double, 9, 1> singular = svd.singularValues();
    if (!(singular(0) > 0) || !singular.allFinite())
        return 0;
    // Near-planar data (noise below kPlanarTolerance) leaves no exact kernel: the best direction.
    int kernel = 1;
    while (kernel < 9 && singular(8 - kernel) <= kKernelTolerance * singular(0))
        ++kernel;
    if (kernel > 2)
        return 0;

    const Eigen::Vector3d normal = plane.head<3>().normalized();
    const Eigen::Vector3d e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    const Vector12d w1 = complement * svd.matrixV().col(8);
    if (kernel == 1)
        return appendPlanarRotations(rotationBlock(w1), e1, e2, solutions);

    // Two kernel vectors: w = b1 w1 + b2 w2 with M(w) an isometry on the plane's directions up to
    // scale. Each condition is a quadric in [b1^2, b1 b2, b2^2]; their common root is the null
    // vector of the 2x3 system, the cross product of its rows.
    const Vector12d w2 = complement * svd.matrixV().col(7);
    const Eigen::Matrix3d M1 = rotationBlock(w1), M2 = rotationBlock(w2);
    const Eigen::Vector3d a1 = M1 * e1, b1 = M1 * e2, a2 = M2 * e1, b2 = M2 * e2;
    const Eigen::Vector3d equalNorms(a1.dot(a1) - b1.dot(b1), 2 * (a1.dot(a2) - b1.dot(b2)), a2.dot(a2) - b2.dot(b2));
    const Eigen::Vector3d orthogonal(a1.dot(b1), a1.dot(b2) + a2.dot(b1), a2.dot(b2));
    const Eigen::Vector3d monomials = equalNorms.cross(orthogonal);
    if (!(monomials.norm() > 0) || !monomials.allFinite())
        return 0;
    // [b1^2, b1 b2, b2^2] = s [b1, b2] b1 = s [b1, b2] b2: read the ratio from the larger square.
    const Eigen::Vector2d beta = std::abs(monomials(0)) >= std::abs(monomials(2)) ? monomials.head<2>()
                                                                                    : monomials.tail<2>();
    return appendPlanarRotations(beta(0) * M1 + beta(1) * M2, e1, e2, solutions);
}

} // namespace tripose
