// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// nearestRotation (src/linear/pose_recovery.hpp): the rotation the linear solvers make of the
// 3x3 part of a solution vector, which must be a proper rotation whatever the matrix.

#include "test_precomp.hpp"

#include <Eigen/Dense>

#include "../src/core/linear/pose_recovery.hpp"

namespace opencv_test {
namespace {

using ::tripose::nearestRotation;
using Eigen::Matrix3d;
using Eigen::Vector3d;

Vector3d gaussian3(RNG& rng)
{
    // One draw per statement, as C++ leaves the order of arguments and operands unspecified: z before y
    // before x, and the right factor before the left below, is the order the seeded inputs were drawn
    // in so far (GCC's, right to left).
    const double z = rng.gaussian(1.0);
    const double y = rng.gaussian(1.0);
    const double x = rng.gaussian(1.0);
    return Vector3d(x, y, z);
}

//! |R^T R - I| and det R: a proper rotation has 0 and +1.
void expectProperRotation(const Matrix3d& R, int trial)
{
    EXPECT_LT((R.transpose() * R - Matrix3d::Identity()).norm(), 1e-12) << "trial " << trial;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << "trial " << trial;
}

TEST(Tripose_NearestRotation, equals_the_polar_factor_of_a_well_conditioned_matrix)
{
    RNG rng(5);
    for (int trial = 0; trial < 1000; ++trial)
    {
        Matrix3d M;
        for (int c = 0; c < 3; ++c)
            M.col(c) = gaussian3(rng);
        if (M.determinant() < 0)
            M.col(0) = -M.col(0);
        const Matrix3d R = nearestRotation(M);
        expectProperRotation(R, trial);
        const Eigen::JacobiSVD<Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
        EXPECT_LT((R - svd.matrixU() * svd.matrixV().transpose()).norm(), 1e-9) << "trial " << trial;
    }
}

TEST(Tripose_NearestRotation, rank_deficient_matrices_give_proper_rotations)
{
    // Rank 2: the computed determinant is rounding of either sign. Before the fix, about one in
    // eight of those with a positive one came back as a reflection (found by fuzzing the stereo
    // solver on degenerate input).
    RNG rng(6);
    for (int trial = 0; trial < 20000; ++trial)
    {
        const Vector3d d = gaussian3(rng);
        const Vector3d c = gaussian3(rng);
        const Vector3d b = gaussian3(rng);
        const Vector3d a = gaussian3(rng);
        const Matrix3d M = a * b.transpose() + c * d.transpose();
        expectProperRotation(nearestRotation(M), trial);
        if (HasFailure())
            break;
    }
    // Rank 1 and 0.
    const Vector3d b = gaussian3(rng);
    const Vector3d a = gaussian3(rng);
    expectProperRotation(nearestRotation(a * b.transpose()), -1);
    expectProperRotation(nearestRotation(Matrix3d::Zero()), -2);
}

}} // namespace
