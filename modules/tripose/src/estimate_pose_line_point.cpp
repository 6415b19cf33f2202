// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/pose_conversion.hpp"
#include "input/problem_input.hpp"
#include "refine/multi_start_refinement.hpp"
#include "linear/linear_solver.hpp"
#include "scoring/pose_scorer.hpp"

namespace cv {
namespace tripose {

namespace {

// Refined candidates closer than this (rotation in radians, translation relative to its norm) are
// one local minimum reached twice.
constexpr double kSameMinimum = 1e-7;

bool sameMinimum(const detail::CameraPose& a, const detail::CameraPose& b)
{
    const double scale = std::max(1e-300, std::max(a.t.norm(), b.t.norm()));
    return (a.R - b.R).norm() <= kSameMinimum && (a.t - b.t).norm() <= kSameMinimum * scale;
}

/** Refines every candidate over the three views, and from the 26 starts around the best-ranked one
that keep its rotation and move the centre of view 3 (refine/multi_start_refinement.hpp); each is
re-triangulated until it settles. Returns the distinct minima that use as many features as the
best one (an RMS over fewer residuals is not comparable), lowest RMS first: with a narrow
known pair or planar structure the linear candidates alone lead refinement to another minimum in
most scenes (doc/accuracy.md). Candidates whose refinement has no usable feature are dropped. */
void refineCandidates(const detail::ViewSet& views, std::vector<detail::ScoredPose>& candidates)
{
    const RefineParams params;
    std::vector<detail::CameraPose> starts;
    for (const detail::ScoredPose& candidate : candidates)
        starts.push_back(candidate.pose);
    if (!candidates.empty())
        detail::centreDirectionStarts(views, candidates.front().pose, starts);
    std::vector<detail::LocalMinimum> minima;
    detail::refineFromStarts(views, starts, params, nullptr, nullptr, &minima);
    std::stable_sort(minima.begin(), minima.end(),
                     [](const detail::LocalMinimum& a, const detail::LocalMinimum& b) { return a.betterThan(b); });
    std::vector<detail::ScoredPose> refined;
    for (const detail::LocalMinimum& m : minima)
    {
        bool repeated = false;
        for (const detail::ScoredPose& r : refined)
            repeated = repeated || sameMinimum(r.pose, m.pose);
        if (repeated || m.used < minima.front().used)
            continue;
        detail::ScoredPose p;
        p.pose = m.pose;
        p.rms = m.rms;
        refined.push_back(p);
    }
    candidates.swap(refined);
}

} // namespace

int estimatePoseLinePoint(InputArray points1, InputArray points2, InputArray points3,
                          InputArray lines1, InputArray lines2, InputArray lines3,
                          InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                          InputArray R12, InputArray t12, OutputArray R, OutputArray t, int method,
                          OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray reprojectionErrors)
{
    CV_INSTRUMENT_REGION();
    if (method != POSE_LINEAR && method != POSE_LINEAR_REFINE)
        CV_Error_(Error::StsBadArg, ("method must be POSE_LINEAR (%d) or POSE_LINEAR_REFINE (%d), got %d",
                                     (int)POSE_LINEAR, (int)POSE_LINEAR_REFINE, method));

    const detail::ViewSet views = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                             cameraMatrix, distCoeffs, R12, t12);
    std::vector<detail::CameraPose> poses;
    detail::linearPoseCandidates(views, poses);
    const detail::PoseScorer scorer(views);
    std::vector<detail::ScoredPose> ranked = detail::rankCandidates(scorer, poses);
    if (method == POSE_LINEAR_REFINE)
        refineCandidates(views, ranked);

    const int n = (int)ranked.size();
    if (n == 0)
    {
        R.release();
        t.release();
    }
    else
    {
        detail::writePose(ranked[0].pose.R, ranked[0].pose.t, R, t);
    }
    if (Rs.needed())
    {
        CV_Assert(Rs.kind() == _InputArray::STD_VECTOR_MAT && "Rs must be a std::vector<Mat>");
        Rs.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            Rs.getMatRef(i) = detail::toMat(ranked[i].pose.R);
    }
    if (ts.needed())
    {
        CV_Assert(ts.kind() == _InputArray::STD_VECTOR_MAT && "ts must be a std::vector<Mat>");
        ts.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            ts.getMatRef(i) = detail::toMat(ranked[i].pose.t);
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

} // namespace tripose
} // namespace cv
