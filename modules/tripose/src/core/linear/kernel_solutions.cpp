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

#include "../generated/beta_constraints.hpp"
#include "../generated/beta_n4.hpp"
#include "kernel_solutions.hpp"
#include "polynomial_roots.hpp"

namespace tripose {

namespace {

constexpr double kNearlyRealTolerance = 1e-2;

//! Coefficients from the quadratic monomials b_i b_j (i <= j, symmetric matrix B of b b^T up to
//! scale): the largest diagonal entry is the most reliable square root.
template <int N>
Eigen::Matrix<double, N, 1> coefficientsFromMonomials(const Eigen::Matrix<double, N, N>& B)
{
    int pivot = 0;
    B.diagonal().maxCoeff(&pivot);
    Eigen::Matrix<double, N, 1> beta;
    const double root = std::sqrt(std::max(B(pivot, pivot), 0.0));
    if (root == 0)
        return Eigen::Matrix<double, N, 1>::Zero();
    for (int i = 0; i < N; ++i)
        beta(i) = B(pivot, i) / root;
    return beta;
}

int solveN2(const Eigen::Matrix<double, 12, 2>& basis, std::vector<Vector12d>& solutions)
{
    Eigen::Matrix<double, 5, 3, Eigen::RowMajor> C;
    generated::betaConstraintsN2(basis.col(0).data(), basis.col(1).data(), C.data());
    // Null vector from the 3x3 Gram matrix in closed form: a fraction of the cost of a 5x3 SVD.
    // Its squared conditioning only costs digits that the polish of every candidate restores.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(C.transpose() * C);
    Eigen::Vector3d m = eigen.eigenvectors().col(0); // [b1^2, b2^2, b1 b2]
    if (m(0) + m(1) < 0)
        m = -m;
    Eigen::Matrix2d B;
    B << m(0), m(2), m(2), m(1);
    const Eigen::Vector2d beta = coefficientsFromMonomials<2>(B);
    if (beta.isZero())
        return 0;
    solutions.push_back(basis * beta);
    return 1;
}

int solveN3(const Eigen::Matrix<double, 12, 3>& basis, std::vector<Vector12d>& solutions)
{
    Eigen::Matrix<double, 6, 6, Eigen::RowMajor> C;
    generated::betaConstraintsN3(basis.col(0).data(), basis.col(1).data(), basis.col(2).data(), C.data());
    Eigen::Matrix<double, 6, 1> rhs;
    rhs << 0, 0, 0, 1, 1, 1;
    const Eigen::Matrix<double, 6, 1> m = C.colPivHouseholderQr().solve(rhs); // b1², b2², b3², b1b2, b1b3, b2b3
    if (!m.allFinite())
        return 0;
    Eigen::Matrix3d B;
    B << m(0), m(3), m(4),
         m(3), m(1), m(5),
         m(4), m(5), m(2);
    const Eigen::Vector3d beta = coefficientsFromMonomials<3>(B);
    if (beta.isZero())
        return 0;
    solutions.push_back(basis * beta);
    return 1;
}

//! The five homogeneous orthonormality constraints on v = [r1; r2; r3; t]: r1.r2, r2.r3, r3.r1,
//! |r1|^2 - |r2|^2, |r2|^2 - |r3|^2.
Eigen::Matrix<double, 5, 1> orthonormalityResiduals(const Vector12d& v)
{
    const Eigen::Map<const Eigen::Matrix3d> R(v.data());
    Eigen::Matrix<double, 5, 1> e;
    e << R.col(0).dot(R.col(1)), R.col(1).dot(R.col(2)), R.col(2).dot(R.col(0)),
         R.col(0).squaredNorm() - R.col(1).squaredNorm(), R.col(1).squaredNorm() - R.col(2).squaredNorm();
    return e;
}

/** Gauss-Newton on the five constraints over (b1, b2, b3) with b4 = 1. The root of the degree-11
polynomial locates the solution, but its accuracy suffers from the conditioning of the polynomial;
a few steps on the constraints themselves restore full precision (exact data: quadratic convergence
to the true coefficients) and, with noise, lower the algebraic error the method minimises anyway.
A step is kept only if it lowers the residual.
*/
Eigen::Vector3d polishN4(const Eigen::Matrix<double, 12, 4>& basis, Eigen::Vector3d b)
{
    auto solution = [&basis](const Eigen::Vector3d& c) -> Vector12d {
        return basis.leftCols<3>() * c + basis.col(3);
    };
    Vector12d v = solution(b);
    Eigen::Matrix<double, 5, 1> e = orthonormalityResiduals(v);
    for (int iteration = 0; iteration < 5; ++iteration)
    {
        const Eigen::Map<const Eigen::Matrix3d> R(v.data());
        Eigen::Matrix<double, 5, 3> J;
        for (int k = 0; k < 3; ++k)
        {
            const Eigen::Map<const Eigen::Matrix3d> D(basis.col(k).data());
            J(0, k) = D.col(0).dot(R.col(1)) + R.col(0).dot(D.col(1));
            J(1, k) = D.col(1).dot(R.col(2)) + R.col(1).dot(D.col(2));
            J(2, k) = D.col(2).dot(R.col(0)) + R.col(2).dot(D.col(0));
            J(3, k) = 2 * (D.col(0).dot(R.col(0)) - D.col(1).dot(R.col(1)));
            J(4, k) = 2 * (D.col(1).dot(R.col(1)) - D.col(2).dot(R.col(2)));
        }
        const Eigen::Vector3d step = (J.transpose() * J).ldlt().solve(J.transpose() * e);
        if (!step.allFinite())
            break;
        const Eigen::Vector3d next = b - step;
        const Vector12d vNext = solution(next);
        const Eigen::Matrix<double, 5, 1> eNext = orthonormalityResiduals(vNext);
        if (!(eNext.squaredNorm() < e.squaredNorm()))
            break;
        b = next;
        v = vNext;
        e = eNext;
    }
    return b;
}

int solveN4(const Eigen::Matrix<double, 12, 4>& basis, std::vector<Vector12d>& solutions)
{
    double u[26], p[12], roots[11];
    generated::betaN4NullVector(basis.data(), u);
    generated::betaN4Polynomial(u, p);
    // Nearly real complex roots are kept too: where the polynomial is ill conditioned the root
    // of the true solution can drift off the real axis, and the polishing below brings it back.
    const int numRoots = solveNearlyRealPolynomialRoots(p, 11, roots, kNearlyRealTolerance);
    // Packed null vector: u1..u3 degree 4 (5 coefficients each), u4, u5 degree 3, u6 degree 2.
    const double* u4 = u + 15;
    const double* u5 = u + 19;
    const double* u6 = u + 23;
    int added = 0;
    for (int i = 0; i < numRoots; ++i)
    {
        const double b3 = roots[i];
        const double w = evaluatePolynomial(u6, 2, b3);
        if (!(std::abs(w) > 0))
            continue;
        const Eigen::Vector3d b = polishN4(basis, Eigen::Vector3d(evaluatePolynomial(u4, 3, b3) / w,
                                                                 evaluatePolynomial(u5, 3, b3) / w, b3));
        const Vector12d v = basis.leftCols<3>() * b + basis.col(3);
        if (!v.allFinite())
            continue;
        solutions.push_back(v);
        ++added;
    }
    return added;
}

} // namespace

int solveKernelCombinations(const Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 4>& basis,
                            std::vector<Vector12d>& solutions)
{
    switch (basis.cols())
    {
    case 1: solutions.push_back(basis.col(0)); return 1;
    case 2: return solveN2(basis, solutions);
    case 3: return solveN3(basis, solutions);
    case 4: return solveN4(basis, solutions);
    default: fail(ErrorCode::Internal, "kernel dimension must be 1 to 4");
    }
}

} // namespace tripose
