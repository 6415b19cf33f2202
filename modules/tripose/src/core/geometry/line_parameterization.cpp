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

#include "line_parameterization.hpp"
#include "rotation.hpp"

namespace tripose {

bool OrthonormalLine::fromPlucker(const PluckerLine& line, OrthonormalLine& out)
{
    const double dNorm = line.d.norm(), mNorm = line.m.norm();
    if (!(dNorm > 0) || !std::isfinite(mNorm) || !std::isfinite(dNorm))
        return false;
    const Eigen::Vector3d u2 = line.d / dNorm;
    // Enforce the Plücker constraint m . d = 0 on the way (rounding, inexact inputs).
    Eigen::Vector3d u1 = line.m - u2.dot(line.m) * u2;
    double u1Norm = u1.norm();
    if (!(u1Norm > 1e-300))
    {
        // Line through the origin: the moment vanishes and any normal of d completes the frame.
        u1 = std::abs(u2.x()) < 0.9 ? Eigen::Vector3d::UnitX().cross(u2) : Eigen::Vector3d::UnitY().cross(u2);
        u1Norm = u1.norm();
    }
    const double scale = std::hypot(mNorm, dNorm);
    out.U.col(0) = u1 / u1Norm;
    out.U.col(1) = u2;
    out.U.col(2) = out.U.col(0).cross(u2);
    out.w1 = mNorm / scale;
    out.w2 = dNorm / scale;
    return out.U.allFinite() && std::isfinite(out.w1) && std::isfinite(out.w2);
}

Eigen::Matrix<double, 6, 4> OrthonormalLine::pluckerJacobian() const
{
    // m = w1 u1, d = w2 u2 with u_k = U e_k. Under U <- U Exp(dtheta): du1 = U (dtheta x e1) =
    // [0, -u3, u2] dtheta and du2 = [u3, 0, -u1] dtheta; under the SO(2) increment dw1 = -w2 dphi,
    // dw2 = w1 dphi.
    const auto u1 = U.col(0), u2 = U.col(1), u3 = U.col(2);
    Eigen::Matrix<double, 6, 4> J;
    J.block<3, 1>(0, 0).setZero();
    J.block<3, 1>(0, 1) = -w1 * u3;
    J.block<3, 1>(0, 2) = w1 * u2;
    J.block<3, 1>(0, 3) = -w2 * u1;
    J.block<3, 1>(3, 0) = w2 * u3;
    J.block<3, 1>(3, 1).setZero();
    J.block<3, 1>(3, 2) = -w2 * u1;
    J.block<3, 1>(3, 3) = w1 * u2;
    return J;
}

OrthonormalLine OrthonormalLine::plus(const Eigen::Vector4d& delta) const
{
    OrthonormalLine out;
    out.U = rotateRight(U, delta.head<3>());
    const double c = std::cos(delta(3)), s = std::sin(delta(3));
    out.w1 = c * w1 - s * w2;
    out.w2 = s * w1 + c * w2;
    // Keep w on the unit circle despite rounding over many updates.
    const double n = std::hypot(out.w1, out.w2);
    out.w1 /= n;
    out.w2 /= n;
    return out;
}

bool lineFromPlanes(const Eigen::Vector4d* planes, int count, PluckerLine& line, double minRatio)
{
    TRIPOSE_ASSERT(count >= 2);
    // The line lies in the span of the two dominant right singular vectors p, q of the stacked
    // planes M (count x 4). Up to three planes they come from the small Gram matrix M M^T = U S^2 U^T
    // as M^T u_k, a closed-form 3x3 eigen-decomposition; more planes use M^T M (4x4) directly.
    Eigen::Vector4d p = Eigen::Vector4d::Zero(), q = Eigen::Vector4d::Zero();
    if (count <= 3)
    {
        Eigen::Matrix3d gram = Eigen::Matrix3d::Zero();
        for (int a = 0; a < count; ++a)
            for (int b = 0; b <= a; ++b)
                gram(a, b) = gram(b, a) = planes[a].dot(planes[b]);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(gram);
        const Eigen::Vector3d& lambda = eig.eigenvalues(); // ascending: squared singular values
        if (!(lambda(2) > 0) || !(std::max(lambda(1), 0.0) >= minRatio * minRatio * lambda(2)))
            return false;
        for (int k = 0; k < count; ++k)
        {
            p += eig.eigenvectors()(k, 2) * planes[k];
            q += eig.eigenvectors()(k, 1) * planes[k];
        }
    }
    else
    {
        Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
        for (int k = 0; k < count; ++k)
            normal.noalias() += planes[k] * planes[k].transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(normal);
        const Eigen::Vector4d& lambda = eig.eigenvalues();
        if (eig.info() != Eigen::Success || !(lambda(3) > 0) ||
            !(std::max(lambda(2), 0.0) >= minRatio * minRatio * lambda(3)))
            return false;
        p = eig.eigenvectors().col(3);
        q = eig.eigenvectors().col(2);
    }
    // Intersection of the planes (n_p, e_p) and (n_q, e_q): direction n_p x n_q and moment
    // e_p n_q - e_q n_p (for X on both, X x (n_p x n_q) = n_p (X.n_q) - n_q (X.n_p)).
    line.d = p.head<3>().cross(q.head<3>());
    line.m = p(3) * q.head<3>() - q(3) * p.head<3>();
    return line.d.norm() > 1e-12 * p.head<3>().norm() * q.head<3>().norm() && line.m.allFinite();
}

Eigen::Vector3d closestPointToRay(const PluckerLine& line, const Eigen::Vector3d& ray, const Eigen::Vector3d& origin)
{
    const double dd = line.d.squaredNorm();
    const Eigen::Vector3d foot = line.d.cross(line.m) / dd;
    const Eigen::Vector3d u = line.d / std::sqrt(dd);
    const Eigen::Vector3d r = ray.normalized();
    // Minimise |foot + s u - (origin + lambda r)| over s and lambda.
    const Eigen::Vector3d f = foot - origin;
    const double b = u.dot(r), du = u.dot(f), dr = r.dot(f);
    const double denominator = 1.0 - b * b;
    if (!(denominator > 1e-12))
        return foot;
    const double s = (b * dr - du) / denominator;
    return foot + s * u;
}

} // namespace tripose
