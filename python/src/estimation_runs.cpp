// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "estimation_runs.hpp"

#include <limits>
#include <tuple>

namespace estimation_runs {

using namespace array_conversions;

namespace {

//! The pose's uncertainty into @p out: covariance (6, 6) and noise_variance, both None when not valid.
void writeCovariance(const tripose::PoseCovariance& uncertainty, PoseResult& out)
{
    if (!uncertainty.valid)
        return;
    const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> rowMajor = uncertainty.covariance;
    out.covariance = newArray({ 6, 6 }, rowMajor.data());
    out.noise_variance = nb::float_(uncertainty.noiseVariance);
}

} // namespace

PoseResult robustResult(bool found, const tripose::RobustEstimate& estimate, const tripose::PoseCovariance& uncertainty)
{
    PoseResult out;
    out.kind = PoseResult::Kind::Robust;
    out.hasPose = found;
    if (found)
    {
        out.rotation = estimate.pose.R;
        out.translation = estimate.pose.t;
        out.R = rotationArray(estimate.pose.R);
        out.t = vectorArray(estimate.pose.t);
    }
    out.num_inliers = nb::int_(found ? estimate.numInliers : 0);
    out.point_inliers = maskArray(estimate.pointInliers);
    out.line_inliers = maskArray(estimate.lineInliers);
    out.numPoints = (int)estimate.pointInliers.size();
    out.numLines = (int)estimate.lineInliers.size();
    for (unsigned char inlier : estimate.pointInliers)
        out.pointInliers += inlier != 0;
    for (unsigned char inlier : estimate.lineInliers)
        out.lineInliers += inlier != 0;
    out.rmsValue = found ? estimate.inlierRms : std::numeric_limits<double>::quiet_NaN();
    out.rms = nb::float_(out.rmsValue);
    writeCovariance(uncertainty, out);
    // The minima of the final refinement that the data cannot tell apart (the returned pose first).
    out.candidates = candidateList(estimate.minima);
    nb::list rms;
    for (const tripose::ScoredPose& m : estimate.minima)
        rms.append(m.rms);
    out.candidate_rms = rms;
    out.numCandidates = (int)estimate.minima.size();
    out.ambiguous = nb::bool_(estimate.minima.size() > 1);
    return out;
}

PoseResult candidatesResult(const std::vector<tripose::ScoredPose>& candidates)
{
    PoseResult out;
    out.kind = PoseResult::Kind::Candidates;
    out.candidates = candidateList(candidates);
    nb::list rms;
    for (const tripose::ScoredPose& candidate : candidates)
        rms.append(candidate.rms);
    out.candidate_rms = rms;
    out.numCandidates = (int)candidates.size();
    out.hasPose = !candidates.empty();
    if (out.hasPose)
    {
        // The best candidate's arrays are the views that its (R, t) in candidates holds.
        const nb::object best = out.candidates[nb::int_(0)];
        out.R = best[nb::int_(0)];
        out.t = best[nb::int_(1)];
        out.rotation = candidates[0].pose.R;
        out.translation = candidates[0].pose.t;
        out.rmsValue = candidates[0].rms;
        out.rms = nb::float_(out.rmsValue);
    }
    return out;
}

PoseResult refinedResult(const tripose::ViewSet& views, const tripose::CameraPose& pose, double rms,
                         const tripose::RefinedStructure& structure, const tripose::PoseCovariance& uncertainty)
{
    PoseResult out;
    out.kind = PoseResult::Kind::Refined;
    out.hasPose = true;
    out.rotation = pose.R;
    out.translation = pose.t;
    out.R = rotationArray(pose.R);
    out.t = vectorArray(pose.t);
    out.rmsValue = rms;
    out.rms = nb::float_(rms);
    std::tie(out.points3d, out.lines3d) = structureArrays(structure.points, structure.lineEnds, views.numPoints,
                                                          views.numLines);
    out.numPoints = views.numPoints;
    out.numLines = views.numLines;
    writeCovariance(uncertainty, out);
    return out;
}

} // namespace estimation_runs
