// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include <Eigen/Dense>

#include "../geometry/line_parameterization.hpp"
#include "ml_refinement.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

typedef Eigen::Matrix<double, 6, 1> Vector6d;
typedef Eigen::Matrix<double, 6, 6> Matrix6d;

//! One view: pose and intrinsics in the forms the residuals need.
struct Camera
{
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    double fx, shear, cx, fy, cy;
    //! Maps a calibrated image line to the pixel line (K^-T up to a positive scale).
    Eigen::Matrix3d lineK;
    //! d(moment in this camera) / d(m, d) = [R, [t]x R].
    Eigen::Matrix<double, 3, 6> lineMoment;

    void setPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
    {
        R = rotation;
        t = translation;
        lineMoment.leftCols<3>() = R;
        lineMoment.rightCols<3>().noalias() = skew(t) * R;
    }

    void setIntrinsics(const Intrinsics& K)
    {
        fx = K.fx;
        shear = K.shear;
        cx = K.cx;
        fy = K.fy;
        cy = K.cy;
        lineK = K.lineK;
    }
};

//! Squared-norm loss rho(s) of one residual pair and its IRLS weight rho'(s).
struct Loss
{
    int kind;
    double c2;

    double rho(double s, double& weight) const
    {
        if (kind == LOSS_HUBER && s > c2)
        {
            const double r = std::sqrt(s), c = std::sqrt(c2);
            weight = c / r;
            return 2 * c * r - c2;
        }
        if (kind == LOSS_CAUCHY)
        {
            weight = 1.0 / (1.0 + s / c2);
            return c2 * std::log1p(s / c2);
        }
        weight = 1.0;
        return s;
    }
};

//! Robust cost and plain sum of squares of a set of residuals.
struct CostSum
{
    double robust = 0, squares = 0;
    int residuals = 0;

    void add(double s, double rho)
    {
        robust += rho;
        squares += s;
        residuals += 2;
    }
    double rms() const
    {
        return residuals > 0 ? std::sqrt(squares / residuals) : std::numeric_limits<double>::infinity();
    }
};

//! The normal-equation pieces of one feature with a structure block of size D.
template <int D>
struct FeatureBlock
{
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
    Eigen::Matrix<double, D, D> V;     //!< Structure-structure block J_s^T w J_s.
    Eigen::Matrix<double, 6, D> W;     //!< Pose-structure block J_p^T w J_s.
    Eigen::Matrix<double, D, 1> g;     //!< Structure gradient J_s^T w r.
    Eigen::Matrix<double, D, D> Vinv;  //!< Inverse of the damped V (set per damping value).
    Eigen::Matrix<double, D, 1> diag;  //!< Marquardt scaling of the damping.
    Eigen::Matrix<double, D, 1> step;  //!< Structure increment of the last solve.
    bool solvable = false;
};

template <typename T>
using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

struct Estimate
{
    CameraPose pose;
    std::vector<Eigen::Vector3d> points;
    std::vector<OrthonormalLine> lines;
};

//! Damping scale for each diagonal entry: the entry itself (Marquardt), kept away from zero so that
//! unobserved directions are still damped.
template <int D>
Eigen::Matrix<double, D, 1> dampingDiagonal(const Eigen::Matrix<double, D, D>& H)
{
    const Eigen::Matrix<double, D, 1> d = H.diagonal();
    const double floor = std::max(1e-12 * d.maxCoeff(), 1e-300);
    return d.cwiseMax(floor);
}

