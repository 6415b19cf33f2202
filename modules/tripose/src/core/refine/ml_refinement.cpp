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
#include <Eigen/Geometry>

#include "../geometry/conditioning.hpp"
#include "../geometry/feature_refit.hpp"
#include "../geometry/line_parameterization.hpp"
#include "../geometry/triangulation.hpp"
#include "ml_refinement.hpp"
#include "../geometry/rotation.hpp"
#include "../geometry/segment_cheirality.hpp"
#include "observation_model.hpp"
#include "robust_loss.hpp"
#include "schur_system.hpp"

namespace tripose {

namespace {

// An RMS of 1e-10 px is an exact fit: nothing is left to gain.
constexpr double kNegligibleSquare = 1e-20;
constexpr double kMaxLambda = 1e16;
// Smallest / largest eigenvalue of the pose information, scaled to a unit diagonal, below which a
// direction of the pose is not determined: its variance would be rounding noise.
constexpr double kDeterminedPose = 1e-12;

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

struct Estimate
{
    std::vector<CameraPose> poses; //!< The estimated poses (ViewAtPose: the cameras views are mounted on).
    std::vector<Eigen::Vector3d> points;
    std::vector<OrthonormalLine> lines;
};

struct SelectedFeature
{
    int index = 0;            //!< Index in the ViewSet.
    bool used = false;        //!< Enters the cost: determined by its views and in front of them.
    bool initialized = false; //!< Has a finite structure estimate (for the output).
};

/** Levenberg-Marquardt over the estimated poses and the structure of the selected features, every
view of the ViewSet contributing the observations it has (observation_model.hpp), the known views
fixed. Each estimated view is mounted on one of the estimated poses (@p poseOfView; -1 for a known
view); P is 6 for one pose, Eigen::Dynamic for several. The normal equations are solved with the
structure eliminated (schur_system.hpp).
*/
template <int P>
class Refiner
{
public:
    Refiner(const ViewSet& set, const std::vector<int>& poseOfView, int numPoses, const RefineOptions& params,
            const std::vector<int>* pointIndices, const std::vector<int>* lineIndices)
        : set_(set), poseOfView_(poseOfView), numPoses_(numPoses), loss_(params.loss, params.lossScale),
          maxIterations_(params.maxIterations), tolerance_(params.tolerance),
          minDepth_(1e-6 * set.knownBaseline()), views_(set.views.size())
    {
        select(pointIndices, set.numPoints, points_);
        select(lineIndices, set.numLines, lines_);
        // Known views never move: set once. setPoses() updates the others.
        for (size_t v = 0; v < views_.size(); ++v)
            views_[v].set(set_.views[v], CameraPose());
    }

