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
#include "rotation_polish.hpp"

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

//! r^T S r, the algebraic error with t eliminated, as polishRotation() reads it.
struct ReducedNormalCost
{
    const Matrix9d& S;

    double evaluate(const Vector9d& r, Vector9d& halfGradient) const
    {
        // lazyProduct: coefficient-wise products beat Eigen's blocked GEMM at these sizes.
        halfGradient = S.lazyProduct(r);
        return r.dot(halfGradient);
    }
    Eigen::Matrix3d gaussNewtonMatrix(const Eigen::Matrix<double, 9, 3>& D) const
    {
        return D.transpose().lazyProduct(S.lazyProduct(D));
    }
};

//! Steps of the polish: it starts from the nearest rotation of a kernel solution, near the minimum,
//! where Gauss-Newton converges in a few; the bound caps the cost of a candidate that does not.
constexpr int kPolishIterations = 5;

} // namespace

void polishPoseAlgebraic(const ReducedNormalSystem& system, CameraPose& pose)
{
    const ReducedNormalCost cost = { system.S };
    polishRotation(cost, kPolishIterations, pose.R);
    pose.t = system.T * Eigen::Map<const Vector9d>(pose.R.data());
}

} // namespace tripose
