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
#include <Eigen/Geometry>

#include "affine_kernel_solutions.hpp"
#include "pose_recovery.hpp"
#include "rig_solver.hpp"
#include "rig_system.hpp"
#include "rotation_polish.hpp"
#include "../geometry/rotation.hpp"

namespace tripose {

namespace {

/** Relative size of the smallest singular value A must keep outside its expected kernel. Exact
data in general position stays orders of magnitude above it; below it the features do not fix the
pose (collinear points, a line with no parallax at time B) and the kernel is wider than its count.
*/
constexpr double kRankTolerance = 1e-12;

/** Determinant of the over-determined solution's rotation block, divided by the cube of its scale,
beyond which its sign alone fixes the sign of the solution: 1 for a scaled rotation, near 0 where
noise leaves the block far from one. */
constexpr double kClearDeterminant = 0.5;

struct ScoredCandidate
{
    CameraPose pose;
    double residual;
};

/** The algebraic error |A v - b|^2 of a pose with t at its least-squares value for R, in the
triangular factor of the system: |B r - beta|^2, B and beta the rotation columns and the right-hand
side with the span of the translation columns projected out. Read by polishRotation().
*/
struct ReducedRigSystem
{
    Eigen::Matrix<double, 12, 9> B;
    Vector12d beta;

    double evaluate(const Eigen::Matrix<double, 9, 1>& r, Eigen::Matrix<double, 9, 1>& halfGradient) const
    {
        const Vector12d residual = B * r - beta;
        halfGradient = B.transpose() * residual;
        return residual.squaredNorm();
    }
    Eigen::Matrix3d gaussNewtonMatrix(const Eigen::Matrix<double, 9, 3>& D) const
    {
        const Eigen::Matrix<double, 12, 3> J = B * D;
        return J.transpose() * J;
    }
};

//! Steps of the polish: where the kernel combinations are ill-conditioned (two solutions close
//! together, a minimal problem near a degenerate one) its start is only near the minimum.
constexpr int kPolishIterations = 10;

} // namespace

int rigPoseCandidates(const ViewSet& set, std::vector<CameraPose>& poses, const std::vector<int>* pointIndices,
                      const std::vector<int>* lineIndices)
{
    RigSystem system;
    if (!buildRigSystem(set, pointIndices, lineIndices, system))
        return 0;
    const int d = rigKernelDimension(system.counts);
    const int count = rigSolutionCount(system.counts, d);
    if (count == 0 || system.A.rows() < 12 - d || !system.A.allFinite() || !system.b.allFinite())
        return 0;

    // Everything below needs A only through A^T A and A^T b: the triangular factor R of a QR of
    // [A b] holds both (A v - b has the norm of [R_A v - c; rho]) at 12 x 13 whatever the number
    // of rows. Zero rows pad short systems to a square factor.
    const int rows = std::max((int)system.A.rows(), 13);
    Eigen::Matrix<double, Eigen::Dynamic, 13> Ab = Eigen::Matrix<double, Eigen::Dynamic, 13>::Zero(rows, 13);
    Ab.topLeftCorner(system.A.rows(), 12) = system.A;
    Ab.col(12).head(system.A.rows()) = system.b;
    const Eigen::HouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 13>> qr(Ab);
    const Matrix12d R = qr.matrixQR().topLeftCorner<12, 12>().triangularView<Eigen::Upper>();
    const Vector12d c = qr.matrixQR().col(12).head<12>();

    std::vector<Vector12d> solutions;
    if (d == 0)
    {
        // Over-determined (the common case): v = R^-1 c, the rank judged on the diagonal of a
        // column-pivoted QR of R, a fraction of the cost of the SVD the kernel case needs.
        const Eigen::ColPivHouseholderQR<Matrix12d> pivoted(R);
        const double largest = std::abs(pivoted.matrixQR()(0, 0)), smallest = std::abs(pivoted.matrixQR()(11, 11));
        if (!(largest > 0) || !(smallest > kRankTolerance * largest))
            return 0;
        // The rig's translation fixes the scale of v only through the constant term, weakly for a
        // short baseline at a long depth: noise can leave v near -lambda v_true, whose nearest
        // rotation is turned by about pi. The sign of the rotation block's determinant tells (a
        // rotation has +1 times the cube of its scale, a negated one -1) unless the block is far
        // from a scaled rotation; then both signs go to the selection, where cheirality decides.
        const Vector12d v = pivoted.solve(c);
        const Eigen::Map<const Eigen::Matrix3d> block(v.data());
        const double scale = block.norm() / std::sqrt(3.0);
        const double det = block.determinant() / (scale * scale * scale);
        solutions.push_back(det < 0 ? Vector12d(-v) : v);
        if (!(std::abs(det) > kClearDeterminant))
            solutions.push_back(det < 0 ? v : Vector12d(-v));
    }
    else
    {
        const Eigen::JacobiSVD<Matrix12d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Vector12d s = svd.singularValues();
        const int k = 12 - d;
        if (!(s(0) > 0) || (k > 0 && !(s(k - 1) > kRankTolerance * s(0))))
            return 0;
        Vector12d v0 = Vector12d::Zero();
        for (int i = 0; i < k; ++i)
            v0 += (svd.matrixU().col(i).dot(c) / s(i)) * svd.matrixV().col(i);
        solveAffineKernel(v0, svd.matrixV().rightCols(d), count, solutions);
    }

    // t by least squares with R fixed: R_t t = c - R_r vec(R), R_t the translation columns.
    const Eigen::Matrix<double, 12, 3> Rt = R.rightCols<3>();
    const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 12, 3>> translation(Rt);
    if (translation.rank() < 3)
        return 0;

    ReducedRigSystem reduced;
    const Eigen::Matrix<double, 12, 3> Qt = translation.householderQ() * Eigen::Matrix<double, 12, 3>::Identity();
    reduced.B = R.leftCols<9>() - Qt * (Qt.transpose() * R.leftCols<9>());
    reduced.beta = c - Qt * (Qt.transpose() * c);

    std::vector<ScoredCandidate> candidates;
    for (const Vector12d& v : solutions)
    {
        if (!v.allFinite())
            continue;
        ScoredCandidate candidate;
        candidate.pose.R = nearestRotation(Eigen::Map<const Eigen::Matrix3d>(v.data()));
        polishRotation(reduced, kPolishIterations, candidate.pose.R);
        const Eigen::Map<const Eigen::Matrix<double, 9, 1>> r(candidate.pose.R.data());
        candidate.pose.t = translation.solve(c - R.leftCols<9>() * r);
        Vector12d fitted;
        fitted << r, candidate.pose.t;
        candidate.residual = (R * fitted - c).norm();
        if (!candidate.pose.allFinite() || !std::isfinite(candidate.residual))
            continue;
        candidate.pose.t *= system.translationScale;
        candidates.push_back(candidate);
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const ScoredCandidate& a, const ScoredCandidate& b) { return a.residual < b.residual; });
    for (const ScoredCandidate& candidate : candidates)
        poses.push_back(candidate.pose);
    return (int)candidates.size();
}

} // namespace tripose
