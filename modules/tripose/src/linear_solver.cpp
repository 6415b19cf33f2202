// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "kernel_solutions.hpp"
#include "linear_solver.hpp"
#include "linear_system.hpp"
#include "pose_recovery.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

//! R' = (2 t t^T - I) R with t the unit baseline direction, and its least-squares translation.
bool twistedPair(const CameraPose& pose, const Matrix12d& normalMatrix, CameraPose& twisted)
{
    const double n = pose.t.norm();
    if (!(n > 0))
        return false;
    const Eigen::Vector3d d = pose.t / n;
    Vector12d v;
    v << Eigen::Map<const Eigen::Matrix<double, 9, 1>>(
             Eigen::Matrix3d((2.0 * d * d.transpose() - Eigen::Matrix3d::Identity()) * pose.R).data()),
        Eigen::Vector3d::Zero();
    return poseFromSolutionVector(v, normalMatrix, twisted);
}

} // namespace

int kernelDimensionFor(int numFeatures)
{
    CV_Assert(numFeatures >= 4);
    return numFeatures >= 6 ? 1 : 12 - 2 * numFeatures;
}

int linearPoseCandidates(const TripletData& data, std::vector<CameraPose>& poses,
                         const std::vector<int>* pointIndices, const std::vector<int>* lineIndices, bool twistedPairs)
{
    const int numFeatures = (pointIndices ? (int)pointIndices->size() : data.numPoints()) +
                            (lineIndices ? (int)lineIndices->size() : data.numLines());
    const double translationScale = data.view2.t.norm();
    const ConstraintMatrix A = buildConstraintMatrix(data, translationScale, pointIndices, lineIndices);
    if (!A.allFinite())
        return 0;

    const int N = kernelDimensionFor(numFeatures);
    std::vector<Vector12d> solutions;
    Matrix12d normalMatrix;
    if (N == 1)
    {
        // Over-determined: the eigenvectors of A^T A are accurate enough here (the rows are
        // balanced and every candidate is polished on the algebraic error), at a fraction of the
        // cost of an SVD. Besides N = 1, try N = 2: with noise and few redundant constraints the two
        // smallest singular values can be close, and the orthonormality constraints then pick the
        // rotation better than the last singular vector alone; selection decides.
        normalMatrix = A.transpose().lazyProduct(A); // small: coefficient-wise beats blocked GEMM
        Eigen::SelfAdjointEigenSolver<Matrix12d> eigen(normalMatrix);
        if (eigen.info() != Eigen::Success)
            return 0;
        solveKernelCombinations(eigen.eigenvectors().leftCols(1), solutions);
        solveKernelCombinations(eigen.eigenvectors().leftCols(2), solutions);
    }
    else
    {
        // Four or five features: the kernel's edge is where exact data must stay exact, and
        // eigenvectors of A^T A would square its conditioning: SVD of A (rows beyond 12 folded
        // first into a 12x12 triangular factor, which has the same right singular vectors).
        Eigen::Matrix<double, Eigen::Dynamic, 12, 0, 12, 12> reduced;
        if (A.rows() > 12)
        {
            Eigen::HouseholderQR<ConstraintMatrix> qr(A);
            reduced = qr.matrixQR().topRows<12>().triangularView<Eigen::Upper>();
        }
        else
            reduced = A;
        normalMatrix = reduced.transpose() * reduced;
        Eigen::JacobiSVD<Eigen::Matrix<double, Eigen::Dynamic, 12, 0, 12, 12>> svd(reduced, Eigen::ComputeFullV);
        // Singular values descend: the last N right singular vectors span the kernel.
        solveKernelCombinations(svd.matrixV().rightCols(N), solutions);
    }

    int added = 0;
    for (const Vector12d& v : solutions)
    {
        CameraPose pose;
        if (!poseFromSolutionVector(v, normalMatrix, pose))
            continue;
        polishPoseAlgebraic(normalMatrix, pose);
        CameraPose twisted;
        // The twisted pair (R rotated by pi about the baseline direction t) fits the rows almost
        // as well when the constraints are weak (small motion, few features, noise); only
        // cheirality tells them apart, so both go to the selection.
        const bool addTwisted = twistedPairs && twistedPair(pose, normalMatrix, twisted);
        pose.t *= translationScale;
        poses.push_back(pose);
        ++added;
        if (addTwisted)
        {
            polishPoseAlgebraic(normalMatrix, twisted);
            twisted.t *= translationScale;
            poses.push_back(twisted);
            ++added;
        }
    }
    return added;
}

std::vector<ScoredPose> rankCandidates(const TripletData& data, const TwoViewStructure& structure,
                                       const std::vector<CameraPose>& poses)
{
    std::vector<ScoredPose> ranked;
    for (const CameraPose& pose : poses)
    {
        const ReprojectionScore score = scorePose(data, structure, pose);
        if (2 * score.behind > score.considered || !std::isfinite(score.rms))
            continue;
        ScoredPose scored; // not brace-initialised: OpenCV 4.x builds modules as C++11
        scored.pose = pose;
        scored.rms = score.rms;
        ranked.push_back(scored);
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const ScoredPose& a, const ScoredPose& b) { return a.rms < b.rms; });
    return ranked;
}

} // namespace detail
} // namespace tripose
} // namespace cv
