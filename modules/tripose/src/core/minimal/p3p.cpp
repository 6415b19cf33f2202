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

#include "p3p.hpp"

namespace tripose {

namespace {

// Sine of the angle below which two bearings, or the two sides X1X2 and X1X3, are taken as parallel.
constexpr double kParallelSine = 1e-8;
constexpr int kPolishIterations = 5;

//! tr(adj(A) B) for symmetric A: the coefficient that is linear in B of det(A + B).
double mixedDeterminant(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B)
{
    return A.col(1).cross(A.col(2)).dot(B.col(0)) + A.col(2).cross(A.col(0)).dot(B.col(1)) +
           A.col(0).cross(A.col(1)).dot(B.col(2));
}

//! The largest real root of c3 g^3 + c2 g^2 + c1 g + c0 (c3 != 0), polished by Newton's method.
double largestCubicRoot(double c3, double c2, double c1, double c0)
{
    const double a = c2 / c3, b = c1 / c3, c = c0 / c3;
    // g = x - a/3 gives x^3 + p x + q = 0.
    const double p = b - a * a / 3.0;
    const double q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c;
    const double disc = 0.25 * q * q + p * p * p / 27.0;
    double x;
    if (disc > 0)
    {
        const double s = std::sqrt(disc);
        x = std::cbrt(-0.5 * q + s) + std::cbrt(-0.5 * q - s);
    }
    else
    {
        // Three real roots (p <= 0): the trigonometric form, its largest branch.
        const double r = std::sqrt(std::max(0.0, -p / 3.0));
        const double cosine = r > 0 ? std::max(-1.0, std::min(1.0, -0.5 * q / (r * r * r))) : 1.0;
        x = 2.0 * r * std::cos(std::acos(cosine) / 3.0);
    }
    double g = x - a / 3.0;
    for (int i = 0; i < 2; ++i)
    {
        const double f = ((g + a) * g + b) * g + c;
        const double df = (3.0 * g + 2.0 * a) * g + b;
        if (df == 0)
            break;
        g -= f / df;
    }
    return g;
}

//! The directions (u, w) with Q00 u^2 + 2 Q01 u w + Q11 w^2 = 0; returns how many (0 or 2).
int homogeneousQuadraticRoots(double q00, double q01, double q11, Eigen::Vector2d roots[2])
{
    double disc = q01 * q01 - q00 * q11;
    if (disc < 0)
    {
        // A double root perturbed by rounding still gives the (near-)solution.
        if (disc < -1e-12 * (q01 * q01 + std::abs(q00 * q11)))
            return 0;
        disc = 0;
    }
    const double k = -(q01 + std::copysign(std::sqrt(disc), q01));
    if (std::abs(q00) >= std::abs(q11))
    {
        if (q00 == 0)
            return 0;
        // Roots of u/w: k / q00 and q11 / k (the product of the roots is q11 / q00).
        roots[0] = Eigen::Vector2d(k / q00, 1.0);
        roots[1] = k != 0 ? Eigen::Vector2d(q11 / k, 1.0) : roots[0];
    }
    else
    {
        roots[0] = Eigen::Vector2d(1.0, k / q11);
        roots[1] = k != 0 ? Eigen::Vector2d(1.0, q00 / k) : roots[0];
    }
    return 2;
}

} // namespace

int solveP3P(const Eigen::Vector3d bearings[3], const Eigen::Vector3d points[3], std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d y1 = bearings[0].normalized(), y2 = bearings[1].normalized(), y3 = bearings[2].normalized();
    const Eigen::Vector3d d12 = points[0] - points[1], d13 = points[0] - points[2];
    const Eigen::Vector3d normal = d12.cross(d13);
    const double a12 = d12.squaredNorm(), a13 = d13.squaredNorm(), a23 = (points[1] - points[2]).squaredNorm();
    if (!(normal.norm() > kParallelSine * std::sqrt(a12 * a13)) || !y1.allFinite() || !y2.allFinite() || !y3.allFinite())
        return 0;
    const double b12 = y1.dot(y2), b13 = y1.dot(y3), b23 = y2.dot(y3);
    const double maxCosine = std::sqrt(1.0 - kParallelSine * kParallelSine);
    if (std::abs(b12) > maxCosine || std::abs(b13) > maxCosine || std::abs(b23) > maxCosine)
        return 0;

    Eigen::Matrix3d M12, M13, M23;
    M12 << 1, -b12, 0, -b12, 1, 0, 0, 0, 0;
    M13 << 1, 0, -b13, 0, 0, 0, -b13, 0, 1;
    M23 << 0, 0, 0, 0, 1, -b23, 0, -b23, 1;
    const Eigen::Matrix3d D1 = a23 * M12 - a12 * M23;
    const Eigen::Matrix3d D2 = a23 * M13 - a13 * M23;

    // det(D1 + g D2) = c3 g^3 + c2 g^2 + c1 g + c0. A (nearly) singular D2 is the root g = infinity.
    const double c3 = D2.determinant(), c2 = mixedDeterminant(D2, D1), c1 = mixedDeterminant(D1, D2);
    const double c0 = D1.determinant();
    const double scale = std::max(std::max(std::abs(c3), std::abs(c2)), std::max(std::abs(c1), std::abs(c0)));
    if (!(scale > 0) || !std::isfinite(scale))
        return 0;
    Eigen::Matrix3d D0;
    if (std::abs(c3) > 1e-10 * scale)
        D0 = D1 + largestCubicRoot(c3, c2, c1, c0) * D2;
    else
        D0 = D2;

    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(D0);
    const Eigen::Vector3d sigma = eigen.eigenvalues();
    const Eigen::Matrix3d E = eigen.eigenvectors();
    int k0 = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(sigma(i)) < std::abs(sigma(k0)))
            k0 = i;
    // The eigenvalues are sorted: with the kernel's one removed, 'lo' <= 'hi'.
    const int lo = k0 == 0 ? 1 : 0, hi = k0 == 2 ? 1 : 2;
    const Eigen::Vector3d v0 = E.col(k0);

