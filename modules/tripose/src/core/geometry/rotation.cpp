// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "rotation.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace tripose {

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

} // namespace tripose
