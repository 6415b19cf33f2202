// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_SCHUR_SYSTEM_HPP
#define OPENCV_TRIPOSE_REFINE_SCHUR_SYSTEM_HPP

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/StdVector>

#include "../support/error.hpp"

namespace tripose {

typedef Eigen::Matrix<double, 6, 1> Vector6d;
typedef Eigen::Matrix<double, 6, 6> Matrix6d;

/** The normal-equation pieces of one feature whose structure has D parameters, in a system of
P pose parameters (6 per pose: 6 for one camera, Eigen::Dynamic for several). */
template <int D, int P = 6>
struct StructureBlock
{
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
    Eigen::Matrix<double, D, D> V;    //!< Structure-structure block J_s^T w J_s.
    //! Pose-structure block J_p^T w J_s: all P rows for one pose; for several poses, 6 rows per pose
    //! in @p poses (those the feature's observations depend on), in that order, in its first rows (it
    //! keeps the rows of earlier fills, so that a refill does not allocate them again).
    Eigen::Matrix<double, P, D> W;
    std::vector<int> poses;           //!< Several poses: the poses of W's rows.
    Eigen::Matrix<double, D, 1> g;    //!< Structure gradient J_s^T w r.
    Eigen::Matrix<double, D, D> Vinv; //!< Inverse of the damped V (set per damping value).
    Eigen::Matrix<double, D, 1> diag; //!< Marquardt scaling of the damping.
    Eigen::Matrix<double, D, 1> step; //!< Structure increment of the last solve.
    bool active = false;              //!< Takes part in the system (else: no step).
};

/** Damped Gauss-Newton normal equations of the poses (6 parameters each: P = 6 for one pose, or
Eigen::Dynamic for any number) and many independent structure blocks (3 per point, 4 per line),
solved with every structure block eliminated (Schur complement to a system in the poses alone), so
that a step costs time linear in the number of features.

Fill it with clear() and add(); solve() for a damping value; read the pose step and each block's
step. The damping is Marquardt's (lambda times the diagonal), so the step does not depend on the
units of the parameters. An observation depends on one pose at most: the poses are coupled only
through the structure they share.
*/
template <int P = 6>
class SchurSystem
{
public:
    typedef Eigen::Matrix<double, P, P> PoseMatrix;
    typedef Eigen::Matrix<double, P, 1> PoseVector;

    //! Sizes the system for @p points and @p lines structure blocks and @p poses poses (1 when P = 6).
    void resize(size_t points, size_t lines, int poses = 1)
    {
        TRIPOSE_DEBUG_ASSERT(P == Eigen::Dynamic || 6 * poses == P);
        const int n = 6 * poses;
        points_.resize(points);
        lines_.resize(lines);
        if constexpr (!kSeveral)
        {
            for (StructureBlock<3, P>& b : points_)
                b.W.resize(n, 3);
            for (StructureBlock<4, P>& b : lines_)
                b.W.resize(n, 4);
        }
        U_.resize(n, n);
        gPose_.resize(n);
        poseDiag_.resize(n);
        poseStep_.resize(n);
    }

    //! Zeroes the pose blocks and marks every structure block inactive.
    void clear()
    {
        U_.setZero();
        gPose_.setZero();
        for (StructureBlock<3, P>& b : points_)
            b.active = false;
        for (StructureBlock<4, P>& b : lines_)
            b.active = false;
    }

    //! Starts the structure block of a feature (zeroed, active).
    template <int D>
    StructureBlock<D, P>& begin(StructureBlock<D, P>& block)
    {
        block.V.setZero();
        if constexpr (kSeveral)
            block.poses.clear();
        else
            block.W.setZero();
        block.g.setZero();
        block.active = true;
        return block;
    }
    StructureBlock<3, P>& point(size_t k) { return points_[k]; }
    StructureBlock<4, P>& line(size_t k) { return lines_[k]; }
    const StructureBlock<3, P>& point(size_t k) const { return points_[k]; }
    const StructureBlock<4, P>& line(size_t k) const { return lines_[k]; }