    //! Refines @p poses in place; @p covariance (only for one pose) receives the uncertainty of the result.
    RefinementSummary run(std::vector<CameraPose>& poses, RefinedStructure* structure, PoseCovariance* covariance,
                          const RefinedStructure* start = nullptr)
    {
        if (covariance)
            *covariance = PoseCovariance();
        RefinementSummary summary;
        Estimate current;
        current.poses = poses;
        bool finitePose = true;
        for (const CameraPose& pose : poses)
            finitePose = finitePose && pose.allFinite();
        if (finitePose)
        {
            initializeStructure(current);
            if (start)
                continueStructure(*start, current);
        }
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

        system_.resize(points_.size(), lines_.size(), numPoses_);
        Estimate trial = current;
        double lambda = 1e-4, nu = 2;
        bool linearized = false;
        while (summary.iterations < maxIterations_)
        {
            if (cost.squares <= kNegligibleSquare * cost.residuals)
                break;
            if (!linearized)
            {
                linearize(current);
                linearized = true;
            }
            ++summary.iterations;
            double predicted = 0;
            CostSum trialCost;
            const bool stepped = system_.solve(lambda, predicted) && applyStep(current, trial) &&
                                 evaluate(trial, trialCost);
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
        summary.residuals = cost.residuals;
        poses = current.poses;
        exportStructure(current, structure);
        if (covariance)
            estimateCovariance(current, cost, *covariance);
        return summary;
    }

private:
    static void select(const std::vector<int>* indices, int count, std::vector<SelectedFeature>& out)
    {
        out.clear();
        SelectedFeature feature;
        if (indices)
        {
            out.reserve(indices->size());
            for (int i : *indices)
            {
                TRIPOSE_ASSERT(0 <= i && i < count);
                feature.index = i;
                out.push_back(feature);
            }
            return;
        }
        out.reserve(count);
        for (int i = 0; i < count; ++i)
        {
            feature.index = i;
            out.push_back(feature);
        }
    }

    void setPoses(const std::vector<CameraPose>& poses)
    {
        for (size_t v = 0; v < views_.size(); ++v)
            if (poseOfView_[v] >= 0)
                views_[v].set(set_.views[v], poses[poseOfView_[v]]);
    }

    //! The estimated pose that view @p v moves with (any pose for a known view: it is not read).
    const CameraPose& mountOf(const Estimate& e, size_t v) const
    {
        return e.poses[std::max(poseOfView_[v], 0)];
    }

    /** Initial structure from every view that sees the feature, the estimated ones at the initial
    pose: with a narrow known pair the known views alone would place the structure far off and cost
    many iterations. Features that the views do not determine, or points behind a camera, stay out
    of the cost. */
    void initializeStructure(Estimate& e)
    {
        setPoses(e.poses);
        std::vector<CameraPose> poses(views_.size());
        for (size_t v = 0; v < views_.size(); ++v)
            poses[v] = views_[v].pose;

        e.points.assign(points_.size(), Eigen::Vector3d::Zero());
        for (size_t k = 0; k < points_.size(); ++k)
        {
            const int i = points_[k].index;
            Eigen::Vector3d X = Eigen::Vector3d::Zero();
            const bool triangulated =
                triangulatePoint(set_, poses.data(), i, ViewSelection::All, X, kPointTriangulationConditioning,
                                 minDepth_) > 0;
            points_[k].initialized = triangulated;
            if (!triangulated)
                continue;
            e.points[k] = X;
            bool inFront = true;
            for (size_t v = 0; v < views_.size() && inFront; ++v)
                inFront = !set_.views[v].seesPoint(i) || poses[v].toCamera(X).z() > minDepth_;
            points_[k].used = inFront;
        }

        e.lines.assign(lines_.size(), OrthonormalLine());
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            const int i = lines_[k].index;
            PluckerLine L;
            if (!(triangulateLine(set_, poses.data(), i, ViewSelection::All, L, kLineTriangulationConditioning) &&
                  OrthonormalLine::fromPlucker(L, e.lines[k])))
            {
                // Not determined by the views: keep any finite fit for the output, outside the cost.
                lines_[k].initialized = triangulateLine(set_, poses.data(), i, ViewSelection::All, L, 0.0) &&
                                        OrthonormalLine::fromPlucker(L, e.lines[k]);
                continue;
            }
            lines_[k].initialized = true;
            const PluckerLine fitted = e.lines[k].plucker();
            bool imaged = true;
            for (size_t v = 0; v < views_.size() && imaged; ++v)
            {
                const View& view = set_.views[v];
                Eigen::Vector2d r;
                imaged = !view.seesLine(i) ||
                         lineObservation(views_[v], mountOf(e, v), fitted, view.lineEnds[2 * i], view.lineEnds[2 * i + 1], r);
            }
            lines_[k].used = imaged;
        }
    }

    /** Takes the structure of the features that @p start used (an earlier refinement of the same
    features, RefinedStructure) over the triangulation, where this refinement uses them too. */
    void continueStructure(const RefinedStructure& start, Estimate& e) const
    {
        if (start.points.size() == points_.size() && start.pointUsed.size() == points_.size())
            for (size_t k = 0; k < points_.size(); ++k)
                if (points_[k].used && start.pointUsed[k] && start.points[k].allFinite())
                    e.points[k] = start.points[k];
        if (start.lineEnds.size() != 2 * lines_.size() || start.lineUsed.size() != lines_.size())
            return;
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            if (!lines_[k].used || !start.lineUsed[k])
                continue;
            const Eigen::Vector3d& A = start.lineEnds[2 * k];
            const Eigen::Vector3d& B = start.lineEnds[2 * k + 1];
            PluckerLine L;
            L.d = B - A;
            L.m = A.cross(B);
            OrthonormalLine line;
            if (A.allFinite() && B.allFinite() && OrthonormalLine::fromPlucker(L, line))
                e.lines[k] = line;
        }
    }

    //! Robust cost of an estimate; false when a used feature became degenerate (behind a camera,
    //! line through a centre) or a value is not finite.
    bool evaluate(const Estimate& e, CostSum& cost)
    {
        setPoses(e.poses);
        cost = CostSum();
        Eigen::Vector2d r;
        for (size_t k = 0; k < points_.size(); ++k)
        {
            if (!points_[k].used)
                continue;
            const int i = points_[k].index;
            for (size_t vi = 0; vi < views_.size(); ++vi)
            {
                const ViewAtPose& v = views_[vi];
                if (!v.view->seesPoint(i))
                    continue;
                if (!pointObservation(v, mountOf(e, vi), e.points[k], v.view->points[i], minDepth_, r))
                    return false;
                const double s = r.squaredNorm();
                cost.add(s, loss_.evaluate(s));
            }
        }
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            if (!lines_[k].used)
                continue;
            const int i = lines_[k].index;
            const PluckerLine L = e.lines[k].plucker();
            for (size_t vi = 0; vi < views_.size(); ++vi)
            {
                const ViewAtPose& v = views_[vi];
                if (!v.view->seesLine(i))
                    continue;
                if (!lineObservation(v, mountOf(e, vi), L, v.view->lineEnds[2 * i], v.view->lineEnds[2 * i + 1], r))
                    return false;
                const double s = r.squaredNorm();
                cost.add(s, loss_.evaluate(s));
            }
        }
        return std::isfinite(cost.robust) && std::isfinite(cost.squares);
    }

