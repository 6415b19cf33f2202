// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Geometry>

#include "candidate_scoring.hpp"
#include "linear_solver.hpp"
#include "ml_refinement.hpp"
#include "robust_estimator.hpp"
#include "sample_generator.hpp"
#include "three_view_residuals.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

constexpr int kSampleSize = 4;
constexpr int kLocalOptimizationRounds = 3;
// The sampling loop measures view-3 residuals against structure triangulated from views 1-2 alone,
// which carries the triangulation error of those views on top of the image noise; it tests them
// against twice the user's threshold. The final inliers use residuals over all three views
// (threeViewResiduals) against the threshold itself.
constexpr double kSamplingThresholdFactor = 2.0;
//! Candidates of a minimal sample. Twisted pairs double the hypotheses to score for little gain
//! here: local optimisation and refinement on the inliers repair the hypotheses that are merely
//! close. With few features (@p enumerated samples) there is little to repair them with, and the
//! kernel basis ordered by fit gives the better hypotheses (VGG 3P+2L: upper-quartile rotation
//! error 0.95-1.25 deg instead of 3.7-5.3); with many it only costs time (about 15 % at 100P+40L
//! with 50 % outliers).
CandidateOptions sampleCandidateOptions(bool enumerated)
{
    CandidateOptions options;
    options.twistedPairs = false;
    options.orderedKernel = enumerated;
    return options;
}

//! A model's support: MSAC cost and the inliers it implies.
struct Support
{
    double cost = std::numeric_limits<double>::infinity();
    int inliers = 0;
};

class RobustEstimator
{
public:
    RobustEstimator(const TripletData& data, const RansacParams& params)
        : data_(data), params_(params), structure_(triangulateTwoViewStructure(data)),
          threshold2_(kSamplingThresholdFactor * kSamplingThresholdFactor * params.threshold * params.threshold)
    {
        // Flat arrays of what the early-exit cost needs; features without two-view structure
        // always cost the full threshold.
        for (int i = 0; i < data.numPoints(); ++i)
        {
            if (structure_.pointValid[i])
            {
                scoredPoints_.push_back(structure_.points[i]);
                observedPoints_.push_back(data.pixels[2].points[i]);
            }
            else
                invalidCost_ += threshold2_;
        }
        for (int i = 0; i < data.numLines(); ++i)
        {
            if (structure_.lineValid[i])
                for (int end = 0; end < 2; ++end)
                {
                    scoredLineEnds_.push_back(structure_.lineEnds[2 * i + end]);
                    observedLineEnds_.push_back(data.pixels[2].lineEnds[2 * i + end]);
                }
            else
                invalidCost_ += threshold2_;
        }
    }

    bool run(RobustEstimate& estimate)
    {
        const int numFeatures = data_.numFeatures();
        SampleGenerator samples(numFeatures, kSampleSize, params_.maxIterations, (uint64)(int64)params_.seed);
        std::vector<int> sample(kSampleSize), samplePoints, sampleLines;
        std::vector<CameraPose> candidates;
        const CandidateOptions sampleOptions = sampleCandidateOptions(samples.enumerates());
        long maxIterations = params_.maxIterations;
        int iteration = 0;
        for (; iteration < maxIterations && samples.next(sample); ++iteration)
        {
            samplePoints.clear();
            sampleLines.clear();
            for (int f : sample)
                (f < data_.numPoints() ? samplePoints : sampleLines).push_back(f < data_.numPoints() ? f : f - data_.numPoints());
            candidates.clear();
            linearPoseCandidates(data_, candidates, &samplePoints, &sampleLines, sampleOptions);
            if (!keepBest(candidates))
                continue;
            if (params_.localOptimization)
                optimizeLocally();
            maxIterations = std::min<long>(maxIterations, requiredIterations(best_.inliers, numFeatures));
        }
        // With few features every sample was tried, and the structure of views 1-2 alone may put
        // all their residuals over the threshold (four features: the one sample has no redundancy
        // to test). Then the linear solution over all features, ranked as the linear solver ranks
        // it, goes on to the three-view inlier test below.
        bool haveModel = std::isfinite(best_.cost) && best_.inliers > 0;
        if (!haveModel && samples.enumerates())
            haveModel = adoptLinearSolution();
        if (!haveModel)
            return false;

        estimate.iterations = iteration;
        estimate.pose = bestPose_;
        // Final inliers: consistency with all three views under the pose. Refinement on them may
        // change the classification; one more round settles it.
        estimate.numInliers = inlierMasks(estimate.pose, estimate.pointInliers, estimate.lineInliers);
        for (int round = 0; round < 2 && params_.refine; ++round)
        {
            refineOnInliers(estimate.pose, estimate.pointInliers, estimate.lineInliers);
            std::vector<unsigned char> points, lines;
            estimate.numInliers = inlierMasks(estimate.pose, points, lines);
            const bool settled = points == estimate.pointInliers && lines == estimate.lineInliers;
            estimate.pointInliers.swap(points);
            estimate.lineInliers.swap(lines);
            if (settled)
                break;
        }
        return estimate.numInliers > 0;
    }

private:
    //! The linear solver's best pose over all features as the best model; false if it has none.
    bool adoptLinearSolution()
    {
        std::vector<CameraPose> poses;
        linearPoseCandidates(data_, poses);
        const std::vector<ScoredPose> ranked = rankCandidates(data_, structure_, poses);
        if (ranked.empty())
            return false;
        bestPose_ = ranked.front().pose;
        best_ = support(bestPose_);
        return true;
    }