    /** Adds one observation with residual @p r, IRLS weight @p weight, d(r)/d(structure) @p Js and,
    when the observation depends on pose @p pose, d(r)/d(that pose) @p Jp.
    */
    template <int D>
    void add(StructureBlock<D, P>& block, const Eigen::Matrix<double, 2, D>& Js, const Eigen::Matrix<double, 2, 6>* Jp,
             const Eigen::Vector2d& r, double weight, int pose = 0)
    {
        const Eigen::Matrix<double, 2, D> wJs = weight * Js;
        block.V.noalias() += Js.transpose() * wJs;
        block.g.noalias() += wJs.transpose() * r;
        if (Jp)
        {
            const int o = 6 * pose;
            if constexpr (kSeveral)
                block.W.template middleRows<6>(6 * slot(block, pose)).noalias() += Jp->transpose() * wJs;
            else
                block.W.template middleRows<6>(o).noalias() += Jp->transpose() * wJs;
            U_.template block<6, 6>(o, o).noalias() += Jp->transpose() * (weight * *Jp);
            gPose_.template segment<6>(o).noalias() += Jp->transpose() * (weight * r);
        }
    }

    /** Solves the system damped by @p lambda; @p predicted receives the decrease of the cost that
    the linear model predicts (Madsen, Nielsen & Tingleff, eq. 3.10). False when the reduced system
    is not positive definite or a value is not finite.
    */
    bool solve(double lambda, double& predicted)
    {
        poseDiag_ = dampingDiagonal<P>(U_);
        PoseMatrix S = U_;
        S.diagonal() += lambda * poseDiag_;
        PoseVector b = -gPose_;
        for (StructureBlock<3, P>& block : points_)
            eliminate<3>(block, lambda, S, b);
        for (StructureBlock<4, P>& block : lines_)
            eliminate<4>(block, lambda, S, b);
        mirrorLowerBlocks(S);
        Eigen::LDLT<PoseMatrix> ldlt(S);
        if (ldlt.info() != Eigen::Success)
            return false;
        poseStep_ = ldlt.solve(b);
        if (!poseStep_.allFinite())
            return false;
        predicted = poseStep_.dot(lambda * poseDiag_.cwiseProduct(poseStep_) - gPose_);
        for (StructureBlock<3, P>& block : points_)
            predicted += backSubstitute<3>(block, lambda, poseStep_);
        for (StructureBlock<4, P>& block : lines_)
            predicted += backSubstitute<4>(block, lambda, poseStep_);
        return std::isfinite(predicted);
    }

    //! The step of all poses (6 per pose: omega, dt).
    const PoseVector& poseStep() const { return poseStep_; }

    /** The undamped pose block of J^T w J with every active structure block eliminated (the
    information of the poses with the structure marginalised), in @p reduced. False when an active
    structure block is not positive definite (its structure would not be determined, so the
    marginal is undefined) or a value is not finite.
    */
    bool reducedPoseMatrix(PoseMatrix& reduced) const
    {
        reduced = U_;
        for (const StructureBlock<3, P>& block : points_)
            if (!marginalize<3>(block, reduced))
                return false;
        for (const StructureBlock<4, P>& block : lines_)
            if (!marginalize<4>(block, reduced))
                return false;
        mirrorLowerBlocks(reduced);
        return reduced.allFinite();
    }

private:
    //! Several poses (P dynamic): each structure block couples only the poses that see it, so its
    //! pose-structure block holds those poses' rows alone and the elimination touches only their
    //! blocks of the reduced system, which keeps a step linear in the number of features.
    static constexpr bool kSeveral = P == Eigen::Dynamic;

    //! The index of @p pose among @p block's poses, added (its rows zeroed) when new.
    template <int D>
    static int slot(StructureBlock<D, P>& block, int pose)
    {
        for (size_t i = 0; i < block.poses.size(); ++i)
            if (block.poses[i] == pose)
                return (int)i;
        block.poses.push_back(pose);
        const Eigen::Index rows = 6 * (Eigen::Index)block.poses.size();
        if (block.W.rows() < rows)
            block.W.conservativeResize(std::max(rows, 2 * block.W.rows()), D);
        block.W.template middleRows<6>(rows - 6).setZero();
        return (int)block.poses.size() - 1;
    }