    // The planes of the degenerate quadric D0 (a single line, v0, when it is semi-definite).
    Eigen::Vector3d directions[4];
    int numDirections = 0;
    if (sigma(lo) < 0 && sigma(hi) > 0)
    {
        const double s = std::sqrt(-sigma(lo) / sigma(hi));
        const Eigen::Matrix3d& Dq = D1.norm() >= D2.norm() ? D1 : D2;
        for (int sign = -1; sign <= 1; sign += 2)
        {
            const Eigen::Vector3d n = E.col(hi) + sign * s * E.col(lo);
            const Eigen::Vector3d w = n.cross(v0).normalized();
            const Eigen::Vector3d Dv0 = Dq * v0, Dw = Dq * w;
            Eigen::Vector2d uw[2];
            const int m = homogeneousQuadraticRoots(v0.dot(Dv0), v0.dot(Dw), w.dot(Dw), uw);
            for (int i = 0; i < m; ++i)
                directions[numDirections++] = uw[i](0) * v0 + uw[i](1) * w;
        }
    }
    else
        directions[numDirections++] = v0;

    const Eigen::Matrix3d Msum = M12 + M13 + M23;
    const double aSum = a12 + a13 + a23;
    const Eigen::Matrix3d Dworld = (Eigen::Matrix3d() << d12, d13, normal).finished();
    const Eigen::Matrix3d DworldInv = Dworld.inverse();
    int count = 0;
    for (int i = 0; i < numDirections; ++i)
    {
        const double denominator = directions[i].dot(Msum * directions[i]);
        if (!(denominator > 0))
            continue;
        Eigen::Vector3d L = std::sqrt(aSum / denominator) * directions[i];
        if (L.sum() < 0)
            L = -L;
        // Gauss-Newton on the three distance equations L^T M_ij L = a_ij.
        for (int it = 0; it < kPolishIterations; ++it)
        {
            const Eigen::Vector3d r(L.dot(M12 * L) - a12, L.dot(M13 * L) - a13, L.dot(M23 * L) - a23);
            if (r.cwiseAbs().maxCoeff() < 1e-15 * aSum)
                break;
            Eigen::Matrix3d J;
            J.row(0) = 2.0 * (M12 * L).transpose();
            J.row(1) = 2.0 * (M13 * L).transpose();
            J.row(2) = 2.0 * (M23 * L).transpose();
            const double det = J.determinant();
            if (!(std::abs(det) > 0))
                break;
            L -= J.inverse() * r;
        }
        if (!(L.minCoeff() > 0) || !L.allFinite())
            continue;
        const Eigen::Vector3d e12 = L(0) * y1 - L(1) * y2, e13 = L(0) * y1 - L(2) * y3;
        const Eigen::Matrix3d Dcamera = (Eigen::Matrix3d() << e12, e13, e12.cross(e13)).finished();
        // Exact solutions give a rotation; rounding is removed through the unit quaternion.
        const Eigen::Quaterniond q(Eigen::Matrix3d(Dcamera * DworldInv));
        CameraPose pose;
        pose.R = q.normalized().toRotationMatrix();
        pose.t = L(0) * y1 - pose.R * points[0];
        if (!pose.allFinite())
            continue;
        poses.push_back(pose);
        ++count;
    }
    return count;
}

} // namespace tripose
