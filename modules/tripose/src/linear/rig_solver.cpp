// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include <Eigen/Dense>

#include "affine_kernel_solutions.hpp"
#include "pose_recovery.hpp"
#include "rig_solver.hpp"
#include "rig_system.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

/** Relative size of the smallest singular value A must keep outside its expected kernel. Exact
data in general position stays orders of magnitude above it; below it the features do not fix the
pose (collinear points, a line with no parallax at time B) and the kernel is wider than its count.
*/
constexpr double kRankTolerance = 1e-12;

struct ScoredCandidate
{
    CameraPose pose;
    double residual;
};

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

    const Eigen::JacobiSVD<Matrix12d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Vector12d s = svd.singularValues();
    const int k = 12 - d;
    if (!(s(0) > 0) || (k > 0 && !(s(k - 1) > kRankTolerance * s(0))))
        return 0;
    Vector12d v0 = Vector12d::Zero();
    for (int i = 0; i < k; ++i)
        v0 += (svd.matrixU().col(i).dot(c) / s(i)) * svd.matrixV().col(i);

    std::vector<Vector12d> solutions;
    if (d == 0)
        solutions.push_back(v0);
    else
        solveAffineKernel(v0, svd.matrixV().rightCols(d), count, solutions);

    // t by least squares with R fixed: R_t t = c - R_r vec(R), R_t the translation columns.
    const Eigen::Matrix<double, 12, 3> Rt = R.rightCols<3>();
    const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 12, 3>> translation(Rt);
    if (translation.rank() < 3)
        return 0;

    std::vector<ScoredCandidate> candidates;
    for (const Vector12d& v : solutions)
    {
        if (!v.allFinite())
            continue;
        ScoredCandidate candidate;
        candidate.pose.R = nearestRotation(Eigen::Map<const Eigen::Matrix3d>(v.data()));
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

} // namespace detail
} // namespace tripose
} // namespace cv