    /** reduced -= W A W^T and b += W A g over the poses of @p block (A symmetric D x D). With
    several poses only the 6 x 6 blocks on and below the diagonal are updated (the product is
    symmetric): mirrorLowerBlocks() completes @p reduced once every block is in. */
    template <int D>
    static void subtractCoupling(const StructureBlock<D, P>& block, const Eigen::Matrix<double, D, D>& A,
                                 PoseMatrix& reduced, PoseVector* b)
    {
        if constexpr (!kSeveral)
        {
            const Eigen::Matrix<double, P, D> Y = block.W * A;
            reduced.noalias() -= Y * block.W.transpose();
            if (b)
                b->noalias() += Y * block.g;
            return;
        }
        else
        {
            for (size_t i = 0; i < block.poses.size(); ++i)
            {
                const int oi = 6 * block.poses[i];
                const Eigen::Matrix<double, 6, D> Yi = block.W.template middleRows<6>(6 * i) * A;
                for (size_t j = 0; j < block.poses.size(); ++j)
                    if (block.poses[j] <= block.poses[i])
                        reduced.template block<6, 6>(oi, 6 * block.poses[j]).noalias() -=
                            Yi * block.W.template middleRows<6>(6 * j).transpose();
                if (b)
                    b->template segment<6>(oi).noalias() += Yi * block.g;
            }
        }
    }

    //! With several poses, the blocks above the diagonal of @p reduced copied from those below it.
    static void mirrorLowerBlocks(PoseMatrix& reduced)
    {
        if constexpr (kSeveral)
            for (Eigen::Index j = 1; j < reduced.cols(); ++j)
                reduced.col(j).head(j) = reduced.row(j).head(j).transpose();
    }

    //! W^T poseStep over the poses of @p block.
    template <int D>
    static Eigen::Matrix<double, D, 1> transposedTimes(const StructureBlock<D, P>& block, const PoseVector& poseStep)
    {
        if constexpr (!kSeveral)
            return block.W.transpose() * poseStep;
        Eigen::Matrix<double, D, 1> out = Eigen::Matrix<double, D, 1>::Zero();
        for (size_t i = 0; i < block.poses.size(); ++i)
            out.noalias() += block.W.template middleRows<6>(6 * i).transpose() *
                             poseStep.template segment<6>(6 * block.poses[i]);
        return out;
    }

    template <typename T>
    using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

    //! Damping scale for each diagonal entry: the entry itself, kept away from zero so that
    //! directions the data do not constrain are still damped.
    template <int D>
    static Eigen::Matrix<double, D, 1> dampingDiagonal(const Eigen::Matrix<double, D, D>& H)
    {
        const Eigen::Matrix<double, D, 1> d = H.diagonal();
        const double floor = std::max(1e-12 * d.maxCoeff(), 1e-300);
        return d.cwiseMax(floor);
    }

    template <int D>
    static void eliminate(StructureBlock<D, P>& block, double lambda, PoseMatrix& S, PoseVector& b)
    {
        if (!block.active)
            return;
        block.diag = dampingDiagonal<D>(block.V);
        Eigen::Matrix<double, D, D> damped = block.V;
        damped.diagonal() += lambda * block.diag;
        // A non-positive determinant means the block is singular even with damping (rounding):
        // this structure then stays where it is for this step.
        const double det = damped.determinant();
        block.Vinv.setZero();
        if (!(det > 0) || !std::isfinite(det))
            return;
        block.Vinv = damped.inverse();
        if (!block.Vinv.allFinite())
        {
            block.Vinv.setZero();
            return;
        }
        subtractCoupling<D>(block, block.Vinv, S, &b);
    }

    template <int D>
    static bool marginalize(const StructureBlock<D, P>& block, PoseMatrix& reduced)
    {
        if (!block.active)
            return true;
        const Eigen::LLT<Eigen::Matrix<double, D, D>> llt(block.V);
        if (llt.info() != Eigen::Success)
            return false;
        if constexpr (kSeveral)
            subtractCoupling<D>(block, llt.solve(Eigen::Matrix<double, D, D>::Identity()), reduced, nullptr);
        else
            reduced.noalias() -= block.W * llt.solve(block.W.transpose());
        return true;
    }

    //! The block's step given the pose step; returns its share of the predicted decrease.
    template <int D>
    static double backSubstitute(StructureBlock<D, P>& block, double lambda, const PoseVector& poseStep)
    {
        if (!block.active)
        {
            block.step.setZero();
            return 0;
        }
        block.step.noalias() = -block.Vinv * (block.g + transposedTimes<D>(block, poseStep));
        return block.step.dot(lambda * block.diag.cwiseProduct(block.step) - block.g);
    }

    AlignedVector<StructureBlock<3, P>> points_;
    AlignedVector<StructureBlock<4, P>> lines_;
    PoseMatrix U_;
    PoseVector gPose_, poseDiag_, poseStep_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_SCHUR_SYSTEM_HPP
