// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <complex>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "../generated/affine_constraints.hpp"
#include "affine_kernel_solutions.hpp"

namespace tripose {

namespace {

typedef Eigen::MatrixXd MatrixXd;
typedef Eigen::Matrix<double, 20, Eigen::Dynamic, Eigen::RowMajor, 20, 28> QuadricMatrix;

const int kMaxDimension = 6;
// Highest exponent of a variable in any monomial looked up (the Macaulay matrix has degree 3).
const int kMaxExponent = 3;

/** A linear form l(c) = sum_k w_k c_k separating the solutions by value: any generic weights do
(two solutions with equal l(s) have probability zero); fixed ones keep the solver deterministic.
*/
const double kFormWeights[kMaxDimension] = { 0.7213, -0.4571, 0.9032, -0.2718, 0.5387, -0.8164 };

//! Exponents of a monomial in c_1..c_d (zero beyond d).
typedef std::array<int, kMaxDimension> Exponent;

int degreeOf(const Exponent& e)
{
    int sum = 0;
    for (int x : e)
        sum += x;
    return sum;
}

Exponent unitExponent(int k)
{
    Exponent e = {};
    e[k] = 1;
    return e;
}

Exponent shifted(Exponent e, int k)
{
    ++e[k];
    return e;
}

//! Position of each monomial in a list of exponents, by a dense table over exponents 0..kMaxExponent.
class MonomialIndex
{
public:
    explicit MonomialIndex(const std::vector<Exponent>& exponents) : table_(kTableSize, -1)
    {
        for (size_t i = 0; i < exponents.size(); ++i)
            table_[key(exponents[i])] = (int)i;
    }

    //! Row of @p e, -1 when absent.
    int find(const Exponent& e) const
    {
        for (int x : e)
            if (x > kMaxExponent)
                return -1;
        return table_[key(e)];
    }

private:
    static const int kTableSize = 4096; // (kMaxExponent + 1)^kMaxDimension

    static int key(const Exponent& e)
    {
        int k = 0;
        for (int j = kMaxDimension - 1; j >= 0; --j)
            k = k * (kMaxExponent + 1) + e[j];
        return k;
    }

