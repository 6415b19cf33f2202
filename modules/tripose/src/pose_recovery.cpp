// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "pose_recovery.hpp"

namespace cv {
namespace tripose {
namespace detail {

Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& M)
{
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d U = svd.matrixU();
    const Eigen::Matrix3d V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0)
        U.col(2) = -U.col(2);
    return U * V.transpose();
}

bool poseFromSolutionVector(const Vector12d& v, const Matrix12d& normalMatrix, CameraPose& pose)
{
    // v stacks the columns of R: column-major storage is exactly R.
    const Eigen::Map<const Eigen::Matrix3d> Rraw(v.data());
    const double det = Rraw.determinant();
    const double scaleNorm = Rraw.squaredNorm();
    // Relative test: det of a rotation scaled by s is s^3 while its squared norm is 3 s^2.
    if (!std::isfinite(det) || !(std::abs(det) > 1e-9 * std::pow(scaleNorm / 3.0, 1.5)))
        return false;
    pose.R = nearestRotation(Rraw / std::cbrt(det));

    const Eigen::Matrix3d Att = normalMatrix.block<3, 3>(9, 9);
    const Eigen::Matrix<double, 3, 9> Atr = normalMatrix.block<3, 9>(9, 0);
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> r(pose.R.data());
    Eigen::LDLT<Eigen::Matrix3d> ldlt(Att);
    const Eigen::Vector3d d = ldlt.vectorD();
    if (ldlt.info() != Eigen::Success || !(d.minCoeff() > 1e-12 * std::max(d.maxCoeff(), 1e-300)))
        return false;
    pose.t = -ldlt.solve(Atr * r);
    return pose.t.allFinite() && pose.R.allFinite();
}

namespace {

double algebraicError(const Matrix12d& M, const CameraPose& pose, Vector12d& v)
{
    v << Eigen::Map<const Eigen::Matrix<double, 9, 1>>(pose.R.data()), pose.t;
    return v.dot(M * v);
}

Eigen::Matrix3d skew(const Eigen::Vector3d& a)
{
    Eigen::Matrix3d S;
    S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    return S;
}

} // namespace

void polishPoseAlgebraic(const Matrix12d& normalMatrix, CameraPose& pose)
{
    Vector12d v;
    double error = algebraicError(normalMatrix, pose, v);
    for (int iteration = 0; iteration < 5 && error > 0; ++iteration)
    {
        // d r_j / d w = -[r_j]x for the columns r_j of R; d t / d t = I.
        Eigen::Matrix<double, 12, 6> D = Eigen::Matrix<double, 12, 6>::Zero();
        for (int j = 0; j < 3; ++j)
            D.block<3, 3>(3 * j, 0) = -skew(pose.R.col(j));
        D.block<3, 3>(9, 3).setIdentity();
        // lazyProduct: coefficient-wise products beat Eigen's blocked GEMM at these sizes.
        const Eigen::Matrix<double, 6, 12> DtM = D.transpose().lazyProduct(normalMatrix);
        const Eigen::Matrix<double, 6, 6> H = DtM.lazyProduct(D);
        const Eigen::Matrix<double, 6, 1> step = H.ldlt().solve(-(DtM * v));
        if (!step.allFinite())
            return;
        CameraPose next;
        const double angle = step.head<3>().norm();
        next.R = angle > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, step.head<3>() / angle) * pose.R) : pose.R;
        next.t = pose.t + step.tail<3>();
        Vector12d vNext;
        const double nextError = algebraicError(normalMatrix, next, vNext);
        if (!(nextError < error))
            return;
        pose = next;
        v = vNext;
        // Converged once a step gains nothing measurable.
        const bool converged = error - nextError <= 1e-12 * error;
        error = nextError;
        if (converged)
            return;
    }
}

} // namespace detail
} // namespace tripose
} // namespace cv