    //! Makes the cheapest of @p poses the best model if it beats it; true if it did.
    bool keepBest(const std::vector<CameraPose>& poses)
    {
        bool improved = false;
        for (const CameraPose& pose : poses)
        {
            // Most hypotheses are bad: stop adding up their cost once it exceeds the best.
            if (!(truncatedCost(pose, best_.cost) < best_.cost))
                continue;
            const Support s = support(pose);
            if (s.cost < best_.cost)
            {
                best_ = s;
                bestPose_ = pose;
                improved = true;
            }
        }
        return improved;
    }

    //! The MSAC cost of a pose, abandoned (+inf) as soon as it exceeds @p bound.
    double truncatedCost(const CameraPose& pose, double bound) const
    {
        const Eigen::Matrix3d& K = data_.pixels[2].K;
        const Eigen::Matrix3d KR = K * pose.R;
        const Eigen::Vector3d Kt = K * pose.t;
        const double inf = std::numeric_limits<double>::infinity();
        double cost = invalidCost_;
        for (size_t i = 0; i < scoredPoints_.size(); ++i)
        {
            const Eigen::Vector3d x = KR * scoredPoints_[i] + Kt;
            cost += x.z() > 0 ? std::min((x.hnormalized() - observedPoints_[i]).squaredNorm(), threshold2_) : threshold2_;
            if (cost > bound)
                return inf;
        }
        for (size_t i = 0; i < scoredLineEnds_.size(); i += 2)
        {
            const Eigen::Vector3d a = KR * scoredLineEnds_[i] + Kt, b = KR * scoredLineEnds_[i + 1] + Kt;
            double r2 = threshold2_;
            if (a.z() > 0 && b.z() > 0)
            {
                Eigen::Vector3d line = a.cross(b);
                const double n2 = line.head<2>().squaredNorm();
                if (n2 > 0)
                {
                    const double d0 = line.dot(observedLineEnds_[i].homogeneous());
                    const double d1 = line.dot(observedLineEnds_[i + 1].homogeneous());
                    r2 = std::min(0.5 * (d0 * d0 + d1 * d1) / n2, threshold2_);
                }
            }
            cost += r2;
            if (cost > bound)
                return inf;
        }
        return cost;
    }

    //! Truncated quadratic cost over all features and the number of features under the threshold.
    Support support(const CameraPose& pose)
    {
        scorePose(data_, structure_, pose, &pointResiduals_, &lineResiduals_);
        Support s;
        s.cost = 0;
        for (const std::vector<double>* residuals : { &pointResiduals_, &lineResiduals_ })
            for (double r : *residuals)
            {
                const double r2 = r * r;
                if (r2 < threshold2_)
                {
                    s.cost += r2;
                    ++s.inliers;
                }
                else
                    s.cost += threshold2_;
            }
        return s;
    }

