// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <Eigen/Eigenvalues>

#include "smallest_eigenvectors.hpp"

namespace tripose {

namespace {

constexpr int kSize = 9;
typedef Eigen::Matrix<double, kSize, kSize> Matrix9d;
typedef Eigen::Matrix<double, kSize, 1> Vector9d;
typedef Eigen::Matrix<double, kSize - 1, 1> Vector8d;

/** LU factorisation with partial pivoting of T - mu I, T symmetric tridiagonal (diagonal d,
off-diagonal e). Row swaps fill one more super-diagonal, so U has three diagonals u0, u1, u2.
*/
class ShiftedTridiagonalLU
{
public:
    ShiftedTridiagonalLU(const Vector9d& d, const Vector8d& e, double mu, double tiny)
    {
        double sub[kSize];
        for (int i = 0; i < kSize; ++i)
        {
            u0_[i] = d(i) - mu;
            u1_[i] = i + 1 < kSize ? e(i) : 0.0;
            u2_[i] = 0.0;
            sub[i] = i + 1 < kSize ? e(i) : 0.0;
        }
        for (int i = 0; i + 1 < kSize; ++i)
        {
            // Row i holds (u0, u1, u2) in columns i..i+2; row i+1 holds (sub, u0, u1) there.
            swapped_[i] = std::abs(sub[i]) > std::abs(u0_[i]);
            if (swapped_[i])
            {
                std::swap(u0_[i], sub[i]);
                std::swap(u1_[i], u0_[i + 1]);
                std::swap(u2_[i], u1_[i + 1]);
            }
            // An exactly singular pivot (the shift is an eigenvalue to the last bit) is nudged: the
            // solution then grows along the wanted eigenvector, which is all inverse iteration needs.
            if (u0_[i] == 0)
                u0_[i] = tiny;
            multiplier_[i] = sub[i] / u0_[i];
            u0_[i + 1] -= multiplier_[i] * u1_[i];
            u1_[i + 1] -= multiplier_[i] * u2_[i];
        }
        if (u0_[kSize - 1] == 0)
            u0_[kSize - 1] = tiny;
    }

