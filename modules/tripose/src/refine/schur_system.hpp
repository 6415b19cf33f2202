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

namespace cv {
namespace tripose {
namespace detail {

typedef Eigen::Matrix<double, 6, 1> Vector6d;
typedef Eigen::Matrix<double, 6, 6> Matrix6d;

//! The normal-equation pieces of one feature whose structure has D parameters.
template <int D>
struct StructureBlock
{
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
    Eigen::Matrix<double, D, D> V;    //!< Structure-structure block J_s^T w J_s.
    Eigen::Matrix<double, 6, D> W;    //!< Pose-structure block J_p^T w J_s.
    Eigen::Matrix<double, D, 1> g;    //!< Structure gradient J_s^T w r.
    Eigen::Matrix<double, D, D> Vinv; //!< Inverse of the damped V (set per damping value).
    Eigen::Matrix<double, D, 1> diag; //!< Marquardt scaling of the damping.
    Eigen::Matrix<double, D, 1> step; //!< Structure increment of the last solve.
    bool active = false;              //!< Takes part in the system (else: no step).
};

/** Damped Gauss-Newton normal equations of one pose (6 parameters) and many independent structure
blocks (3 per point, 4 per line), solved with every structure block eliminated (Schur complement
to a 6x6 system), so that a step costs time linear in the number of features.

Fill it with clear() and add(); solve() for a damping value; read the pose step and each block's
step. The damping is Marquardt's (lambda times the diagonal), so the step does not depend on the
units of the parameters.
*/
class SchurSystem
{
public:
    void resize(size_t points, size_t lines)
    {
        points_.resize(points);
        lines_.resize(lines);
    }

    //! Zeroes the pose block and marks every structure block inactive.
    void clear()
    {
        U_.setZero();
        gPose_.setZero();
        for (StructureBlock<3>& b : points_)
            b.active = false;
        for (StructureBlock<4>& b : lines_)
            b.active = false;
    }

    //! Starts the structure block of a feature (zeroed, active).
    template <int D>
    StructureBlock<D>& begin(StructureBlock<D>& block)
    {
        block.V.setZero();
        block.W.setZero();
        block.g.setZero();
        block.active = true;
        return block;
    }
    StructureBlock<3>& point(size_t k) { return points_[k]; }
    StructureBlock<4>& line(size_t k) { return lines_[k]; }
    const StructureBlock<3>& point(size_t k) const { return points_[k]; }
    const StructureBlock<4>& line(size_t k) const { return lines_[k]; }

    /** Adds one observation with residual @p r, IRLS weight @p weight, d(r)/d(structure) @p Js and,
    when the observation depends on the pose, d(r)/d(pose) @p Jp.
    */
    template <int D>
    void add(StructureBlock<D>& block, const Eigen::Matrix<double, 2, D>& Js, const Eigen::Matrix<double, 2, 6>* Jp,
             const Eigen::Vector2d& r, double weight)
    {
        const Eigen::Matrix<double, 2, D> wJs = weight * Js;
        block.V.noalias() += Js.transpose() * wJs;
        block.g.noalias() += wJs.transpose() * r;
        if (Jp)
        {
            block.W.noalias() += Jp->transpose() * wJs;
            U_.noalias() += Jp->transpose() * (weight * *Jp);
            gPose_.noalias() += Jp->transpose() * (weight * r);
        }
    }

    /** Solves the system damped by @p lambda; @p predicted receives the decrease of the cost that
    the linear model predicts (Madsen, Nielsen & Tingleff, eq. 3.10). False when the reduced system
    is not positive definite or a value is not finite.
    */
    bool solve(double lambda, double& predicted)
    {
        poseDiag_ = dampingDiagonal<6>(U_);
        Matrix6d S = U_;
        S.diagonal() += lambda * poseDiag_;
        Vector6d b = -gPose_;
        for (StructureBlock<3>& block : points_)
            eliminate<3>(block, lambda, S, b);
        for (StructureBlock<4>& block : lines_)
            eliminate<4>(block, lambda, S, b);
        Eigen::LDLT<Matrix6d> ldlt(S);
        if (ldlt.info() != Eigen::Success)
            return false;
        poseStep_ = ldlt.solve(b);
        if (!poseStep_.allFinite())
            return false;
        predicted = poseStep_.dot(lambda * poseDiag_.cwiseProduct(poseStep_) - gPose_);
        for (StructureBlock<3>& block : points_)
            predicted += backSubstitute<3>(block, lambda, poseStep_);
        for (StructureBlock<4>& block : lines_)
            predicted += backSubstitute<4>(block, lambda, poseStep_);
        return std::isfinite(predicted);
    }

    const Vector6d& poseStep() const { return poseStep_; }

private:
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
    static void eliminate(StructureBlock<D>& block, double lambda, Matrix6d& S, Vector6d& b)
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
        const Eigen::Matrix<double, 6, D> Y = block.W * block.Vinv;
        S.noalias() -= Y * block.W.transpose();
        b.noalias() += Y * block.g;
    }

    //! The block's step given the pose step; returns its share of the predicted decrease.
    template <int D>
    static double backSubstitute(StructureBlock<D>& block, double lambda, const Vector6d& poseStep)
    {
        if (!block.active)
        {
            block.step.setZero();
            return 0;
        }
        block.step.noalias() = -block.Vinv * (block.g + block.W.transpose() * poseStep);
        return block.step.dot(lambda * block.diag.cwiseProduct(block.step) - block.g);
    }

    AlignedVector<StructureBlock<3>> points_;
    AlignedVector<StructureBlock<4>> lines_;
    Matrix6d U_;
    Vector6d gPose_, poseDiag_, poseStep_;
};

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_REFINE_SCHUR_SYSTEM_HPP
