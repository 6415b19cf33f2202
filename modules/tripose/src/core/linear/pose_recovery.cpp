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

#include "pose_recovery.hpp"

#include "../geometry/rotation.hpp"

namespace tripose {

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
        const Eigen::Matrix3d next = rotateLeft(step, pose.R);
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

} // namespace tripose