    //! x <- (T - mu I)^-1 x.
    void solve(Vector9d& x) const
    {
        for (int i = 0; i + 1 < kSize; ++i)
        {
            if (swapped_[i])
                std::swap(x(i), x(i + 1));
            x(i + 1) -= multiplier_[i] * x(i);
        }
        for (int i = kSize - 1; i >= 0; --i)
        {
            double s = x(i);
            if (i + 1 < kSize)
                s -= u1_[i] * x(i + 1);
            if (i + 2 < kSize)
                s -= u2_[i] * x(i + 2);
            x(i) = s / u0_[i];
        }
    }

private:
    double u0_[kSize], u1_[kSize], u2_[kSize], multiplier_[kSize];
    bool swapped_[kSize];
};

//! ||T y - lambda y|| for the tridiagonal T (d, e).
double residual(const Vector9d& d, const Vector8d& e, const Vector9d& y, double lambda)
{
    double sum = 0;
    for (int i = 0; i < kSize; ++i)
    {
        double r = (d(i) - lambda) * y(i);
        if (i > 0)
            r += e(i - 1) * y(i - 1);
        if (i + 1 < kSize)
            r += e(i) * y(i + 1);
        sum += r * r;
    }
    return std::sqrt(sum);
}

//! y^T T y for the tridiagonal T (d, e).
double rayleighQuotient(const Vector9d& d, const Vector8d& e, const Vector9d& y)
{
    double q = d(0) * y(0) * y(0);
    for (int i = 1; i < kSize; ++i)
        q += d(i) * y(i) * y(i) + 2.0 * e(i - 1) * y(i - 1) * y(i);
    return q;
}

//! Number of eigenvalues of T (d, e) below x: the negative pivots of the LDL^T factorisation of
//! T - x I (Sylvester's law of inertia).
int eigenvaluesBelow(const Vector9d& d, const Vector8d& e, double x, double tiny)
{
    int count = 0;
    double pivot = d(0) - x;
    for (int i = 0;; ++i)
    {
        if (pivot == 0)
            pivot = -tiny;
        count += pivot < 0;
        if (i + 1 == kSize)
            return count;
        pivot = d(i + 1) - x - e(i) * e(i) / pivot;
    }
}

/** The two smallest eigenvalues of the positive semi-definite tridiagonal T (d, e): inverse
iteration from shift 0 (deflated against the first vector for the second) until the Rayleigh
quotient is near its eigenvalue, then Rayleigh quotient iteration, which converges cubically.
Either may settle on another eigenvalue: the result is kept only if Sturm counts confirm that no
eigenvalue lies below the first and exactly one below the second. Returns false otherwise.
*/
bool smallestTwoEigenvalues(const Vector9d& d, const Vector8d& e, double norm, double lambda[2])
{
    const double tiny = std::numeric_limits<double>::epsilon() * norm;
    Vector9d first;
    for (int k = 0; k < 2; ++k)
    {
        Vector9d y = Vector9d::Ones();
        double rho = 0;
        for (int step = 0; step < 8; ++step)
        {
            if (k == 1)
                y -= first.dot(y) * first;
            y /= y.norm();
            const double next = rayleighQuotient(d, e, y);
            if (step >= 3 && std::abs(next - rho) <= 1e-15 * norm)
            {
                rho = next;
                break;
            }
            rho = next;
            // Three steps at shift 0 bring the vector close to the wanted eigenvector; then the
            // Rayleigh quotient is the shift.
            const ShiftedTridiagonalLU lu(d, e, step < 3 ? 0.0 : rho, tiny);
            lu.solve(y);
            if (!y.allFinite())
                return false;
        }
        if (k == 0)
            first = y;
        lambda[k] = rho;
    }
    const double tolerance = 1e-12 * norm;
    return lambda[0] <= lambda[1] && eigenvaluesBelow(d, e, lambda[0] - tolerance, tiny) == 0 &&
           eigenvaluesBelow(d, e, lambda[1] - tolerance, tiny) == 1 &&
           eigenvaluesBelow(d, e, lambda[1] + tolerance, tiny) >= 2;
}

bool fullDecomposition(const Matrix9d& S, Eigen::Matrix<double, 9, 2>& vectors)
{
    Eigen::SelfAdjointEigenSolver<Matrix9d> eigen(S);
    if (eigen.info() != Eigen::Success)
        return false;
    vectors = eigen.eigenvectors().leftCols<2>();
    return true;
}

} // namespace

bool smallestEigenvectors(const Matrix9d& S, Eigen::Matrix<double, 9, 2>& vectors)
{
    const Eigen::Tridiagonalization<Matrix9d> tridiagonal(S);
    const Vector9d d = tridiagonal.diagonal();
    const Vector8d e = tridiagonal.subDiagonal();
    // Gershgorin bound of the spectral norm.
    double norm = std::numeric_limits<double>::min();
    for (int i = 0; i < kSize; ++i)
        norm = std::max(norm, std::abs(d(i)) + (i > 0 ? std::abs(e(i - 1)) : 0.0) + (i + 1 < kSize ? std::abs(e(i)) : 0.0));
    const double tiny = std::numeric_limits<double>::epsilon() * norm;
    double lambda[2];
    if (!smallestTwoEigenvalues(d, e, norm, lambda))
    {
        // Close or clustered eigenvalues: all of them by the implicit QR of the tridiagonal matrix.
        Eigen::SelfAdjointEigenSolver<Matrix9d> values;
        values.computeFromTridiagonal(d, e, Eigen::EigenvaluesOnly);
        if (values.info() != Eigen::Success)
            return fullDecomposition(S, vectors);
        lambda[0] = values.eigenvalues()(0);
        lambda[1] = values.eigenvalues()(1);
    }

    Eigen::Matrix<double, 9, 2> Y;
    for (int k = 0; k < 2; ++k)
    {
        const ShiftedTridiagonalLU lu(d, e, lambda[k], tiny);
        // Two steps from a vector with no zero component: the shift is accurate to rounding, so
        // each step multiplies the wanted component by about 1 / epsilon over the others.
        Vector9d y = Vector9d::Ones();
        for (int step = 0; step < 2; ++step)
        {
            lu.solve(y);
            y /= y.norm();
        }
        // Close eigenvalues: both iterations land in their common subspace; Gram-Schmidt against
        // the first makes the pair an orthonormal basis of it.
        if (k == 1)
        {
            y -= Y.col(0).dot(y) * Y.col(0);
            y /= y.norm();
        }
        // Eigenvectors to the accuracy of the full decomposition satisfy this by a wide margin.
        if (!y.allFinite() || !(residual(d, e, y, lambda[k]) <= 1e-8 * norm + (k == 1 ? lambda[1] - lambda[0] : 0.0)))
            return fullDecomposition(S, vectors);
        Y.col(k) = y;
    }
    vectors = tridiagonal.matrixQ() * Y;
    return vectors.allFinite();
}

} // namespace tripose
