// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_ESTIMATION_RUNS_HPP
#define TRIPOSE_PYTHON_ESTIMATION_RUNS_HPP

// How every arrangement's estimators run once their arguments are read: the core builds and solves
// with the GIL released, and the results become Python objects after. Shared by the three-view,
// stereo-rig and several-views bindings.

#include <vector>

#include <nanobind/nanobind.h>

#include "array_conversions.hpp"
#include "pipeline/pose_pipelines.hpp"
#include "pose_result.hpp"
#include "problem/view_set_builder.hpp"

namespace estimation_runs {

namespace nb = nanobind;

//! The fewest features (points + lines) of each arrangement's problems.
const int kMinFeatures = 4, kMinStereoFeatures = 2, kMinStereoRansacFeatures = 3, kMinRefineFeatures = 3;

//! A robust estimate as a PoseResult (@p found false: no pose).
PoseResult robustResult(bool found, const tripose::RobustEstimate& estimate, const tripose::PoseCovariance& uncertainty);

//! A refined pose, its structure and uncertainty as a PoseResult.
PoseResult refinedResult(const tripose::ViewSet& views, const tripose::CameraPose& pose, double rms,
                         const tripose::RefinedStructure& structure, const tripose::PoseCovariance& uncertainty);

//! Ranked candidates as a PoseResult: the best one as R, t (None without any), all of them in
//! candidates and candidate_rms.
PoseResult candidatesResult(const std::vector<tripose::ScoredPose>& candidates);

//! The candidates of a problem: @p build makes its ViewSet, Solver is its PoseSolver; the GIL is
//! released while they run.
template <class Solver, class Build>
PoseResult runCandidates(Build build, bool refine)
{
    std::vector<tripose::ScoredPose> candidates;
    {
        nb::gil_scoped_release release;
        const tripose::ViewSet views = build();
        const Solver solver(views);
        candidates = tripose::estimateCandidates(views, solver, refine);
    }
    return candidatesResult(candidates);
}

//! The robust estimate of a problem: @p estimate runs the estimator of its arrangement, with
//! @p options, on the ViewSet that @p build makes (GIL released); with refinement, the uncertainty
//! of the refined pose over the inliers.
template <class Build, class Estimate>
PoseResult runRobust(Build build, Estimate estimate, const tripose::RansacOptions& options, bool wantCovariance)
{
    tripose::RobustEstimate result;
    tripose::PoseCovariance uncertainty;
    bool found;
    {
        nb::gil_scoped_release release;
        const tripose::ViewSet views = build();
        found = estimate(views, result);
        // Asked for only: it refines once more over the inliers, about half a RANSAC's time.
        if (wantCovariance && found && options.refine)
            uncertainty = tripose::covarianceOfEstimate(views, result.pose, options.refineOptions,
                                                        &result.pointInliers, &result.lineInliers);
    }
    return robustResult(found, result, uncertainty);
}

//! The refinement of the initial pose (@p R, @p t) over the ViewSet that @p build makes (GIL released).
template <class Build>
PoseResult runRefinement(Build build, const tripose::ArgumentMatrix& R, const tripose::ArgumentMatrix& t,
                       const tripose::RefineOptions& options)
{
    tripose::RefinedStructure structure;
    tripose::PoseCovariance uncertainty;
    tripose::CameraPose pose;
    double rms;
    tripose::ViewSet views;
    {
        nb::gil_scoped_release release;
        views = build();
        pose.R = tripose::readRotation(R);
        pose.t = tripose::readTranslation(t, false);
        rms = tripose::refineInitialPose(views, pose, options, &structure, &uncertainty);
    }
    return refinedResult(views, pose, rms, structure, uncertainty);
}

} // namespace estimation_runs

#endif // TRIPOSE_PYTHON_ESTIMATION_RUNS_HPP
