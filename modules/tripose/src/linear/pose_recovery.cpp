// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "pose_recovery.hpp"

namespace cv {
namespace tripose {
namespace detail {

Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& M)
{
    if (M.determinant() > 0)
    {
        // Newton's iteration for the orthogonal polar factor, X <- (g X + X^-T / g) / 2 with
        // Higham's norm scaling g while far from it: quadratic convergence to the same rotation as
        // U V^T of the SVD, at a fraction of the cost of a 3x3 SVD. det > 0 keeps it in SO(3).
        Eigen::Matrix3d X = M;
        for (int iteration = 0; iteration < 30; ++iteration)
        {
            const Eigen::Matrix3d Xinv = X.inverse();
            const double scale = std::sqrt(Xinv.norm() / X.norm());
            const bool far = std::abs(scale - 1.0) > 1e-3;
            const Eigen::Matrix3d next = far ? Eigen::Matrix3d(0.5 * (scale * X + Xinv.transpose() / scale))
                                             : Eigen::Matrix3d(0.5 * (X + Xinv.transpose()));
            const double change = (next - X).norm();
            X = next;
            if (!std::isfinite(change))
                break;
            // Quadratic convergence: after a change of 1e-9 the iterate is orthogonal to rounding.
            // A numerically singular M (rank 2, its determinant positive by rounding alone) can
            // converge to a reflection: the inverses carry the sign of rounding errors. The SVD
            // below then gives the nearest rotation.
            if (change <= 1e-9)
            {
                if (X.determinant() > 0)
                    return X;
                break;
            }
        }
    }
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d U = svd.matrixU();
    const Eigen::Matrix3d V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0)
        U.col(2) = -U.col(2);
    return U * V.transpose();
}

bool reduceNormalMatrix(const Matrix12d& normalMatrix, ReducedNormalSystem& system)
{
    Eigen::LDLT<Eigen::Matrix3d> ldlt(normalMatrix.block<3, 3>(9, 9));
    const Eigen::Vector3d d = ldlt.vectorD();
    if (ldlt.info() != Eigen::Success || !(d.minCoeff() > 1e-12 * std::max(d.maxCoeff(), 1e-300)))
        return false;
    system.T = -ldlt.solve(normalMatrix.block<3, 9>(9, 0));
    system.S = normalMatrix.topLeftCorner<9, 9>() + normalMatrix.block<9, 3>(0, 9).lazyProduct(system.T);
    // Rounding leaves S slightly asymmetric; the eigen-solver reads one triangle, the polish both.
    system.S = (0.5 * (system.S + system.S.transpose())).eval();
    return system.S.allFinite() && system.T.allFinite();
}

bool poseFromSolutionVector(const Vector12d& v, const ReducedNormalSystem& system, CameraPose& pose)
{
    // v stacks the columns of R: column-major storage is exactly R.
    const Eigen::Map<const Eigen::Matrix3d> Rraw(v.data());
    const double det = Rraw.determinant();
    const double scaleNorm = Rraw.squaredNorm();
    // Relative test: det of a rotation scaled by s is s^3 while its squared norm is 3 s^2.
    if (!std::isfinite(det) || !(std::abs(det) > 1e-9 * std::pow(scaleNorm / 3.0, 1.5)))
        return false;
    pose.R = nearestRotation(Rraw / std::cbrt(det));
    pose.t = system.T * Eigen::Map<const Vector9d>(pose.R.data());
    return pose.t.allFinite() && pose.R.allFinite();
}

namespace {

//! Below this step (rad) the polish keeps its Gauss-Newton matrix (see polishPoseAlgebraic()).
constexpr double kChordStepAngle = 1e-2;

} // namespace

void polishPoseAlgebraic(const ReducedNormalSystem& system, CameraPose& pose)
{
    const Matrix9d& S = system.S;
    Vector9d r = Eigen::Map<const Vector9d>(pose.R.data());
    Vector9d Sr = S.lazyProduct(r); // kept from the error evaluation for the next gradient
    double error = r.dot(Sr);
    Eigen::Matrix3d Hinv = Eigen::Matrix3d::Zero(); // set in the first iteration
    double lastAngle = HUGE_VAL;
    for (int iteration = 0; iteration < 5 && error > 0; ++iteration)
    {
        // d r_j / d w = -[r_j]x for the columns r_j of R.
        Eigen::Matrix<double, 9, 3> D;
        for (int j = 0; j < 3; ++j)
            D.block<3, 3>(3 * j, 0) = -skew(pose.R.col(j));
        // The Gauss-Newton matrix D^T S D changes with R by about the last step: once the steps
        // are small (near the minimum) the previous one serves (a chord step), which saves its
        // 9x9x3 product; convergence stays superlinear as the steps shrink.
        const bool fresh = lastAngle > kChordStepAngle;
        if (fresh)
        {
            // lazyProduct: coefficient-wise products beat Eigen's blocked GEMM at these sizes.
            const Eigen::Matrix3d H = D.transpose().lazyProduct(S.lazyProduct(D));
            // 3x3 symmetric positive (semi-)definite: the closed-form inverse is the cheapest
            // solve; a singular H gives a non-finite step, which ends the polish.
            Hinv = H.inverse();
        }
        const Eigen::Vector3d step = -(Hinv * (D.transpose() * Sr));
        if (!step.allFinite())
            break;
        const double angle = step.norm();
        const Eigen::Matrix3d next = angle > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, step / angle) * pose.R) : pose.R;
        const Vector9d rNext = Eigen::Map<const Vector9d>(next.data());
        const Vector9d SrNext = S.lazyProduct(rNext);
        const double nextError = rNext.dot(SrNext);
        if (!(nextError < error))
        {
            if (fresh)
                break;
            lastAngle = HUGE_VAL; // a stale matrix may be the cause: retry with a fresh one
            continue;
        }
        pose.R = next;
        lastAngle = angle;
        r = rNext;
        Sr = SrNext;
        // Converged once a step gains nothing measurable.
        const bool converged = error - nextError <= 1e-12 * error;
        error = nextError;
        if (converged)
            break;
    }
    pose.t = system.T * r;
}

} // namespace detail
} // namespace tripose
} // namespace cv
