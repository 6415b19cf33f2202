// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "rotation.hpp"

#include <algorithm>
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

Eigen::Vector3d rotationVector(const Eigen::Matrix3d& R)
{
    // 2 sin(angle) axis is the vee of R - R^T; with cos(angle) from the trace, atan2 gives the angle
    // to full precision away from a half turn, where the axis comes from the symmetric part instead.
    const Eigen::Vector3d v(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
    const double cosine = std::max(-1.0, std::min(1.0, 0.5 * (R.trace() - 1.0)));
    if (cosine < 0)
    {
        const Eigen::AngleAxisd rotation(R);
        return rotation.angle() * rotation.axis();
    }
    const double sine = 0.5 * v.norm();
    const double angle = std::atan2(sine, cosine);
    return sine > 1e-15 ? Eigen::Vector3d(v * (0.5 * angle / sine)) : Eigen::Vector3d(0.5 * v);
}

} // namespace tripose