class Refiner
{
public:
    Refiner(const ViewSet& data, const RefineParams& params, const std::vector<int>* pointIndices,
            const std::vector<int>* lineIndices)
        : data_(data)
    {
        loss_.kind = params.loss;
        loss_.c2 = params.lossScale * params.lossScale;
        maxIterations_ = params.maxIterations;
        tolerance_ = params.tolerance;
        select(pointIndices, data.numPoints, points_);
        select(lineIndices, data.numLines, lines_);
        for (int v = 0; v < 3; ++v)
            cameras_[v].setIntrinsics(data.views[v].camera);
        cameras_[0].setPose(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
        cameras_[1].setPose(data.pose12().R, data.pose12().t);
        // Depths below this (relative to the baseline of views 1-2) count as "at the camera centre".
        minDepth_ = 1e-6 * data.pose12().t.norm();
    }

    RefinementSummary run(CameraPose& pose, RefinedStructure* structure)
    {
        RefinementSummary summary;
        Estimate current;
        current.pose = pose;
        const bool finitePose = pose.R.allFinite() && pose.t.allFinite();
        if (finitePose)
            initializeStructure(current);
        else
        {
            current.points.assign(points_.size(), Eigen::Vector3d::Zero());
            current.lines.assign(lines_.size(), OrthonormalLine());
        }

        CostSum cost;
        if (!finitePose || !evaluate(current, cost) || cost.residuals == 0)
        {
            summary.initialRms = summary.finalRms = std::numeric_limits<double>::infinity();
            exportStructure(current, structure);
            return summary;
        }
        summary.initialRms = cost.rms();

        pointBlocks_.resize(points_.size());
        lineBlocks_.resize(lines_.size());
        Estimate trial = current;
        double lambda = 1e-4, nu = 2;
        bool linearized = false;
        while (summary.iterations < maxIterations_)
        {
            if (cost.squares <= kNegligibleSquare * cost.residuals)
                break; // exact fit: nothing left to gain
            if (!linearized)
            {
                linearize(current);
                linearized = true;
            }
            ++summary.iterations;
            double predicted = 0;
            CostSum trialCost;
            const bool stepped = solve(lambda, predicted) && applyStep(current, trial) && evaluate(trial, trialCost);
            const double actual = stepped ? cost.robust - trialCost.robust : -1.0;
            if (stepped && actual > 0 && predicted > 0)
            {
                const bool converged = actual <= tolerance_ * cost.robust;
                std::swap(current, trial);
                cost = trialCost;
                linearized = false;
                const double gain = actual / predicted;
                lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3));
                nu = 2;
                if (converged)
                    break;
            }
            else
            {
                // A step that changes nothing measurable means the minimum is reached to rounding.
                if (stepped && std::abs(actual) <= tolerance_ * cost.robust)
                    break;
                lambda *= nu;
                nu *= 2;
                if (!(lambda < kMaxLambda))
                    break;
            }
        }
        summary.finalRms = cost.rms();
        pose = current.pose;
        exportStructure(current, structure);
        return summary;
    }

