// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Eigenvalues>

#include "smallest_eigenvectors.hpp"

namespace cv {
namespace tripose {
namespace detail {

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
    Eigen::SelfAdjointEigenSolver<Matrix9d> values;
    values.computeFromTridiagonal(d, e, Eigen::EigenvaluesOnly);
    if (values.info() != Eigen::Success)
        return fullDecomposition(S, vectors);
    const Vector9d& lambda = values.eigenvalues();
    const double norm = std::max(lambda.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
    const double tiny = std::numeric_limits<double>::epsilon() * norm;

    Eigen::Matrix<double, 9, 2> Y;
    for (int k = 0; k < 2; ++k)
    {
        const ShiftedTridiagonalLU lu(d, e, lambda(k), tiny);
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
        if (!y.allFinite() || !(residual(d, e, y, lambda(k)) <= 1e-8 * norm + (k == 1 ? lambda(1) - lambda(0) : 0.0)))
            return fullDecomposition(S, vectors);
        Y.col(k) = y;
    }
    vectors = tridiagonal.matrixQ() * Y;
    return vectors.allFinite();
}

} // namespace detail
} // namespace tripose
} // namespace cv
