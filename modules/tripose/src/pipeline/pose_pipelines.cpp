// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include <Eigen/Dense>
#include "../opencv_compat.hpp"

#include "../input/pose_conversion.hpp"
#include "../input/problem_input.hpp"
#include "../linear/linear_solver.hpp"
#include "../refine/ml_refinement.hpp"
#include "../refine/multi_start_refinement.hpp"
#include "../refine/multi_start_refiner.hpp"
#include "../robust/robust_estimator.hpp"
#include "../scoring/known_structure.hpp"
#include "../scoring/pose_scorer.hpp"
#include "pose_pipelines.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

// Refined candidates closer than this (rotation in radians, translation relative to its norm) are
// one local minimum reached twice.
constexpr double kSameMinimum = 1e-7;

bool sameMinimum(const CameraPose& a, const CameraPose& b)
{
    const double scale = std::max(1e-300, std::max(a.t.norm(), b.t.norm()));
    return (a.R - b.R).norm() <= kSameMinimum && (a.t - b.t).norm() <= kSameMinimum * scale;
}

/** Refines every candidate over every view and, when the problem has several basins
(@p severalBasins: a narrow known pair or planar structure, scoring/known_structure.hpp), from the
26 starts around the best-ranked one that keep its rotation and move the centre of the estimated
camera (refine/multi_start_refinement.hpp); each is re-triangulated until it settles. Returns the distinct minima that use as many features as
the best one (an RMS over fewer residuals is not comparable), lowest RMS first: with a narrow
known pair or planar structure the linear candidates alone lead refinement to another minimum in
most scenes (doc/accuracy.md). Candidates whose refinement has no usable feature are dropped. */
void refineCandidates(const ViewSet& views, bool severalBasins, std::vector<ScoredPose>& candidates)
{
    const RefineParams params;
    std::vector<CameraPose> starts;
    for (const ScoredPose& candidate : candidates)
        starts.push_back(candidate.pose);
    if (severalBasins && !candidates.empty())
        centreDirectionStarts(views, candidates.front().pose, starts);
    std::vector<LocalMinimum> minima;
    refineFromStarts(views, starts, params, nullptr, nullptr, &minima);
    std::stable_sort(minima.begin(), minima.end(),
                     [](const LocalMinimum& a, const LocalMinimum& b) { return a.betterThan(b); });
    std::vector<ScoredPose> refined;
    for (const LocalMinimum& m : minima)
    {
        bool repeated = false;
        for (const ScoredPose& r : refined)
            repeated = repeated || sameMinimum(r.pose, m.pose);
        if (repeated || m.used < minima.front().used)
            continue;
        ScoredPose p;
        p.pose = m.pose;
        p.rms = m.rms;
        refined.push_back(p);
    }
    candidates.swap(refined);
}

FeatureSubset allFeatures(const ViewSet& views)
{
    FeatureSubset all;
    all.points.resize(views.numPoints);
    all.lines.resize(views.numLines);
    for (int i = 0; i < views.numPoints; ++i)
        all.points[i] = i;
    for (int i = 0; i < views.numLines; ++i)
        all.lines[i] = i;
    return all;
}

void validate(const RansacParams& p)
{
    if (!(p.threshold > 0) || !std::isfinite(p.threshold))
        CV_Error_(Error::StsBadArg, ("params.threshold must be a positive number of pixels, got %g", p.threshold));
    if (!(p.confidence > 0 && p.confidence < 1))
        CV_Error_(Error::StsBadArg, ("params.confidence must be in (0, 1), got %g", p.confidence));
    if (p.maxIterations <= 0)
        CV_Error_(Error::StsBadArg, ("params.maxIterations must be positive, got %d", p.maxIterations));
    if (p.refine)
        checkRefineParams(p.refineParams, "params.refineParams");
}

void writeMask(const std::vector<unsigned char>& mask, OutputArray out)
{
    if (out.needed())
        Mat((int)mask.size(), 1, CV_8U, (void*)mask.data()).copyTo(out);
}

//! How the caller gave the rotation, so that it is written back in the same form.
struct RotationForm
{
    bool rodrigues = false;
    int rows = 3, cols = 3;
};

Eigen::Matrix3d readInitialRotation(InputArray arr, RotationForm& form)
{
    const Mat m = arr.getMat();
    form.rodrigues = m.total() * m.channels() == 3;
    form.rows = m.rows;
    form.cols = m.cols;
    // Validated like R12; returned as an exact rotation, which the multiplicative update needs.
    return readRotation(arr, "R");
}

void writeRotation(const Eigen::Matrix3d& E, const RotationForm& form, OutputArray out)
{
    const Mat R = toMat(E);
    if (!form.rodrigues)
    {
        R.copyTo(out);
        return;
    }
    Mat rvec;
    Rodrigues(R, rvec);
    rvec.reshape(1, form.rows).copyTo(out);
}

} // namespace