private:
    static constexpr double kNegligibleSquare = 1e-20; //!< (px^2) per residual: RMS 1e-10 px is an exact fit.
    static constexpr double kMaxLambda = 1e16;
    //! det / trace^3 of a point's triangulation normal matrix below which its depth is undetermined.
    static constexpr double kPointConditioning = 1e-14;
    //! Singular value ratio (second / first) of the three planes of a line below which they do not pin it down.
    static constexpr double kLineConditioning = 1e-5;

    struct SelectedFeature
    {
        // No default member initializers: brace initialisation must stay valid C++11 (an aggregate).
        int index;        //!< Index in the ViewSet.
        bool used;        //!< Enters the cost (well determined, in front of the cameras).
        bool initialized; //!< Has a finite structure estimate (for the output).
    };

    static void select(const std::vector<int>* indices, int count, std::vector<SelectedFeature>& out)
    {
        out.clear();
        if (indices)
        {
            out.reserve(indices->size());
            for (int i : *indices)
            {
                CV_Assert(0 <= i && i < count);
                out.push_back({ i, false, false });
            }
        }
        else
        {
            out.reserve(count);
            for (int i = 0; i < count; ++i)
                out.push_back({ i, false, false });
        }
    }

    void setView3(const CameraPose& pose)
    {
        cameras_[2].setPose(pose.R, pose.t);
    }

    const Eigen::Vector2d& calibratedPoint(int view, int i) const
    {
        return data_.views[view].calibratedPoints[i];
    }

    const Eigen::Vector3d& calibratedLine(int view, int i) const
    {
        return data_.views[view].calibratedLines[i];
    }

    /** Linear triangulation of point @p i over the three views, rows weighted to approximate pixel
    errors. Returns det / trace^3 of the normal matrix, a conditioning measure (0 when it is
    numerically singular). */
    double triangulatePoint(int i, Eigen::Vector3d& X) const
    {
        double weight[3] = { cameras_[0].fx, cameras_[1].fx, cameras_[2].fx };
        double conditioning = 0;
        // The second pass divides each view's rows by the depth found in the first, which turns the
        // algebraic error into the reprojection error to first order.
        for (int pass = 0; pass < 2; ++pass)
        {
            Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            for (int v = 0; v < 3; ++v)
            {
                const Camera& c = cameras_[v];
                const Eigen::Vector2d& x = calibratedPoint(v, i);
                for (int row = 0; row < 2; ++row)
                {
                    const Eigen::Vector3d a = weight[v] * (c.R.row(row) - x(row) * c.R.row(2)).transpose();
                    const double rhs = -weight[v] * (c.t(row) - x(row) * c.t(2));
                    A.noalias() += a * a.transpose();
                    b += rhs * a;
                }
            }
            // det / trace^3 bounds lambda_min / lambda_max from below (and is within a small factor of
            // it when the two directions across the rays are well determined, which they are for any
            // point at a finite distance).
            const double trace = A.trace(), det = A.determinant();
            if (!(trace > 0) || !(det > kPointConditioning * trace * trace * trace))
                return pass == 0 ? 0 : conditioning;
            const Eigen::Vector3d solution = A.inverse() * b;
            if (!solution.allFinite())
                return pass == 0 ? 0 : conditioning;
            X = solution;
            conditioning = det / (trace * trace * trace);
            for (int v = 0; v < 3; ++v)
            {
                const double z = depth(cameras_[v], X);
                if (!(z > minDepth_))
                    return conditioning; // behind a camera: the caller leaves it out of the cost
                weight[v] = cameras_[v].fx / z;
            }
        }
        return conditioning;
    }

    static double depth(const Camera& c, const Eigen::Vector3d& X)
    {
        return c.R.row(2).dot(X) + c.t(2);
    }

    /** Initial structure from all three views with the initial pose. (Triangulating from the exact
    views 1-2 alone was tried: it converges no faster from poor starts, and a line near an epipolar
    plane of views 1-2 then starts far off and costs many iterations.) Features that the views do
    not determine, or points behind a camera, stay out of the cost. */
    void initializeStructure(Estimate& e)
    {
        setView3(e.pose);
        e.points.assign(points_.size(), Eigen::Vector3d::Zero());
        for (size_t k = 0; k < points_.size(); ++k)
        {
            const int i = points_[k].index;
            Eigen::Vector3d X = Eigen::Vector3d::Zero();
            const bool triangulated = triangulatePoint(i, X) > 0;
            points_[k].used = triangulated && depth(cameras_[0], X) > minDepth_ && depth(cameras_[1], X) > minDepth_ &&
                              depth(cameras_[2], X) > minDepth_;
            points_[k].initialized = triangulated;
            if (triangulated)
                e.points[k] = X;
        }

        e.lines.assign(lines_.size(), OrthonormalLine());
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            const int i = lines_[k].index;
            Eigen::Vector4d planes[3];
            for (int v = 0; v < 3; ++v)
            {
                const Camera& c = cameras_[v];
                const Eigen::Vector3d& l = calibratedLine(v, i);
                planes[v].head<3>() = c.fx * (c.R.transpose() * l);
                planes[v](3) = c.fx * c.t.dot(l);
            }
            PluckerLine L;
            const bool determined = lineFromPlanes(planes, 3, L, kLineConditioning) &&
                                    OrthonormalLine::fromPlucker(L, e.lines[k]);
            if (!determined)
            {
                // Not determined by the views: keep any finite fit for the output, outside the cost.
                lines_[k].initialized = lineFromPlanes(planes, 3, L, 0.0) && OrthonormalLine::fromPlucker(L, e.lines[k]);
                continue;
            }
            lines_[k].initialized = true;
            bool ok = true;
            // Each view must see the line as a line (not through its centre).
            Eigen::Vector3d unused;
            for (int v = 0; v < 3 && ok; ++v)
                ok = projectLine(cameras_[v], e.lines[k].plucker(), unused);
            lines_[k].used = ok;
        }
    }

    //! Pixel line of a 3D line in a camera; false when the line passes (nearly) through the centre.
    static bool projectLine(const Camera& c, const PluckerLine& L, Eigen::Vector3d& pixelLine)
    {
        const Eigen::Vector3d Rd = c.R * L.d;
        const Eigen::Vector3d mc = c.R * L.m + c.t.cross(Rd);
        pixelLine = c.lineK * mc;
        const double n = pixelLine.head<2>().norm();
        return n > 1e-12 * (L.m.norm() + c.t.norm() * L.d.norm()) && std::isfinite(n);
    }

    //! Robust cost of an estimate; false when a used feature became degenerate (behind a camera,
    //! line through a centre) or a value is not finite.
    bool evaluate(const Estimate& e, CostSum& cost)
    {
        setView3(e.pose);
        cost = CostSum();
        double weight;
        for (size_t k = 0; k < points_.size(); ++k)
        {
            if (!points_[k].used)
                continue;
            const int i = points_[k].index;
            const Eigen::Vector3d& X = e.points[k];
            for (int v = 0; v < 3; ++v)
            {
                const Camera& c = cameras_[v];
                const Eigen::Vector3d Xc = c.R * X + c.t;
                if (!(Xc.z() > minDepth_))
                    return false;
                const double x = Xc.x() / Xc.z(), y = Xc.y() / Xc.z();
                const Eigen::Vector2d& obs = data_.views[v].points[i];
                const double r0 = c.fx * x + c.shear * y + c.cx - obs.x();
                const double r1 = c.fy * y + c.cy - obs.y();
                const double s = r0 * r0 + r1 * r1;
                cost.add(s, loss_.rho(s, weight));
            }
        }
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            if (!lines_[k].used)
                continue;
            const int i = lines_[k].index;
            const PluckerLine L = e.lines[k].plucker();
            for (int v = 0; v < 3; ++v)
            {
                Eigen::Vector3d l;
                if (!projectLine(cameras_[v], L, l))
                    return false;
                const double n = l.head<2>().norm();
                const double r0 = l.dot(data_.views[v].lineEnds[2 * i].homogeneous()) / n;
                const double r1 = l.dot(data_.views[v].lineEnds[2 * i + 1].homogeneous()) / n;
                const double s = r0 * r0 + r1 * r1;
                cost.add(s, loss_.rho(s, weight));
            }
        }
        return std::isfinite(cost.robust) && std::isfinite(cost.squares);
    }

    //! Gauss-Newton pieces at @p e: the pose block U, g_p and one FeatureBlock per used feature.
    void linearize(const Estimate& e)
    {
        setView3(e.pose);
        U_.setZero();
        gp_.setZero();
        for (size_t k = 0; k < points_.size(); ++k)
            linearizePoint(e.points[k], points_[k], pointBlocks_[k]);
        for (size_t k = 0; k < lines_.size(); ++k)
            linearizeLine(e.lines[k], lines_[k], lineBlocks_[k]);
    }

    void linearizePoint(const Eigen::Vector3d& X, const SelectedFeature& feature, FeatureBlock<3>& blk)
    {
        blk.solvable = feature.used;
        if (!blk.solvable)
            return;
        blk.V.setZero();
        blk.W.setZero();
        blk.g.setZero();
        double weight;
        for (int v = 0; v < 3; ++v)
        {
            const Camera& c = cameras_[v];
            // View 1 is [I|0]: skip the identity products.
            const Eigen::Vector3d Xc = v == 0 ? X : Eigen::Vector3d(c.R * X + c.t);
            const double iz = 1.0 / Xc.z();
            const double x = Xc.x() * iz, y = Xc.y() * iz;
            const Eigen::Vector2d& obs = data_.views[v].points[feature.index];
            const Eigen::Vector2d r(c.fx * x + c.shear * y + c.cx - obs.x(), c.fy * y + c.cy - obs.y());
            loss_.rho(r.squaredNorm(), weight);
            const Eigen::Vector2d wr = weight * r;
            // d(pixel) / d(camera point)
            Eigen::Matrix<double, 2, 3> Jc;
            Jc << c.fx * iz, c.shear * iz, -(c.fx * x + c.shear * y) * iz, 0, c.fy * iz, -c.fy * y * iz;
            Eigen::Matrix<double, 2, 3> Js;
            if (v == 0)
                Js = Jc;
            else
                Js.noalias() = Jc * c.R;
            const Eigen::Matrix<double, 2, 3> wJs = weight * Js;
            blk.V.noalias() += Js.transpose() * wJs;
            blk.g.noalias() += Js.transpose() * wr;
            if (v == 2)
            {
                // Left increment: d(R X + t) = -[R X]x domega + dt.
                Eigen::Matrix<double, 2, 6> Jp;
                Jp.leftCols<3>().noalias() = -Jc * skew(Xc - c.t);
                Jp.rightCols<3>() = Jc;
                blk.W.noalias() += Jp.transpose() * wJs;
                U_.noalias() += Jp.transpose() * (weight * Jp);
                gp_.noalias() += Jp.transpose() * wr;
            }
        }
    }

    void linearizeLine(const OrthonormalLine& line, const SelectedFeature& feature, FeatureBlock<4>& blk)
    {
        blk.solvable = feature.used;
        if (!blk.solvable)
            return;
        const int i = feature.index;
        const PluckerLine L = line.plucker();
        const Eigen::Matrix<double, 6, 4> dL = line.pluckerJacobian();
        blk.V.setZero();
        blk.W.setZero();
        blk.g.setZero();
        double weight;
        for (int v = 0; v < 3; ++v)
        {
            const Camera& c = cameras_[v];
            Eigen::Vector3d Rm = L.m, Rd = L.d, mc = L.m;
            if (v > 0)
            {
                Rm.noalias() = c.R * L.m;
                Rd.noalias() = c.R * L.d;
                mc = Rm + c.t.cross(Rd);
            }
            const Eigen::Vector3d l = c.lineK * mc;
            const double n = l.head<2>().norm(), invN = 1.0 / n;
            const Eigen::Vector3d normal(l(0) * invN, l(1) * invN, 0.0);
            Eigen::Vector2d r;
            Eigen::Matrix<double, 2, 3> G; // d(residuals) / d(moment in the camera frame)
            for (int end = 0; end < 2; ++end)
            {
                const Eigen::Vector3d p = data_.views[v].lineEnds[2 * i + end].homogeneous();
                r(end) = l.dot(p) * invN;
                // d(l.p / |l_12|) / dl = (p - r n_hat) / |l_12|
                G.row(end).noalias() = (invN * (p - r(end) * normal)).transpose() * c.lineK;
            }
            loss_.rho(r.squaredNorm(), weight);
            const Eigen::Vector2d wr = weight * r;
            // d(moment in camera) / d(m, d) = [R, [t]x R] (the identity and zero in view 1)
            Eigen::Matrix<double, 2, 4> Js;
            if (v == 0)
                Js.noalias() = G * dL.topRows<3>();
            else
                Js.noalias() = (G * c.lineMoment) * dL;
            const Eigen::Matrix<double, 2, 4> wJs = weight * Js;
            blk.V.noalias() += Js.transpose() * wJs;
            blk.g.noalias() += Js.transpose() * wr;
            if (v == 2)
            {
                // Left increment: d(mc) = (-[Rm]x - [t]x [Rd]x) domega - [Rd]x dt.
                const Eigen::Matrix3d skewRd = skew(Rd);
                Eigen::Matrix<double, 2, 6> Jp;
                Jp.leftCols<3>().noalias() = -G * (skew(Rm) + skew(c.t) * skewRd);
                Jp.rightCols<3>().noalias() = -G * skewRd;
                blk.W.noalias() += Jp.transpose() * wJs;
                U_.noalias() += Jp.transpose() * (weight * Jp);
                gp_.noalias() += Jp.transpose() * wr;
            }
        }
    }

    //! Damped structure block: inverse and contributions to the reduced (Schur) system.
    template <int D>
    static void eliminate(FeatureBlock<D>& blk, double lambda, Matrix6d& S, Vector6d& b)
    {
        if (!blk.solvable)
            return;
        blk.diag = dampingDiagonal<D>(blk.V);
        Eigen::Matrix<double, D, D> damped = blk.V;
        damped.diagonal() += lambda * blk.diag;
        // Closed-form inverse of the small block; a non-positive determinant means it is singular
        // even with damping (rounding): leave this structure alone in this step.
        const double det = damped.determinant();
        if (!(det > 0) || !std::isfinite(det))
        {
            blk.Vinv.setZero();
            return;
        }
        blk.Vinv = damped.inverse();
        if (!blk.Vinv.allFinite())
        {
            blk.Vinv.setZero();
            return;
        }
        const Eigen::Matrix<double, 6, D> Y = blk.W * blk.Vinv;
        S.noalias() -= Y * blk.W.transpose();
        b.noalias() += Y * blk.g;
    }

    //! Back-substitution; returns this block's share of the predicted cost decrease.
    template <int D>
    static double backSubstitute(FeatureBlock<D>& blk, double lambda, const Vector6d& poseStep)
    {
        if (!blk.solvable)
            return 0;
        blk.step.noalias() = -blk.Vinv * (blk.g + blk.W.transpose() * poseStep);
        return blk.step.dot(lambda * blk.diag.cwiseProduct(blk.step) - blk.g);
    }

    //! Solves the damped normal equations; @p predicted receives the decrease the model predicts.
    bool solve(double lambda, double& predicted)
    {
        poseDiag_ = dampingDiagonal<6>(U_);
        Matrix6d S = U_;
        S.diagonal() += lambda * poseDiag_;
        Vector6d b = -gp_;
        for (FeatureBlock<3>& blk : pointBlocks_)
            eliminate<3>(blk, lambda, S, b);
        for (FeatureBlock<4>& blk : lineBlocks_)
            eliminate<4>(blk, lambda, S, b);
        Eigen::LDLT<Matrix6d> ldlt(S);
        if (ldlt.info() != Eigen::Success)
            return false;
        poseStep_ = ldlt.solve(b);
        if (!poseStep_.allFinite())
            return false;
        // Model decrease: h^T (lambda D h - g) (Madsen, Nielsen & Tingleff, eq. 3.10).
        predicted = poseStep_.dot(lambda * poseDiag_.cwiseProduct(poseStep_) - gp_);
        for (FeatureBlock<3>& blk : pointBlocks_)
            predicted += backSubstitute<3>(blk, lambda, poseStep_);
        for (FeatureBlock<4>& blk : lineBlocks_)
            predicted += backSubstitute<4>(blk, lambda, poseStep_);
        return std::isfinite(predicted);
    }

    bool applyStep(const Estimate& from, Estimate& to) const
    {
        const Eigen::Vector3d omega = poseStep_.head<3>();
        const double angle = omega.norm();
        to.pose.R = angle > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, omega / angle) * from.pose.R) : from.pose.R;
        to.pose.t = from.pose.t + poseStep_.tail<3>();
        for (size_t k = 0; k < points_.size(); ++k)
            to.points[k] = pointBlocks_[k].solvable ? Eigen::Vector3d(from.points[k] + pointBlocks_[k].step)
                                                    : from.points[k];
        for (size_t k = 0; k < lines_.size(); ++k)
            to.lines[k] = lineBlocks_[k].solvable ? from.lines[k].plus(lineBlocks_[k].step) : from.lines[k];
        return to.pose.R.allFinite() && to.pose.t.allFinite();
    }

    void exportStructure(const Estimate& e, RefinedStructure* out) const
    {
        if (!out)
            return;
        out->points = e.points;
        out->pointUsed.resize(points_.size());
        for (size_t k = 0; k < points_.size(); ++k)
            out->pointUsed[k] = points_[k].used;
        out->lineEnds.assign(2 * lines_.size(), Eigen::Vector3d::Zero());
        out->lineUsed.resize(lines_.size());
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            out->lineUsed[k] = lines_[k].used;
            if (!lines_[k].initialized)
                continue;
            const PluckerLine L = e.lines[k].plucker();
            if (!(L.d.norm() > 0) || !L.m.allFinite())
                continue;
            for (int end = 0; end < 2; ++end)
            {
                const Eigen::Vector3d X =
                    closestPointToRay(L, data_.views[0].calibratedLineEnd(lines_[k].index, end).homogeneous());
                if (X.allFinite())
                    out->lineEnds[2 * k + end] = X;
            }
        }
    }

    const ViewSet& data_;
    Loss loss_;
    int maxIterations_;
    double tolerance_;
    double minDepth_;
    Camera cameras_[3];
    std::vector<SelectedFeature> points_, lines_;

    AlignedVector<FeatureBlock<3>> pointBlocks_;
    AlignedVector<FeatureBlock<4>> lineBlocks_;
    Matrix6d U_;
    Vector6d gp_, poseDiag_, poseStep_;
};

} // namespace

