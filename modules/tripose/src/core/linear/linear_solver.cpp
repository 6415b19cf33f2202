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
#include <Eigen/Eigenvalues>

#include "kernel_solutions.hpp"
#include "linear_solver.hpp"
#include "linear_system.hpp"
#include "planar_kernel_solutions.hpp"
#include "pose_recovery.hpp"
#include "smallest_eigenvectors.hpp"

namespace tripose {

namespace {

typedef Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 4> KernelBasis;

// Polished candidates closer than this (Frobenius norm of the rotation difference, about
// sqrt(2) times the angle; translation in units of |t12|) are the same minimum of the algebraic
// error: the polish stops at rounding, about 1e-9 from the minimum.
constexpr double kDuplicateTolerance = 1e-7;

// Relative size of a QR pivot below which a four- or five-feature system counts as rank deficient.
// Rounding leaves exact dependencies near 1e-15; image noise on independent features stays far
// above this.
constexpr double kRankTolerance = 1e-9;

//! R' = (2 d d^T - I) R with d the unit baseline direction (a rotation by pi about d), and its
//! least-squares translation.
bool twistedPair(const CameraPose& pose, const ReducedNormalSystem& system, CameraPose& twisted)
{
    const double n = pose.t.norm();
    if (!(n > 0))
        return false;
    const Eigen::Vector3d d = pose.t / n;
    // Already a rotation: no projection needed.
    twisted.R = (2.0 * d * d.transpose() - Eigen::Matrix3d::Identity()) * pose.R;
    twisted.t = system.T * Eigen::Map<const Vector9d>(twisted.R.data());
    return twisted.R.allFinite() && twisted.t.allFinite();
}

/** Orthonormal basis of the N-dimensional kernel of a system of four or five features. A point's
four rows have rank 2 on exact data (the other two carry noise only): each block is first replaced
by its best rank-2 row space (the two dominant eigenvectors of its 4x4 Gram matrix), which leaves
exactly 2 (points + lines) rows. Their null space then comes from a column-pivoted QR of the
transpose (backward stable, so exact data stays exact to rounding) at a fraction of the cost of an
SVD of A.
*/
bool smallSystemKernel(const ConstraintMatrix& A, int numPoints, int N, KernelBasis& kernel)
{
    const int rows = 12 - N;
    Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 12> At(12, rows);
    int out = 0;
    for (int k = 0; k < numPoints; ++k)
    {
        const Eigen::Matrix<double, 4, 12> P = A.middleRows<4>(4 * k);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(P.lazyProduct(P.transpose()));
        if (eigen.info() != Eigen::Success)
            return false;
        // Eigenvalues ascend: the last two span the row space; u^T P are the rows s_i v_i^T.
        At.col(out++) = P.transpose() * eigen.eigenvectors().col(3);
        At.col(out++) = P.transpose() * eigen.eigenvectors().col(2);
    }
    for (int r = 4 * numPoints; r < A.rows(); ++r)
        At.col(out++) = A.row(r).transpose();
    TRIPOSE_DEBUG_ASSERT(out == rows);
    Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 12>> qr(At.rows(), At.cols());
    qr.setThreshold(kRankTolerance);
    qr.compute(At);
    // Rows that depend on each other (collinear points, features seen without parallax) leave a
    // kernel wider than N: the features do not fix the pose, and any combination would be arbitrary.
    if (qr.rank() < rows)
        return false;
    // Q's trailing columns are orthogonal to every constraint row: the kernel.
    Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 4> E = Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 4>::Zero(12, N);
    E.bottomRows(N).setIdentity();
    kernel = qr.householderQ() * E;
    return kernel.allFinite();
}

/** Rotates the kernel basis within its span so that its vectors ascend in fit: the last one is the
best single solution vector (the smallest Ritz value of A^T A). With noise the kernel combinations
depend on the basis (N = 4 fixes the last vector's coefficient to one; N = 2, 3 linearise), and the
QR's order is arbitrary: putting the best-fitting direction where the combinations anchor makes
noisy hypotheses closer to the truth. A rotation within the span keeps exact data exact.
*/
bool orderKernelBasis(const Matrix12d& normalMatrix, KernelBasis& kernel)
{
    typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4> SmallMatrix;
    const SmallMatrix ritz = kernel.transpose() * normalMatrix * kernel;
    const Eigen::SelfAdjointEigenSolver<SmallMatrix> eigen(ritz);
    if (eigen.info() != Eigen::Success)
        return false;
    // Eigenvalues ascend; reversed, the best-fitting vector comes last.
    const KernelBasis ordered = kernel * eigen.eigenvectors().rowwise().reverse();
    kernel = ordered;
    return kernel.allFinite();
}

//! True when @p pose (t in units of |t12|) equals, to polishing accuracy, one of poses[first..].
bool isDuplicate(const CameraPose& pose, const std::vector<CameraPose>& poses, size_t first, double translationScale)
{
    for (size_t i = first; i < poses.size(); ++i)
        if ((poses[i].R - pose.R).norm() < kDuplicateTolerance &&
            (poses[i].t / translationScale - pose.t).norm() < kDuplicateTolerance * (1.0 + pose.t.norm()))
            return true;
    return false;
}

} // namespace

int kernelDimensionFor(int numFeatures)
{
    TRIPOSE_ASSERT(numFeatures >= 4);
    return numFeatures >= 6 ? 1 : 12 - 2 * numFeatures;
}

int linearPoseCandidates(const ViewSet& set, std::vector<CameraPose>& poses,
                         const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                         const CandidateOptions& options)
{
    const int numPoints = pointIndices ? (int)pointIndices->size() : set.numPoints;
    const int numFeatures = numPoints + (lineIndices ? (int)lineIndices->size() : set.numLines);
    const double translationScale = set.pose12().t.norm();
    const ConstraintMatrix A = buildConstraintMatrix(set, translationScale, pointIndices, lineIndices);
    CameraPose scaledPose12 = set.pose12();
    scaledPose12.t /= translationScale;
    Eigen::Vector4d plane;
    const StructureFlatness flatness = structurePlane(set, scaledPose12, pointIndices, lineIndices, plane);
    return poseCandidatesFromRows(A, numPoints, numFeatures, translationScale, poses, options,
                                  flatness != STRUCTURE_GENERAL ? &plane : nullptr, flatness);
}

int poseCandidatesFromRows(const ConstraintMatrix& A, int numPoints, int numFeatures, double translationScale,
                           std::vector<CameraPose>& poses, const CandidateOptions& options,
                           const Eigen::Vector4d* structurePlane, StructureFlatness flatness)
{
    const int N = kernelDimensionFor(numFeatures);
    // Every candidate is judged on the algebraic error of all rows, with t eliminated.
    // A^T A from one triangle (symmetric rank update), mirrored.
    Matrix12d normalMatrix = Matrix12d::Zero();
    normalMatrix.selfadjointView<Eigen::Upper>().rankUpdate(A.transpose());
    normalMatrix.triangularView<Eigen::StrictlyLower>() = normalMatrix.transpose();
    // A non-finite entry of A makes its diagonal entry of A^T A non-finite: one check for both.
    if (!normalMatrix.allFinite())
        return 0;
    ReducedNormalSystem system;
    if (!reduceNormalMatrix(normalMatrix, system))
        return 0;

    std::vector<Vector12d> solutions;
    solutions.reserve(12);
    if (structurePlane)
    {
        // Coplanar structure widens the kernel beyond N (to 4, or 5 for 2P+2L): the general
        // combinations would work in a wrong space, the plane gives the pose in closed form.
        planarKernelSolutions(A, *structurePlane, solutions);
    }
    // Exactly planar structure: the general combinations have nothing to add.
    const bool general = !(structurePlane && flatness == STRUCTURE_PLANAR);
    if (general && N == 1)
    {
        // Over-determined: the smallest eigenvectors of S (9x9: t eliminated, so only the rotation
        // is normalised) are accurate enough here (the rows are balanced and every candidate is
        // polished on the algebraic error), at a fraction of the cost of an SVD. Besides N = 1,
        // try N = 2: with noise and few redundant constraints the two smallest singular values can
        // be close, and the orthonormality constraints then pick the rotation better than the
        // last singular vector alone; selection decides.
        Eigen::Matrix<double, 9, 2> smallest;
        if (smallestEigenvectors(system.S, smallest))
        {
            Eigen::Matrix<double, 12, 2> basis;
            basis.topRows<9>() = smallest;
            basis.bottomRows<3>() = system.T * basis.topRows<9>();
            solveKernelCombinations(basis.leftCols<1>(), solutions);
            solveKernelCombinations(basis, solutions);
        }
    }
    else if (general)
    {
        // Four or five features: the kernel's edge is where exact data must stay exact.
        KernelBasis kernel;
        if (smallSystemKernel(A, numPoints, N, kernel) &&
            (!options.orderedKernel || orderKernelBasis(normalMatrix, kernel)))
            solveKernelCombinations(kernel, solutions);
    }

    const size_t first = poses.size();
    int added = 0;
    for (const Vector12d& v : solutions)
    {
        CameraPose pose;
        if (!poseFromSolutionVector(v, system, pose))
            continue;
        polishPoseAlgebraic(system, pose);
        CameraPose twisted;
        // The twisted pair (R rotated by pi about the baseline direction t) fits the rows almost
        // as well when the constraints are weak (small motion, few features, noise); only
        // cheirality tells them apart, so both go to the selection. Several kernel combinations
        // often polish into the same minimum (N = 1 and N = 2 with noise, several roots for
        // N = 4): such a duplicate still goes to the selection (the closest to the exact pose
        // wins there), but its twisted pair would repeat one already polished.
        const bool addTwisted = options.twistedPairs && !isDuplicate(pose, poses, first, translationScale) &&
                                twistedPair(pose, system, twisted);
        pose.t *= translationScale;
        poses.push_back(pose);
        ++added;
        if (addTwisted)
        {
            polishPoseAlgebraic(system, twisted);
            twisted.t *= translationScale;
            poses.push_back(twisted);
            ++added;
        }
    }
    return added;
}

} // namespace tripose