    std::vector<int> table_;
};

//! The column order of the generated C: [c_k^2, c_k c_l (k < l, lexicographic), c_k, 1].
std::vector<Exponent> quadricMonomials(int d)
{
    std::vector<Exponent> out;
    for (int k = 0; k < d; ++k)
        out.push_back(shifted(unitExponent(k), k));
    for (int k = 0; k < d; ++k)
        for (int l = k + 1; l < d; ++l)
            out.push_back(shifted(unitExponent(k), l));
    for (int k = 0; k < d; ++k)
        out.push_back(unitExponent(k));
    out.push_back(Exponent());
    return out;
}

QuadricMatrix constraintMatrix(const Vector12d& v0, const AffineKernelBasis& basis)
{
    const int d = (int)basis.cols();
    QuadricMatrix C(20, d * (d + 3) / 2 + 1);
    // The basis is column-major: its columns are the concatenated e_k the kernels expect.
    switch (d)
    {
    case 1: generated::affineConstraintsD1(v0.data(), basis.data(), C.data()); break;
    case 2: generated::affineConstraintsD2(v0.data(), basis.data(), C.data()); break;
    case 3: generated::affineConstraintsD3(v0.data(), basis.data(), C.data()); break;
    case 4: generated::affineConstraintsD4(v0.data(), basis.data(), C.data()); break;
    case 5: generated::affineConstraintsD5(v0.data(), basis.data(), C.data()); break;
    default: generated::affineConstraintsD6(v0.data(), basis.data(), C.data()); break;
    }
    return C;
}

/** @p count rows of @p M chosen greedily, each the one with the largest component orthogonal to
those already chosen (the pivots of a column-pivoted QR of M^T): a well-conditioned square block.
*/
std::vector<int> pivotRows(MatrixXd M, int count)
{
    std::vector<int> chosen;
    for (int n = 0; n < count; ++n)
    {
        int best = 0;
        const double norm = M.rowwise().norm().maxCoeff(&best);
        if (!(norm > 0))
            break;
        chosen.push_back(best);
        const Eigen::RowVectorXd u = M.row(best) / norm;
        M -= (M * u.transpose()) * u;
    }
    return chosen;
}

/** The real solutions c whose monomial vectors span the columns of @p W (rows: the monomials
@p exponents; one column per solution). For a basis B of monomials whose products with every c_k
are rows too, each solution s with m(s) = W a satisfies W[l B] a = l(s) W[B] a (l the linear form
of kFormWeights): the eigenvectors of W[B]^-1 W[l B] are the solutions' a, and c is read off the
linear monomials of W a relative to the constant one.
*/
void eigenSolutions(const MatrixXd& W, const std::vector<Exponent>& exponents, int d,
                    std::vector<Eigen::VectorXd>& solutions)
{
    const int r = (int)W.cols();
    const MonomialIndex index(exponents);
    std::vector<int> closed;
    for (size_t i = 0; i < exponents.size(); ++i)
    {
        bool inside = true;
        for (int k = 0; k < d && inside; ++k)
            inside = index.find(shifted(exponents[i], k)) >= 0;
        if (inside)
            closed.push_back((int)i);
    }
    MatrixXd closedRows(closed.size(), r);
    for (size_t i = 0; i < closed.size(); ++i)
        closedRows.row(i) = W.row(closed[i]);
    const std::vector<int> pivots = pivotRows(closedRows, r);
    if ((int)pivots.size() < r)
        return;
    MatrixXd WB(r, r), WlB = MatrixXd::Zero(r, r);
    for (int i = 0; i < r; ++i)
    {
        const Exponent& e = exponents[closed[pivots[i]]];
        WB.row(i) = W.row(closed[pivots[i]]);
        for (int k = 0; k < d; ++k)
            WlB.row(i) += kFormWeights[k] * W.row(index.find(shifted(e, k)));
    }
    const Eigen::FullPivLU<MatrixXd> lu(WB);
    if (!lu.isInvertible())
        return;
    const Eigen::EigenSolver<MatrixXd> eigen(lu.solve(WlB));
    if (eigen.info() != Eigen::Success)
        return;
    const int one = index.find(Exponent());
    const Eigen::MatrixXcd Wc = W.cast<std::complex<double>>();
    for (int j = 0; j < r; ++j)
    {
        const std::complex<double> value = eigen.eigenvalues()(j);
        // Complex pairs are no poses; a real one comes out with rounding in its imaginary part.
        if (std::abs(value.imag()) > 1e-6 * std::max(1.0, std::abs(value)))
            continue;
        const Eigen::VectorXcd m = Wc * eigen.eigenvectors().col(j);
        // A vanishing constant monomial is a solution at infinity.
        if (!(std::abs(m(one)) > 1e-12 * m.cwiseAbs().maxCoeff()))
            continue;
        Eigen::VectorXd c(d);
        for (int k = 0; k < d; ++k)
            c(k) = (m(index.find(unitExponent(k))) / m(one)).real();
        if (c.allFinite())
            solutions.push_back(c);
    }
}

//! d <= 5: the monomials as unknowns of C m = 0 (see solveAffineKernel()).
void solveLinearised(const QuadricMatrix& C, int d, int count, std::vector<Eigen::VectorXd>& solutions)
{
    const int cols = (int)C.cols();
    if (count == 1)
    {
        // Minimum norm: for two points seen in both views with a feature seen once, C has null
        // vectors on the quadratic monomials only, and the linear ones are still unique.
        const Eigen::JacobiSVD<MatrixXd> svd(C.leftCols(cols - 1), Eigen::ComputeThinU | Eigen::ComputeThinV);
        const Eigen::VectorXd m = svd.solve(-C.col(cols - 1));
        if (m.allFinite())
            solutions.push_back(m.tail(d));
        return;
    }
    const Eigen::JacobiSVD<MatrixXd> svd(C, Eigen::ComputeFullV);
    eigenSolutions(svd.matrixV().rightCols(count), quadricMonomials(d), d, solutions);
}

/** d = 6: the eigenproblem on the null space W of the degree-3 Macaulay matrix (the twenty
quadrics times 1, c_1..c_6; 140 x 84). W has dimension 8 and holds the monomial vectors of the
affine solutions, plus, when fewer than 8 are affine (a line seen in both time-B views; two
points and a line), vectors of solutions at infinity, which vanish on every monomial of degree
<= 2. W Z, Z the leading @p count right singular vectors of W restricted to those rows, keeps the
affine part, and the eigenproblem then uses only the rows where the solutions at infinity vanish
(degree <= 2; all rows when all 8 are affine).
*/
void solveMinimal(const QuadricMatrix& C, int count, std::vector<Eigen::VectorXd>& solutions)
{
    const int d = kMaxDimension;
    const std::vector<Exponent> quadrics = quadricMonomials(d);
    std::vector<Exponent> columns;
    Exponent e = {};
    for (e[0] = 0; e[0] <= 3; ++e[0])
        for (e[1] = 0; e[1] <= 3; ++e[1])
            for (e[2] = 0; e[2] <= 3; ++e[2])
                for (e[3] = 0; e[3] <= 3; ++e[3])
                    for (e[4] = 0; e[4] <= 3; ++e[4])
                        for (e[5] = 0; e[5] <= 3; ++e[5])
                            if (degreeOf(e) <= 3)
                                columns.push_back(e);
    // Highest degree first (the order only has to be fixed).
    std::stable_sort(columns.begin(), columns.end(),
                     [](const Exponent& a, const Exponent& b) { return degreeOf(a) > degreeOf(b); });
    const MonomialIndex index(columns);

    MatrixXd M = MatrixXd::Zero(20 * (d + 1), columns.size());
    for (int shift = 0; shift <= d; ++shift)
        for (int q = 0; q < 20; ++q)
            for (size_t m = 0; m < quadrics.size(); ++m)
            {
                const Exponent product = shift == 0 ? quadrics[m] : shifted(quadrics[m], shift - 1);
                M(20 * shift + q, index.find(product)) += C(q, m);
            }
    // The null space from a column-pivoted QR of M^T: the trailing columns of Q are orthogonal to
    // the 76 rows it pivots on, which span M's row space (8 solutions, counted with those at
    // infinity, whatever the noise). Backward stable like an SVD, at a fraction of its cost.
    const Eigen::ColPivHouseholderQR<MatrixXd> qr(M.transpose());
    const int nullity = 8;
    MatrixXd tail = MatrixXd::Zero(M.cols(), nullity);
    tail.bottomRows(nullity).setIdentity();
    const MatrixXd W = qr.householderQ() * tail;

    std::vector<int> low;
    for (size_t i = 0; i < columns.size(); ++i)
        if (degreeOf(columns[i]) <= 2)
            low.push_back((int)i);
    MatrixXd Wlow(low.size(), W.cols());
    for (size_t i = 0; i < low.size(); ++i)
        Wlow.row(i) = W.row(low[i]);
    const Eigen::JacobiSVD<MatrixXd> svdLow(Wlow, Eigen::ComputeThinV);
    const MatrixXd WZ = W * svdLow.matrixV().leftCols(count);

    if (count == 8)
    {
        eigenSolutions(WZ, columns, d, solutions);
        return;
    }
    MatrixXd rows(low.size(), count);
    std::vector<Exponent> lowColumns;
    for (size_t i = 0; i < low.size(); ++i)
    {
        rows.row(i) = WZ.row(low[i]);
        lowColumns.push_back(columns[low[i]]);
    }
    eigenSolutions(rows, lowColumns, d, solutions);
}

} // namespace

int solveAffineKernel(const Vector12d& v0, const AffineKernelBasis& basis, int count, std::vector<Vector12d>& solutions)
{
    const int d = (int)basis.cols();
    TRIPOSE_ASSERT(d >= 1 && d <= kMaxDimension && count >= 1);
    const QuadricMatrix C = constraintMatrix(v0, basis);
    if (!C.allFinite())
        return 0;
    std::vector<Eigen::VectorXd> coefficients;
    if (d <= 5)
        solveLinearised(C, d, count, coefficients);
    else
        solveMinimal(C, count, coefficients);
    for (const Eigen::VectorXd& c : coefficients)
        solutions.push_back(v0 + basis * c);
    return (int)coefficients.size();
}

} // namespace tripose