void checkRefineParams(const RefineParams& params, const char* name)
{
    if (!(params.maxIterations > 0))
        CV_Error_(Error::StsBadArg, ("%s.maxIterations must be positive (got %d)", name, params.maxIterations));
    if (params.loss != LOSS_SQUARED && params.loss != LOSS_HUBER && params.loss != LOSS_CAUCHY)
        CV_Error_(Error::StsBadArg, ("%s.loss must be LOSS_SQUARED (0), LOSS_HUBER (1) or LOSS_CAUCHY (2) (got %d)",
                                     name, params.loss));
    if (!(params.lossScale > 0) || !std::isfinite(params.lossScale))
        CV_Error_(Error::StsBadArg, ("%s.lossScale must be a positive, finite number of pixels (got %g)",
                                     name, params.lossScale));
    if (!(params.tolerance >= 0) || !std::isfinite(params.tolerance))
        CV_Error_(Error::StsBadArg, ("%s.tolerance must be finite and >= 0 (got %g)", name, params.tolerance));
}

RefinementSummary refinePoseAndStructure(const ViewSet& data, CameraPose& pose, const RefineParams& params,
                                         const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                                         RefinedStructure* structure)
{
    Refiner refiner(data, params, pointIndices, lineIndices);
    return refiner.run(pose, structure);
}

} // namespace detail
} // namespace tripose
} // namespace cv
