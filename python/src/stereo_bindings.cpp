// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The stereo rig (a calibrated pair at times A and B, the left camera at time B estimated): read and
// run as the three-view problem.

#include "stereo_bindings.hpp"

#include <functional>
#include <string>

#include <nanobind/stl/string.h>

#include "array_conversions.hpp"
#include "estimation_runs.hpp"
#include "linear/rig_pose_solver.hpp"
#include "options_bindings.hpp"

namespace nb = nanobind;
using namespace array_conversions;
using namespace estimation_runs;

namespace {

/** The stereo rig's arguments (views 3 and 4 may miss features), converted while the GIL is held;
builder() makes its ViewSet (the core validates) without touching a Python object.
*/
struct StereoProblem
{
    tripose::ProblemArguments arguments;
    tripose::ArgumentMatrix R12, t12;

    StereoProblem(nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2,
                  nb::handle l3, nb::handle l4, nb::handle K, nb::handle R12in, nb::handle t12in, nb::handle dist)
    {
        arguments.views.push_back(readView(p1, l1, "points1", "lines1", false));
        arguments.views.push_back(readView(p2, l2, "points2", "lines2", false));
        arguments.views.push_back(readView(p3, l3, "points3", "lines3", true));
        arguments.views.push_back(readView(p4, l4, "points4", "lines4", true));
        readCalibration(K, dist, arguments);
        R12 = readRotation(R12in, "R12");
        t12 = readTranslation(t12in, "t12");
    }

    std::function<tripose::ViewSet()> builder(int minFeatures) const
    {
        return [this, minFeatures] { return tripose::buildStereoRigSet(arguments, R12, t12, minFeatures); };
    }
};

} // namespace

void bindStereo(nb::module_& m)
{
    m.def("estimate_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist, bool refine) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              return runCandidates<tripose::RigPoseSolver>(problem.builder(kMinStereoFeatures), refine);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_line_point_stereo_ransac",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist,
             const tripose::RansacOptions* given, const std::string& optionsName, bool wantCovariance) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::RansacOptions options = checkedRansacOptions(given, optionsName);
              return runRobust(problem.builder(kMinStereoRansacFeatures),
                               [options](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   return tripose::estimateRobustRig(views, options, estimate);
                               },
                               options, wantCovariance);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"), nb::arg("covariance"));

    m.def("refine_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle R, nb::handle t, nb::handle dist,
             const tripose::RefineOptions* given, const std::string& optionsName) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = checkedRefineOptions(given, optionsName);
              return runRefinement(problem.builder(kMinStereoFeatures), Rm, tm, options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));
}
