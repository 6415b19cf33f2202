// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Several views at known world poses: a new view registered against them, free views adjusted with
// them, or the structure triangulated from them.

#include "multiview_bindings.hpp"

#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "array_conversions.hpp"
#include "estimation_runs.hpp"
#include "linear/multiview_pose_solver.hpp"
#include "options_bindings.hpp"
#include "pipeline/posed_structure.hpp"

namespace nb = nanobind;
using namespace array_conversions;
using namespace estimation_runs;

namespace {

//! Views that each may miss features: @p numViews of them, the arrays named points[v], lines[v].
tripose::ProblemArguments readPosedViews(nb::handle points, nb::handle lines, nb::handle K, nb::handle dist,
                                         size_t numViews)
{
    if (points.is_none() && lines.is_none())
        throw nb::value_error("points and lines are both None: at least four features are required");
    const std::vector<nb::object> pointArrays = readViewList(points, "points", numViews);
    const std::vector<nb::object> lineArrays = readViewList(lines, "lines", numViews);
    tripose::ProblemArguments args;
    for (size_t v = 0; v < numViews; ++v)
        args.views.push_back(readView(pointArrays[v], lineArrays[v], "points[" + std::to_string(v) + "]",
                                      "lines[" + std::to_string(v) + "]", true));
    readCalibration(K, dist, args);
    return args;
}

//! Views at the world poses Rs, ts, plus @p unposedViews new views, every view free to miss features.
struct MultiViewProblem
{
    std::vector<tripose::ArgumentMatrix> rotations, translations;
    tripose::ProblemArguments arguments;

    MultiViewProblem(nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
                     size_t unposedViews)
        : rotations(readPoseList(Rs, "Rs", true)), translations(readPoseList(ts, "ts", false)),
          arguments(readPosedViews(points, lines, K, dist, rotations.size() + unposedViews))
    {
    }

    //! The registration of one new view (estimatePoseMultiView's layout).
    std::function<tripose::ViewSet()> newViewBuilder() const
    {
        return [this] { return tripose::buildMultiViewSet(arguments, rotations, translations, kMinFeatures); };
    }
};

} // namespace

void bindMultiView(nb::module_& m)
{
    m.def("estimate_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             bool refine) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              return runCandidates<tripose::MultiViewPoseSolver>(problem.newViewBuilder(), refine);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_multiview_ransac",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             const tripose::RansacOptions* given, const std::string& optionsName, bool wantCovariance) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::RansacOptions options = checkedRansacOptions(given, optionsName);
              return runRobust(problem.newViewBuilder(),
                               [&](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   const tripose::MultiViewPoseSolver linear(views);
                                   return tripose::estimateRobustOnKnownStructure(views, linear, options, estimate);
                               },
                               options, wantCovariance);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"), nb::arg("covariance"));

    m.def("refine_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle R,
             nb::handle t, nb::handle dist, const tripose::RefineOptions* given,
             const std::string& optionsName) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = checkedRefineOptions(given, optionsName);
              return runRefinement(problem.newViewBuilder(), Rm, tm, options);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("adjust_poses_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, const std::vector<int>& fixedViews, nb::handle Rs,
             nb::handle ts, nb::handle dist, const tripose::RefineOptions* given,
             const std::string& optionsName) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 0);
              const tripose::RefineOptions options = checkedRefineOptions(given, optionsName);
              tripose::RefinedStructure structure;
              std::vector<tripose::CameraPose> all;
              double rms;
              tripose::ViewSet views;
              {
                  nb::gil_scoped_release release;
                  std::vector<int> poseOfView;
                  std::vector<tripose::CameraPose> poses;
                  views = tripose::buildSeveralPosesSet(problem.arguments, problem.rotations, problem.translations,
                                                        fixedViews, "fixed_views", poseOfView, poses);
                  rms = tripose::refineSeveralPoses(views, poseOfView, poses, options, &structure);
                  all = tripose::allViewPoses(views, poseOfView, poses);
              }
              PoseResult out;
              out.kind = PoseResult::Kind::Adjusted;
              nb::list Rout, tout;
              for (const tripose::CameraPose& pose : all)
              {
                  Rout.append(rotationArray(pose.R));
                  tout.append(vectorArray(pose.t));
              }
              out.Rs = Rout;
              out.ts = tout;
              out.numPoses = (int)all.size();
              out.rmsValue = rms;
              out.rms = nb::float_(rms);
              std::tie(out.points3d, out.lines3d) = structureArrays(structure.points, structure.lineEnds, views.numPoints,
                                                                    views.numLines);
              return out;
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("fixed_views"), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("triangulate_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 0);
              tripose::PosedStructure structure;
              tripose::ViewSet views;
              {
                  nb::gil_scoped_release release;
                  views = tripose::buildPosedViewSet(problem.arguments, problem.rotations, problem.translations);
                  structure = tripose::triangulateStructure(views);
              }
              const size_t numViews = views.views.size();
              nb::dict out;
              writeStructure(structure.points, structure.lineEnds, views.numPoints, views.numLines, out);
              out["point_errors"] = newArray({ (size_t)views.numPoints, numViews }, structure.pointErrors.data());
              out["line_errors"] = newArray({ (size_t)views.numLines, numViews }, structure.lineErrors.data());
              out["num_with_structure"] = structure.numWithStructure;
              return out;
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none());
}
