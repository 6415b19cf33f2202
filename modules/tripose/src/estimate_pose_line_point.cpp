// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "input/pose_conversion.hpp"
#include "input/problem_input.hpp"
#include "refine/ml_refinement.hpp"
#include "linear/linear_solver.hpp"
#include "scoring/pose_scorer.hpp"

namespace cv {
namespace tripose {

namespace {

//! Refines every candidate over the three views and ranks them by the refined RMS error; candidates
//! whose refinement has no usable feature are dropped.
void refineCandidates(const detail::ViewSet& views, std::vector<detail::ScoredPose>& candidates)
{
    const RefineParams params;
    std::vector<detail::ScoredPose> refined;
    for (detail::ScoredPose candidate : candidates)
    {
        const detail::RefinementSummary summary = detail::refinePoseAndStructure(views, candidate.pose, params);
        if (!std::isfinite(summary.finalRms) || !candidate.pose.allFinite())
            continue;
        candidate.rms = summary.finalRms;
        refined.push_back(candidate);
    }
    std::stable_sort(refined.begin(), refined.end(),
                     [](const detail::ScoredPose& a, const detail::ScoredPose& b) { return a.rms < b.rms; });
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