    //! The normal equations at @p e (which evaluate() accepted: every residual of a used feature is defined).
    void linearize(const Estimate& e)
    {
        setPoses(e.poses);
        system_.clear();
        Eigen::Vector2d r;
        Matrix23d Jpoint;
        Matrix24d Jline;
        Matrix26d Jpose;
        double weight = 1;
        weightedSquares_ = 0;
        for (size_t k = 0; k < points_.size(); ++k)
        {
            if (!points_[k].used)
                continue;
            const int i = points_[k].index;
            StructureBlock<3, P>& block = system_.begin(system_.point(k));
            for (size_t vi = 0; vi < views_.size(); ++vi)
            {
                const ViewAtPose& v = views_[vi];
                if (!v.view->seesPoint(i))
                    continue;
                if (!pointObservation(v, mountOf(e, vi), e.points[k], v.view->points[i], minDepth_, r, &Jpoint,
                                      &Jpose))
                    continue;
                loss_.evaluate(r.squaredNorm(), &weight);
                weightedSquares_ += weight * r.squaredNorm();
                system_.template add<3>(block, Jpoint, v.moves ? &Jpose : nullptr, r, weight, poseOfView_[vi]);
            }
        }
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            if (!lines_[k].used)
                continue;
            const int i = lines_[k].index;
            const PluckerLine L = e.lines[k].plucker();
            const Eigen::Matrix<double, 6, 4> chart = e.lines[k].pluckerJacobian();
            StructureBlock<4, P>& block = system_.begin(system_.line(k));
            for (size_t vi = 0; vi < views_.size(); ++vi)
            {
                const ViewAtPose& v = views_[vi];
                if (!v.view->seesLine(i))
                    continue;
                if (!lineObservation(v, mountOf(e, vi), L, v.view->lineEnds[2 * i], v.view->lineEnds[2 * i + 1], r,
                                     &chart, &Jline, &Jpose))
                    continue;
                loss_.evaluate(r.squaredNorm(), &weight);
                weightedSquares_ += weight * r.squaredNorm();
                system_.template add<4>(block, Jline, v.moves ? &Jpose : nullptr, r, weight, poseOfView_[vi]);
            }
        }
    }

    /** The uncertainty of the pose at @p e, whose cost is @p cost: the Gauss-Newton normal
    equations at @p e with the structure marginalised (ml_refinement.hpp, PoseCovariance). */
    void estimateCovariance(const Estimate& e, const CostSum& cost, PoseCovariance& out)
    {
        TRIPOSE_DEBUG_ASSERT(numPoses_ == 1);
        linearize(e);
        typename SchurSystem<P>::PoseMatrix information;
        if (!system_.reducedPoseMatrix(information))
            return;
        const Matrix6d symmetric = 0.5 * (information.template topLeftCorner<6, 6>() +
                                          information.template topLeftCorner<6, 6>().transpose());
        // Rotation (rad) and translation (scene units) differ in scale: judge the rank on the
        // matrix scaled to a unit diagonal, where rounding leaves a direction that no residual sees
        // at an eigenvalue near 1e-16 instead of exactly zero.
        const Vector6d diagonal = symmetric.diagonal();
        if (!(diagonal.minCoeff() > 0))
            return;
        const Vector6d scale = diagonal.cwiseSqrt().cwiseInverse();
        const Matrix6d scaled = scale.asDiagonal() * symmetric * scale.asDiagonal();
        const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(scaled);
        if (eigen.info() != Eigen::Success || !(eigen.eigenvalues()(0) > kDeterminedPose * eigen.eigenvalues()(5)))
            return;
        const Matrix6d inverse = scale.asDiagonal() *
                                 (eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().asDiagonal() *
                                  eigen.eigenvectors().transpose()) *
                                 scale.asDiagonal();
        if (!inverse.allFinite())
            return;
        out.covariance = 0.5 * (inverse + inverse.transpose());
        int parameters = 6;
        for (const SelectedFeature& f : points_)
            parameters += f.used ? 3 : 0;
        for (const SelectedFeature& f : lines_)
            parameters += f.used ? 4 : 0;
        const int redundancy = cost.residuals - parameters;
        out.noiseVariance = redundancy > 0 ? weightedSquares_ / redundancy : std::numeric_limits<double>::infinity();
        out.valid = true;
    }

    bool applyStep(const Estimate& from, Estimate& to) const
    {
        bool finite = true;
        for (int p = 0; p < numPoses_; ++p)
        {
            const Vector6d step = system_.poseStep().template segment<6>(6 * p);
            const Eigen::Vector3d omega = step.head<3>();
            const CameraPose& a = from.poses[p];
            CameraPose& b = to.poses[p];
            b.R = rotateLeft(omega, a.R);
            b.t = a.t + step.tail<3>();
            finite = finite && b.allFinite();
        }
        for (size_t k = 0; k < points_.size(); ++k)
        {
            const StructureBlock<3, P>& block = system_.point(k);
            to.points[k] = block.active ? Eigen::Vector3d(from.points[k] + block.step) : from.points[k];
        }
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            const StructureBlock<4, P>& block = system_.line(k);
            to.lines[k] = block.active ? from.lines[k].plus(block.step) : from.lines[k];
        }
        return finite;
    }

    /** Whether every view that sees line @p i saw a part of @p L in front of it
    (geometry/segment_cheirality.hpp). Judged on the result, not imposed during the iteration: a
    line triangulated at a poor start may be mirrored through a centre and come back. */
    bool segmentsInFront(const Estimate& e, int i, const PluckerLine& L) const
    {
        for (size_t v = 0; v < set_.views.size(); ++v)
        {
            const View& view = set_.views[v];
            if (view.seesLine(i) && segmentBehindCamera(view.poseFor(mountOf(e, v)), L, view.calibratedLineEnd(i, 0),
                                                        view.calibratedLineEnd(i, 1)))
                return false;
        }
        return true;
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
        out->lineInFront.assign(lines_.size(), 0);
        for (size_t k = 0; k < lines_.size(); ++k)
        {
            out->lineUsed[k] = lines_[k].used;
            if (!lines_[k].initialized)
                continue;
            const PluckerLine L = e.lines[k].plucker();
            if (!(L.d.norm() > 0) || !L.m.allFinite())
                continue;
            out->lineInFront[k] = segmentsInFront(e, lines_[k].index, L);
            // The end points as the first view that sees the line observed them.
            const int i = lines_[k].index;
            for (size_t v = 0; v < set_.views.size(); ++v)
            {
                const View& view = set_.views[v];
                if (!view.seesLine(i))
                    continue;
                Eigen::Vector3d ends[2];
                lineEndsSeenBy(view, view.poseFor(mountOf(e, v)), i, L, ends[0], ends[1]);
                for (int end = 0; end < 2; ++end)
                    if (ends[end].allFinite())
                        out->lineEnds[2 * k + end] = ends[end];
                break;
            }
        }
    }

    const ViewSet& set_;
    const std::vector<int> poseOfView_;
    const int numPoses_;
    RobustLossFunction loss_;
    int maxIterations_;
    double tolerance_;
    double minDepth_;
    std::vector<ViewAtPose> views_;
    std::vector<SelectedFeature> points_, lines_;
    SchurSystem<P> system_;
    double weightedSquares_ = 0; //!< Sum of the IRLS-weighted squared residuals at the last linearisation.
};

} // namespace

