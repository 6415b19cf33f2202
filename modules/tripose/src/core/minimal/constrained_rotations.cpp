// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "constrained_rotations.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "incidences.hpp"
#include "sturm_roots.hpp"

namespace tripose {

namespace {

// Relative size below which the whole eliminant is rounding.
constexpr double kVanishing = 1e-10;
// Relative size of a constraint's dependence on beta below which it is solved as free of beta. Near
// that limit (nearly parallel lines) pairs of roots of the eliminant merge and may turn complex,
// whereas the beta-free solution is off by about this size and the caller's Newton polish, which
// converges quadratically, removes that.
constexpr double kNearlyFreeOfBeta = 1e-4;

using Quadratic = Eigen::Vector3d;             // ascending coefficients in s
using Quartic = Eigen::Matrix<double, 5, 1>;
using Octic = Eigen::Matrix<double, 9, 1>;

//! (1 + s^2) (A ca + B sa + C) with ca = (1 - s^2) / (1 + s^2), sa = 2 s / (1 + s^2).
Quadratic halfAngleForm(double A, double B, double C)
{
    return Quadratic(A + C, 2.0 * B, C - A);
}

Quartic multiply(const Quadratic& f, const Quadratic& g)
{
    Quartic h = Quartic::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            h(i + j) += f(i) * g(j);
    return h;
}

Octic multiply(const Quartic& f, const Quartic& g)
{
    Octic h = Octic::Zero();
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            h(i + j) += f(i) * g(j);
    return h;
}

//! The matrix M of one constraint (see the header): [ca sa 1] M [cb sb 1]^T = tr(G'^T Rz Rx).
Eigen::Matrix3d trigonometricForm(const Eigen::Matrix3d& Gp)
{
    Eigen::Matrix3d M;
    M << Gp(1, 1), -Gp(1, 2), Gp(0, 0), -Gp(0, 1), Gp(0, 2), Gp(1, 0), Gp(2, 2), Gp(2, 1), 0.0;
    return M;
}

Eigen::Matrix3d rotationZ(double c, double s)
{
    Eigen::Matrix3d R;
    R << c, -s, 0, s, c, 0, 0, 0, 1;
    return R;
}

Eigen::Matrix3d rotationX(double c, double s)
{
    Eigen::Matrix3d R;
    R << 1, 0, 0, 0, c, -s, 0, s, c;
    return R;
}

//! The betas with p cb + q sb + w = 0 (up to two), as (cb, sb).
int solveOnCircle(double p, double q, double w, Eigen::Vector2d out[2])
{
    const double r = std::hypot(p, q);
    if (!(r > 0))
        return 0;
    double cosine = -w / r;
    // A tangent circle perturbed by rounding still gives the (near-)solution; Newton polishes it.
    if (std::abs(cosine) > 1.0)
    {
        if (std::abs(cosine) > 1.0 + 1e-9)
            return 0;
        cosine = std::copysign(1.0, cosine);
    }
    const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    const Eigen::Vector2d axis(p / r, q / r), normal(-q / r, p / r);
    out[0] = cosine * axis + sine * normal;
    out[1] = cosine * axis - sine * normal;
    return sine > 0 ? 2 : 1;
}

} // namespace

Eigen::Matrix3d rotationTakingToZ(const Eigen::Vector3d& a)
{
    const Eigen::Vector3d c1 = orthogonalUnitVector(a);
    Eigen::Matrix3d C;
    C.row(0) = c1.transpose();
    C.row(1) = a.cross(c1).transpose();
    C.row(2) = a.transpose();
    return C;
}

int solveConstrainedRotations(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Matrix3d& G1,
                              const Eigen::Matrix3d& G2, Eigen::Matrix3d rotations[8])
{
    const Eigen::Matrix3d C = rotationTakingToZ(a);
    // W maps b to e1: the rows of rotationTakingToZ(b), cycled.
    const Eigen::Matrix3d Wz = rotationTakingToZ(b);
    Eigen::Matrix3d W;
    W << Wz.row(2), Wz.row(0), Wz.row(1);
    const Eigen::Matrix3d M[2] = { trigonometricForm(C * G1 * W.transpose()),
                                   trigonometricForm(C * G2 * W.transpose()) };
    const double norms[2] = { M[0].norm(), M[1].norm() };
    if (!(norms[0] > 0) || !(norms[1] > 0) || !std::isfinite(norms[0] * norms[1]))
        return 0;

    int count = 0;
    auto append = [&](double ca, double sa, double cb, double sb) {
        rotations[count++] = C.transpose() * rotationZ(ca, sa) * rotationX(cb, sb) * W;
    };

    // A constraint free of beta fixes alpha by itself.
    for (int k = 0; k < 2; ++k)
    {
        if (M[k].block<3, 2>(0, 0).norm() > kNearlyFreeOfBeta * norms[k])
            continue;
        const Eigen::Vector2d direction(M[k](1, 2), -M[k](0, 2));
        const double length = direction.norm();
        if (!(length > kVanishing * norms[k]))
            return 0;
        const Eigen::Matrix3d& other = M[1 - k];
        for (int sign = -1; sign <= 1; sign += 2)
        {
            const Eigen::Vector2d cs = sign * direction / length;
            const Eigen::RowVector3d row = Eigen::RowVector3d(cs(0), cs(1), 1.0) * other;
            Eigen::Vector2d betas[2];
            const int m = solveOnCircle(row(0), row(1), row(2), betas);
            for (int i = 0; i < m; ++i)
                append(cs(0), cs(1), betas[i](0), betas[i](1));
        }
        return count;
    }

    Quadratic p[2], q[2], w[2];
    for (int k = 0; k < 2; ++k)
    {
        p[k] = halfAngleForm(M[k](0, 0), M[k](1, 0), M[k](2, 0));
        q[k] = halfAngleForm(M[k](0, 1), M[k](1, 1), M[k](2, 1));
        w[k] = halfAngleForm(M[k](0, 2), M[k](1, 2), M[k](2, 2));
    }
    const Quartic D = multiply(p[0], q[1]) - multiply(p[1], q[0]);
    const Quartic Dc = multiply(q[0], w[1]) - multiply(w[0], q[1]);
    const Quartic Ds = multiply(p[1], w[0]) - multiply(p[0], w[1]);
    const Octic eliminant = multiply(Dc, Dc) + multiply(Ds, Ds) - multiply(D, D);
    // Each coefficient is a sum of products of two entries of M1 and two of M2.
    if (!(eliminant.cwiseAbs().maxCoeff() > kVanishing * norms[0] * norms[0] * norms[1] * norms[1]))
        return 0;

    double roots[8];
    const int numRoots = solveRealRootsSturm(eliminant.data(), 8, roots);
    for (int i = 0; i < numRoots; ++i)
    {
        const double s = roots[i], s2 = s * s;
        const double ca = (1.0 - s2) / (1.0 + s2), sa = 2.0 * s / (1.0 + s2);
        const Eigen::RowVector3d trig(ca, sa, 1.0);
        const Eigen::RowVector3d r1 = trig * M[0], r2 = trig * M[1];
        const double det = r1(0) * r2(1) - r2(0) * r1(1);
        const Eigen::Vector2d cs(r1(1) * r2(2) - r1(2) * r2(1), r2(0) * r1(2) - r1(0) * r2(2));
        // Where the two constraints are dependent (D = Dc = Ds = 0) the root gives no beta.
        const double length = cs.norm();
        if (!(length > 0) || !(std::abs(det) > 0))
            continue;
        const Eigen::Vector2d beta = std::copysign(1.0, det) * cs / length;
        append(ca, sa, beta(0), beta(1));
    }
    return count;
}

} // namespace tripose