    void collectInliers(const CameraPose& pose, std::vector<int>& points, std::vector<int>& lines)
    {
        scorePose(data_, structure_, pose, &pointResiduals_, &lineResiduals_);
        points.clear();
        lines.clear();
        for (int i = 0; i < (int)pointResiduals_.size(); ++i)
            if (pointResiduals_[i] * pointResiduals_[i] < threshold2_)
                points.push_back(i);
        for (int i = 0; i < (int)lineResiduals_.size(); ++i)
            if (lineResiduals_[i] * lineResiduals_[i] < threshold2_)
                lines.push_back(i);
    }

    //! Re-solves from the inliers of the best model while that lowers the cost.
    void optimizeLocally()
    {
        std::vector<int> points, lines;
        std::vector<CameraPose> poses;
        for (int round = 0; round < kLocalOptimizationRounds; ++round)
        {
            collectInliers(bestPose_, points, lines);
            if ((int)(points.size() + lines.size()) < 6) // below six the linear solve is not over-determined
                return;
            poses.clear();
            linearPoseCandidates(data_, poses, &points, &lines);
            if (!keepBest(poses))
                return;
        }
    }

    void refineOnInliers(CameraPose& pose, const std::vector<unsigned char>& pointMask,
                         const std::vector<unsigned char>& lineMask)
    {
        std::vector<int> points, lines;
        for (int i = 0; i < (int)pointMask.size(); ++i)
            if (pointMask[i])
                points.push_back(i);
        for (int i = 0; i < (int)lineMask.size(); ++i)
            if (lineMask[i])
                lines.push_back(i);
        if (points.size() + lines.size() < 3)
            return;
        CameraPose refined = pose;
        refinePoseAndStructure(data_, refined, RefineParams(), &points, &lines);
        if (refined.R.allFinite() && refined.t.allFinite())
            pose = refined;
    }

    //! Inliers by their residual over the three views (see threeViewResiduals()).
    int inlierMasks(const CameraPose& pose, std::vector<unsigned char>& pointMask, std::vector<unsigned char>& lineMask)
    {
        threeViewResiduals(data_, pose, pointResiduals_, lineResiduals_);
        int count = 0;
        pointMask.resize(pointResiduals_.size());
        for (size_t i = 0; i < pointResiduals_.size(); ++i)
            count += pointMask[i] = pointResiduals_[i] < params_.threshold;
        lineMask.resize(lineResiduals_.size());
        for (size_t i = 0; i < lineResiduals_.size(); ++i)
            count += lineMask[i] = lineResiduals_[i] < params_.threshold;
        return count;
    }

    //! Samples needed to draw one all-inlier sample with the requested confidence.
    long requiredIterations(int inliers, int numFeatures) const
    {
        const double w = double(inliers) / numFeatures;
        const double allInliers = std::pow(w, kSampleSize);
        if (allInliers >= 1.0)
            return 1;
        if (allInliers <= 0.0)
            return params_.maxIterations;
        // log1p: for a tiny all-inlier probability 1 - p rounds to 1 and log(1 - p) to 0, which
        // made n -inf and its conversion to an integer undefined.
        const double n = std::log1p(-params_.confidence) / std::log1p(-allInliers);
        if (!(n < params_.maxIterations))
            return params_.maxIterations;
        return (long)std::ceil(n);
    }

    const TripletData& data_;
    const RansacParams& params_;
    const TwoViewStructure structure_;
    const double threshold2_;
    std::vector<double> pointResiduals_, lineResiduals_;
    std::vector<Eigen::Vector3d> scoredPoints_, scoredLineEnds_;
    std::vector<Eigen::Vector2d> observedPoints_, observedLineEnds_;
    double invalidCost_ = 0;
    Support best_;
    CameraPose bestPose_;
};

} // namespace

bool estimatePoseRobust(const TripletData& data, const RansacParams& params, RobustEstimate& estimate)
{
    return RobustEstimator(data, params).run(estimate);
}

} // namespace detail
} // namespace tripose
} // namespace cv