RefinementSummary refinePoseAndStructure(const ViewSet& set, CameraPose& pose, const RefineOptions& params,
                                         const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                                         RefinedStructure* structure, PoseCovariance* covariance,
                                         const RefinedStructure* start)
{
    std::vector<int> poseOfView(set.views.size());
    for (size_t v = 0; v < set.views.size(); ++v)
        poseOfView[v] = set.views[v].estimated ? 0 : -1;
    Refiner<6> refiner(set, poseOfView, 1, params, pointIndices, lineIndices);
    std::vector<CameraPose> poses(1, pose);
    const RefinementSummary summary = refiner.run(poses, structure, covariance, start);
    pose = poses[0];
    return summary;
}

RefinementSummary refinePosesAndStructure(const ViewSet& set, const std::vector<int>& poseOfView,
                                          std::vector<CameraPose>& poses, const RefineOptions& params,
                                          RefinedStructure* structure)
{
    TRIPOSE_ASSERT(poseOfView.size() == set.views.size());
    for (size_t v = 0; v < set.views.size(); ++v)
        TRIPOSE_ASSERT(set.views[v].estimated == (poseOfView[v] >= 0) && poseOfView[v] < (int)poses.size());
    Refiner<Eigen::Dynamic> refiner(set, poseOfView, (int)poses.size(), params, nullptr, nullptr);
    return refiner.run(poses, structure, nullptr);
}

} // namespace tripose