void checkPoseMethod(int method)
{
    if (method != POSE_LINEAR && method != POSE_LINEAR_REFINE)
        CV_Error_(Error::StsBadArg, ("method must be POSE_LINEAR (%d) or POSE_LINEAR_REFINE (%d), got %d",
                                     (int)POSE_LINEAR, (int)POSE_LINEAR_REFINE, method));
}

int estimateCandidates(const ViewSet& views, const PoseSolver& solver, int method, OutputArray R, OutputArray t,
                       OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray reprojectionErrors)
{
    std::vector<CameraPose> poses;
    solver.estimateNonMinimal(allFeatures(views), poses);
    const PoseScorer scorer(views);
    std::vector<ScoredPose> ranked = rankCandidates(scorer, poses);
    if (method == POSE_LINEAR_REFINE)
        refineCandidates(views, hasSeveralBasins(views, scorer), ranked);

    const int n = (int)ranked.size();
    if (n == 0)
    {
        R.release();
        t.release();
    }
    else
    {
        writePose(ranked[0].pose.R, ranked[0].pose.t, R, t);
    }
    if (Rs.needed())
    {
        CV_Assert(Rs.kind() == _InputArray::STD_VECTOR_MAT && "Rs must be a std::vector<Mat>");
        Rs.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            Rs.getMatRef(i) = toMat(ranked[i].pose.R);
    }
    if (ts.needed())
    {
        CV_Assert(ts.kind() == _InputArray::STD_VECTOR_MAT && "ts must be a std::vector<Mat>");
        ts.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            ts.getMatRef(i) = toMat(ranked[i].pose.t);
    }
    if (reprojectionErrors.needed())
    {
        Mat errors(n, 1, CV_64F);
        for (int i = 0; i < n; ++i)
            errors.at<double>(i) = ranked[i].rms;
        errors.copyTo(reprojectionErrors);
    }
    return n;
}

int estimateRobust(const ViewSet& views, const PoseSolver& solver, const RansacParams& params, OutputArray R,
                   OutputArray t, OutputArray pointInliers, OutputArray lineInliers)
{
    const PoseScorer scorer(views);
    return estimateRobust(views, scorer, solver, params, R, t, pointInliers, lineInliers);
}

int estimateRobust(const ViewSet& views, const PoseScorer& scorer, const PoseSolver& solver,
                   const RansacParams& params, OutputArray R, OutputArray t, OutputArray pointInliers,
                   OutputArray lineInliers)
{
    validate(params);
    const MultiStartRefiner refiner(views, params.refineParams, &solver, hasSeveralBasins(views, scorer));
    RobustEstimate estimate;
    if (!estimatePoseRobust(solver, scorer, params.refine ? &refiner : nullptr, params, estimate))
    {
        R.release();
        t.release();
        writeMask(std::vector<unsigned char>(views.numPoints, 0), pointInliers);
        writeMask(std::vector<unsigned char>(views.numLines, 0), lineInliers);
        return 0;
    }
    writePose(estimate.pose.R, estimate.pose.t, R, t);
    writeMask(estimate.pointInliers, pointInliers);
    writeMask(estimate.lineInliers, lineInliers);
    return estimate.numInliers;
}

double refineInitialPose(const ViewSet& views, InputOutputArray R, InputOutputArray t, const RefineParams& params,
                         OutputArray points3d, OutputArray lines3d)
{
    RotationForm form;
    CameraPose pose;
    pose.R = readInitialRotation(R, form);
    pose.t = readTranslation(t, "t", false);
    checkRefineParams(params);

    RefinedStructure structure;
    const RefinementSummary summary = refinePoseAndStructure(views, pose, params, nullptr, nullptr, &structure);

    writeRotation(pose.R, form, R);
    Mat(Matx31d(pose.t.x(), pose.t.y(), pose.t.z())).copyTo(t);
    if (points3d.needed())
    {
        points3d.create(views.numPoints, 3, CV_64F);
        Mat out = points3d.getMat();
        for (int i = 0; i < views.numPoints; ++i)
            for (int c = 0; c < 3; ++c)
                out.at<double>(i, c) = structure.points[i](c);
    }
    if (lines3d.needed())
    {
        lines3d.create(views.numLines, 6, CV_64F);
        Mat out = lines3d.getMat();
        for (int i = 0; i < views.numLines; ++i)
            for (int c = 0; c < 3; ++c)
            {
                out.at<double>(i, c) = structure.lineEnds[2 * i](c);
                out.at<double>(i, 3 + c) = structure.lineEnds[2 * i + 1](c);
            }
    }
    return summary.finalRms;
}

} // namespace detail
} // namespace tripose
} // namespace cv
