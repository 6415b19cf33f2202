// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The generated coefficient kernels against independent Eigen evaluations of the same equations
// at random inputs. Tolerances are 1e-12 relative to the magnitude of the compared quantity; where
// the quantity is a sum with cancellation (determinants, polynomial values), "magnitude" is the
// size of its terms (Hadamard bound, sum of absolute terms), the largest error a correct double
// evaluation can have.

#include "test_precomp.hpp"

#include <Eigen/Dense>

#include "../src/core/generated/beta_constraints.hpp"
#include "../src/core/generated/beta_n4.hpp"
#include "../src/core/generated/line_rows.hpp"
#include "../src/core/generated/point_rows.hpp"

namespace opencv_test {
namespace {

using namespace ::tripose::generated;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::Vector4d;
typedef Eigen::Matrix<double, 12, 1> Vector12d;
typedef Eigen::Matrix<double, 5, 6> Matrix56d;
typedef Eigen::Matrix<double, 3, 3, Eigen::RowMajor> RowMatrix3d;

const double kTol = 1e-12;

double normal(cv::RNG& rng) { return rng.gaussian(1.0); }

template <int N>
Eigen::Matrix<double, N, 1> randomVector(cv::RNG& rng)
{
    Eigen::Matrix<double, N, 1> x;
    for (int i = 0; i < N; ++i)
        x[i] = normal(rng);
    return x;
}

Matrix3d randomRotation(cv::RNG& rng)
{
    Eigen::HouseholderQR<Matrix3d> qr(Matrix3d(Eigen::Matrix<double, 9, 1>(randomVector<9>(rng)).data()));
    Matrix3d Q = qr.householderQ();
    if (Q.determinant() < 0)
        Q = -Q;
    return Q;
}

Matrix3d skew(const Vector3d& x)
{
    Matrix3d S;
    S << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    return S;
}

//! v = [r1; r2; r3; t] with r_i the columns of R.
Vector12d poseVector(const Matrix3d& R, const Vector3d& t)
{
    Vector12d v;
    v << R.col(0), R.col(1), R.col(2), t;
    return v;
}

Matrix3d similarity(const Vector3d& n)
{
    Matrix3d F;
    F << n[0], 0, -n[0] * n[1], 0, n[0], -n[0] * n[2], 0, 0, 1;
    return F;
}

//! |a - b| <= kTol * scale, entry-wise, with a message naming the entry.
template <typename A, typename B>
void expectNear(const A& actual, const B& expected, double scale, const char* what)
{
    ASSERT_EQ(actual.size(), expected.size());
    for (int i = 0; i < (int)actual.size(); ++i)
        EXPECT_LE(std::abs(actual(i) - expected(i)), kTol * scale)
            << what << " entry " << i << ": " << actual(i) << " vs " << expected(i);
}

TEST(Tripose_GeneratedKernels, lineNullSpace_matches_householder_qr)
{
    cv::RNG rng(101);
    for (int trial = 0; trial < 200; ++trial)
    {
        const Vector3d l1 = randomVector<3>(rng), l2 = randomVector<3>(rng), t12 = randomVector<3>(rng);
        const RowMatrix3d R12 = randomRotation(rng);
        Vector4d qa, qb;
        lineNullSpace(l1.data(), l2.data(), R12.data(), t12.data(), qa.data(), qb.data());

        Eigen::Matrix<double, 4, 2> planes;
        planes.col(0) << l1, 0;
        planes.col(1) << R12.transpose() * l2, t12.dot(l2);
        // The paper's elimination: the last two columns of the Householder Q span the same space.
        const Eigen::Matrix4d Q = Eigen::HouseholderQR<Eigen::Matrix<double, 4, 2>>(planes).householderQ();
        const Eigen::Matrix4d expected = Q.rightCols<2>() * Q.rightCols<2>().transpose();
        Eigen::Matrix<double, 4, 2> basis;
        basis << qa, qb;
        const Eigen::Matrix4d actual = basis * basis.transpose();
        expectNear(actual.reshaped(), expected.reshaped(), 1.0, "null-space projector");
        expectNear((basis.transpose() * basis).reshaped(), Eigen::Matrix2d::Identity().reshaped(), 1.0, "Gram matrix");
        expectNear((planes.transpose() * basis).reshaped(), Eigen::Matrix2d::Zero().reshaped(),
                   planes.cwiseAbs().maxCoeff(), "planes^T q");
    }
}

TEST(Tripose_GeneratedKernels, lineRows_equal_point_on_plane_constraint)
{
    cv::RNG rng(102);
    for (int trial = 0; trial < 200; ++trial)
    {
        const Vector4d qa = randomVector<4>(rng), qb = randomVector<4>(rng);
        const Vector3d l3 = randomVector<3>(rng);
        Eigen::Matrix<double, 2, 12, Eigen::RowMajor> rows;
        lineRows(qa.data(), qb.data(), l3.data(), rows.data());
        for (int k = 0; k < 12; ++k)
        {
            // Row . e_k is q^T pi3 for the P3 = [R|t] whose vector v is e_k.
            Vector12d v = Vector12d::Zero();
            v[k] = 1;
            const Matrix3d R = Eigen::Map<const Matrix3d>(v.data());
            Vector4d pi3;
            pi3 << R.transpose() * l3, v.tail<3>().dot(l3);
            const Eigen::Vector2d expected(qa.dot(pi3), qb.dot(pi3));
            const double scale = std::max(qa.norm(), qb.norm()) * l3.norm();
            expectNear(rows.col(k), expected, scale, "line row");
        }
    }
}

TEST(Tripose_GeneratedKernels, pointRows_equal_normalized_trilinear_matrix)
{
    cv::RNG rng(103);
    for (int trial = 0; trial < 200; ++trial)
    {
        Eigen::Vector2d x[3];
        Vector3d n[3];
        for (int j = 0; j < 3; ++j)
        {
            x[j] = randomVector<2>(rng);
            n[j] << rng.uniform(0.5, 3.0), normal(rng), normal(rng);
        }
        const RowMatrix3d R12 = randomRotation(rng);
        const Vector3d t12 = randomVector<3>(rng);
        Eigen::Matrix<double, 4, 12, Eigen::RowMajor> rows;
        pointRows(x[0].data(), x[1].data(), x[2].data(), n[0].data(), n[1].data(), n[2].data(),
                  R12.data(), t12.data(), rows.data());

        const Matrix3d F = similarity(n[0]), G = similarity(n[1]), H = similarity(n[2]);
        const Vector3d x1 = F.inverse() * x[0].homogeneous();
        for (int k = 0; k < 12; ++k)
        {
            Vector12d v = Vector12d::Zero();
            v[k] = 1;
            const Matrix3d R = Eigen::Map<const Matrix3d>(v.data());
            const Vector3d t = v.tail<3>();
            // E = [x^2]x G ((R12 x1) t^T - t12 (R x1)^T) H^T [x^3]x; eqs. (9)-(12) are -E11, E10, E01, -E00.
            const Matrix3d M = (Matrix3d(R12) * x1) * t.transpose() - t12 * (R * x1).transpose();
            const Matrix3d E = skew(x[1].homogeneous()) * G * M * H.transpose() * skew(x[2].homogeneous());
            const Vector4d expected(-E(1, 1), E(1, 0), E(0, 1), -E(0, 0));
            expectNear(rows.col(k), expected, std::max(1.0, E.cwiseAbs().maxCoeff()), "point row");
        }
    }
}

TEST(Tripose_GeneratedKernels, pointRows_have_rank_two_and_vanish_on_true_pose)
{
    cv::RNG rng(104);
    for (int trial = 0; trial < 100; ++trial)
    {
        const Matrix3d R12 = randomRotation(rng), R = randomRotation(rng);
        const Vector3d t12 = randomVector<3>(rng), t = randomVector<3>(rng);
        const Vector3d X = randomVector<3>(rng) + Vector3d(0, 0, 6);
        const Vector3d X2 = R12 * X + t12, X3 = R * X + t;
        const Eigen::Vector2d p[3] = { X.hnormalized(), X2.hnormalized(), X3.hnormalized() };
        Eigen::Vector2d xh[3];
        Vector3d n[3];
        for (int j = 0; j < 3; ++j)
        {
            n[j] << rng.uniform(0.5, 3.0), normal(rng), normal(rng);
            xh[j] = n[j][0] * (p[j] - n[j].tail<2>());
        }
        const RowMatrix3d R12r = R12;
        Eigen::Matrix<double, 4, 12, Eigen::RowMajor> rows;
        pointRows(xh[0].data(), xh[1].data(), xh[2].data(), n[0].data(), n[1].data(), n[2].data(),
                  R12r.data(), t12.data(), rows.data());
        const Eigen::Vector4d s = Eigen::JacobiSVD<Eigen::Matrix<double, 4, 12>>(rows).singularValues();
        EXPECT_GT(s[1], 1e-6 * s[0]);
        EXPECT_LT(s[2], 1e-12 * s[0]);
        const Vector12d v = poseVector(R, t);
        expectNear(rows * v, Vector4d::Zero(), s[0] * v.norm(), "A v");
    }
}

//! The five homogeneous constraints (N = 2, 4) or the six of N = 3 on v.
Eigen::VectorXd constraints(const Vector12d& v, bool unitNorms)
{
    const Vector3d r1 = v.segment<3>(0), r2 = v.segment<3>(3), r3 = v.segment<3>(6);
    Eigen::VectorXd c(unitNorms ? 6 : 5);
    if (unitNorms)
        c << r1.dot(r2), r2.dot(r3), r3.dot(r1), r1.squaredNorm(), r2.squaredNorm(), r3.squaredNorm();
    else
        c << r1.dot(r2), r2.dot(r3), r3.dot(r1), r1.squaredNorm() - r2.squaredNorm(),
            r2.squaredNorm() - r3.squaredNorm();
    return c;
}

//! Size of the terms of the constraints: |r_i| |r_j| bounded by the largest squared column norm.
double constraintScale(const Vector12d& v)
{
    return std::max({ v.segment<3>(0).squaredNorm(), v.segment<3>(3).squaredNorm(), v.segment<3>(6).squaredNorm() });
}

TEST(Tripose_GeneratedKernels, betaConstraintsN2_reproduce_constraints)
{
    cv::RNG rng(105);
    for (int trial = 0; trial < 200; ++trial)
    {
        const Vector12d v1 = randomVector<12>(rng), v2 = randomVector<12>(rng);
        Eigen::Matrix<double, 5, 3, Eigen::RowMajor> C;
        betaConstraintsN2(v1.data(), v2.data(), C.data());
        const double b1 = normal(rng), b2 = normal(rng);
        const Vector12d v = b1 * v1 + b2 * v2;
        const Eigen::Vector3d monomials(b1 * b1, b2 * b2, b1 * b2);
        const double scale = (v1.squaredNorm() + v2.squaredNorm()) * (b1 * b1 + b2 * b2);
        expectNear(C * monomials, constraints(v, false), scale, "N=2 constraint");
    }
}

TEST(Tripose_GeneratedKernels, betaConstraintsN3_reproduce_constraints)
{
    cv::RNG rng(106);
    for (int trial = 0; trial < 200; ++trial)
    {
        const Vector12d v1 = randomVector<12>(rng), v2 = randomVector<12>(rng), v3 = randomVector<12>(rng);
        Eigen::Matrix<double, 6, 6, Eigen::RowMajor> C;
        betaConstraintsN3(v1.data(), v2.data(), v3.data(), C.data());
        const double b1 = normal(rng), b2 = normal(rng), b3 = normal(rng);
        const Vector12d v = b1 * v1 + b2 * v2 + b3 * v3;
        Eigen::Matrix<double, 6, 1> monomials;
        monomials << b1 * b1, b2 * b2, b3 * b3, b1 * b2, b1 * b3, b2 * b3;
        const double scale = (v1.squaredNorm() + v2.squaredNorm() + v3.squaredNorm()) * (b1 * b1 + b2 * b2 + b3 * b3);
        expectNear(C * monomials, constraints(v, true), scale, "N=3 constraint");
    }
}

//! The five homogeneous constraints as symmetric bilinear forms, q_k(v) = B_k(v, v).
Eigen::Matrix<double, 5, 1> bilinear(const Vector12d& a, const Vector12d& b)
{
    auto dot = [&](int i, int j) { return a.segment<3>(3 * i).dot(b.segment<3>(3 * j)); };
    Eigen::Matrix<double, 5, 1> c;
    c << 0.5 * (dot(0, 1) + dot(1, 0)), 0.5 * (dot(1, 2) + dot(2, 1)), 0.5 * (dot(2, 0) + dot(0, 2)),
        dot(0, 0) - dot(1, 1), dot(1, 1) - dot(2, 2);
    return c;
}

//! The 5x6 matrix of eq. (24) at beta3: with w = b3 v3 + v4,
//! q(b1 v1 + b2 v2 + w) = b1^2 B(v1,v1) + b2^2 B(v2,v2) + 2 b1 b2 B(v1,v2) + 2 b1 B(v1,w) + 2 b2 B(v2,w) + B(w,w).
Matrix56d directMatrix(const Vector12d vs[4], double b3)
{
    const Vector12d w = b3 * vs[2] + vs[3];
    Matrix56d A;
    A << bilinear(vs[0], vs[0]), bilinear(vs[1], vs[1]), 2 * bilinear(vs[0], vs[1]), 2 * bilinear(vs[0], w),
        2 * bilinear(vs[1], w), bilinear(w, w);
    return A;
}

TEST(Tripose_GeneratedKernels, betaN4Matrix_matches_constraints)
{
    cv::RNG rng(107);
    for (int trial = 0; trial < 100; ++trial)
    {
        Vector12d vs[4];
        Eigen::Matrix<double, 48, 1> v;
        for (int j = 0; j < 4; ++j)
            v.segment<12>(12 * j) = vs[j] = randomVector<12>(rng);
        Eigen::Matrix<double, 5, 10, Eigen::RowMajor> M;
        betaN4Matrix(v.data(), M.data());
        for (int k = 0; k < 3; ++k)
        {
            const double b3 = 2 * normal(rng);
            Matrix56d A;
            A << M.leftCols<3>(), M.col(3) + b3 * M.col(4), M.col(5) + b3 * M.col(6),
                M.col(7) + b3 * M.col(8) + b3 * b3 * M.col(9);
            // Entries are sums of products of v's entries: their terms are bounded by |v|^2 (1 + b3^2).
            const double scale = v.squaredNorm() * (1 + b3 * b3);
            expectNear(A.reshaped(), directMatrix(vs, b3).reshaped(), scale, "5x6 matrix");
        }
    }
}

double evaluatePolynomial(const double* c, int degree, double x)
{
    double y = c[degree];
    for (int i = degree - 1; i >= 0; --i)
        y = y * x + c[i];
    return y;
}

double evaluateAbsPolynomial(const double* c, int degree, double x)
{
    double y = std::abs(c[degree]);
    for (int i = degree - 1; i >= 0; --i)
        y = y * std::abs(x) + std::abs(c[i]);
    return y;
}

const int kDegrees[6] = { 4, 4, 4, 3, 3, 2 };
const int kOffsets[6] = { 0, 5, 10, 15, 19, 23 };

TEST(Tripose_GeneratedKernels, betaN4NullVector_equals_signed_minors)
{
    cv::RNG rng(108);
    for (int trial = 0; trial < 100; ++trial)
    {
        Vector12d vs[4];
        Eigen::Matrix<double, 48, 1> v;
        for (int j = 0; j < 4; ++j)
            v.segment<12>(12 * j) = vs[j] = randomVector<12>(rng);
        double u[26];
        betaN4NullVector(v.data(), u);
        for (int k = 0; k < 4; ++k)
        {
            const double b3 = 2 * normal(rng);
            const Matrix56d A = directMatrix(vs, b3);
            // Hadamard's bound on every 5x5 minor: the size of the terms of the determinant.
            double hadamard = 1;
            for (int r = 0; r < 5; ++r)
                hadamard *= A.row(r).norm();
            for (int i = 0; i < 6; ++i)
            {
                Eigen::Matrix<double, 5, 5> minor;
                for (int c = 0, m = 0; c < 6; ++c)
                    if (c != i)
                        minor.col(m++) = A.col(c);
                const double expected = (i % 2 ? -1.0 : 1.0) * minor.determinant();
                const double actual = evaluatePolynomial(u + kOffsets[i], kDegrees[i], b3);
                EXPECT_LE(std::abs(actual - expected), kTol * hadamard)
                    << "u" << i + 1 << " at b3 = " << b3;
            }
        }
    }
}

TEST(Tripose_GeneratedKernels, betaN4NullVector_is_null_vector_of_generated_matrix)
{
    cv::RNG rng(109);
    for (int trial = 0; trial < 100; ++trial)
    {
        const Eigen::Matrix<double, 48, 1> v = randomVector<48>(rng);
        Eigen::Matrix<double, 5, 10, Eigen::RowMajor> M;
        betaN4Matrix(v.data(), M.data());
        double u[26];
        betaN4NullVector(v.data(), u);
        for (int k = 0; k < 4; ++k)
        {
            const double b3 = 2 * normal(rng);
            Matrix56d A;
            A << M.leftCols<3>(), M.col(3) + b3 * M.col(4), M.col(5) + b3 * M.col(6),
                M.col(7) + b3 * M.col(8) + b3 * b3 * M.col(9);
            Eigen::Matrix<double, 6, 1> uv;
            double hadamard = 1;
            for (int r = 0; r < 5; ++r)
                hadamard *= A.row(r).norm();
            for (int i = 0; i < 6; ++i)
            {
                uv[i] = evaluatePolynomial(u + kOffsets[i], kDegrees[i], b3);
                Eigen::Matrix<double, 5, 5> minor;
                for (int c = 0, m = 0; c < 6; ++c)
                    if (c != i)
                        minor.col(m++) = A.col(c);
                const double expected = (i % 2 ? -1.0 : 1.0) * minor.determinant();
                EXPECT_LE(std::abs(uv[i] - expected), kTol * hadamard) << "u" << i + 1 << " at b3 = " << b3;
            }
            expectNear(A * uv, Eigen::Matrix<double, 5, 1>::Zero(), hadamard * A.cwiseAbs().maxCoeff(), "A u");
        }
    }
}

//! Ascending-coefficient product, written independently of the generator.
std::vector<double> multiply(const std::vector<double>& a, const std::vector<double>& b)
{
    std::vector<double> c(a.size() + b.size() - 1, 0.0);
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            c[i + j] += a[i] * b[j];
    return c;
}

TEST(Tripose_GeneratedKernels, betaN4Consistency_and_Polynomial_match_polynomial_products)
{
    cv::RNG rng(110);
    for (int trial = 0; trial < 200; ++trial)
    {
        double u[26];
        for (double& x : u)
            x = normal(rng);
        std::vector<double> ui[6], absUi[6];
        for (int i = 0; i < 6; ++i)
            for (int d = 0; d <= kDegrees[i]; ++d)
            {
                ui[i].push_back(u[kOffsets[i] + d]);
                absUi[i].push_back(std::abs(u[kOffsets[i] + d]));
            }
        auto difference = [](const std::vector<double>& a, const std::vector<double>& b) {
            std::vector<double> c(std::max(a.size(), b.size()), 0.0);
            for (size_t i = 0; i < a.size(); ++i) c[i] += a[i];
            for (size_t i = 0; i < b.size(); ++i) c[i] -= b[i];
            return c;
        };
        auto sum = [](const std::vector<double>& a, const std::vector<double>& b) {
            std::vector<double> c(std::max(a.size(), b.size()), 0.0);
            for (size_t i = 0; i < a.size(); ++i) c[i] += a[i];
            for (size_t i = 0; i < b.size(); ++i) c[i] += b[i];
            return c;
        };
        const int pairs[3][4] = { { 3, 4, 2, 5 }, { 3, 3, 0, 5 }, { 4, 4, 1, 5 } };
        std::vector<double> f[3], absF[3];
        for (int i = 0; i < 3; ++i)
        {
            const int* p = pairs[i];
            f[i] = difference(multiply(ui[p[0]], ui[p[1]]), multiply(ui[p[2]], ui[p[3]]));
            absF[i] = sum(multiply(absUi[p[0]], absUi[p[1]]), multiply(absUi[p[2]], absUi[p[3]]));
        }
        double fGenerated[21];
        betaN4Consistency(u, fGenerated);
        for (int i = 0; i < 3; ++i)
            for (int d = 0; d <= 6; ++d)
                EXPECT_LE(std::abs(fGenerated[7 * i + d] - f[i][d]), kTol * absF[i][d]) << "f" << i + 1 << "[" << d << "]";

        // sum f_i f_i' coefficient by coefficient, against the sizes of its terms.
        std::vector<double> p(12, 0.0), absP(12, 0.0);
        for (int i = 0; i < 3; ++i)
        {
            std::vector<double> df, absDf;
            for (int d = 1; d <= 6; ++d)
            {
                df.push_back(d * f[i][d]);
                absDf.push_back(d * absF[i][d]);
            }
            p = sum(p, multiply(f[i], df));
            absP = sum(absP, multiply(absF[i], absDf));
        }
        double pGenerated[12];
        betaN4Polynomial(u, pGenerated);
        for (int d = 0; d < 12; ++d)
            EXPECT_LE(std::abs(pGenerated[d] - p[d]), kTol * absP[d]) << "p[" << d << "]";
    }
}

TEST(Tripose_GeneratedKernels, betaN4_true_coefficients_solve_the_system_with_exact_data)
{
    cv::RNG rng(111);
    for (int trial = 0; trial < 100; ++trial)
    {
        // One draw per statement, as C++ leaves the order of arguments unspecified: the translation
        // before the rotation is the order the seeded inputs were drawn in so far (GCC's, right to left).
        const Vector3d t = randomVector<3>(rng);
        const Matrix3d R = randomRotation(rng);
        const Vector12d vTrue = 1.7 * poseVector(R, t);
        const double b1 = normal(rng), b2 = normal(rng), b3 = normal(rng);
        Vector12d vs[4] = { randomVector<12>(rng), randomVector<12>(rng), randomVector<12>(rng), Vector12d() };
        vs[3] = vTrue - b1 * vs[0] - b2 * vs[1] - b3 * vs[2];
        Eigen::Matrix<double, 48, 1> v;
        for (int j = 0; j < 4; ++j)
            v.segment<12>(12 * j) = vs[j];
        double u[26], p[12];
        betaN4NullVector(v.data(), u);
        betaN4Polynomial(u, p);
        double ub[6];
        for (int i = 0; i < 6; ++i)
            ub[i] = evaluatePolynomial(u + kOffsets[i], kDegrees[i], b3);
        EXPECT_NEAR(ub[3] / ub[5], b1, 1e-9 * (1 + std::abs(b1)));
        EXPECT_NEAR(ub[4] / ub[5], b2, 1e-9 * (1 + std::abs(b2)));
        EXPECT_LE(std::abs(evaluatePolynomial(p, 11, b3)), 1e-10 * evaluateAbsPolynomial(p, 11, b3));
    }
}

}} // namespace
