// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "pose_result.hpp"

#include <cmath>
#include <deque>
#include <string>

#include <Eigen/Geometry>
#include <nanobind/stl/string.h>

#include "support/error.hpp"

namespace nb = nanobind;

namespace {

struct Field
{
    const char* name;
    nb::object PoseResult::*member;
    const char* doc;
    const char* type; //!< The type the stubs give it.
};

#define TRIPOSE_ARRAY "numpy.typing.NDArray[numpy.float64]"
#define TRIPOSE_MASK "numpy.typing.NDArray[numpy.bool_]"

// Every field once: its attribute, its dictionary key (the names of the dicts the functions
// returned before) and its docstring.
const Field kFields[] = {
    { "R", &PoseResult::R,
      "Rotation (3, 3) of the pose, x_cam = R @ X + t (estimate_pose_*: the best candidate's); None when no "
      "pose was found.",
      TRIPOSE_ARRAY " | None" },
    { "t", &PoseResult::t, "Translation (3,) of the pose; None when no pose was found.",
      TRIPOSE_ARRAY " | None" },
    { "num_inliers", &PoseResult::num_inliers,
      "Robust functions: points + lines that agree with the pose (0 when no pose was found).",
      "int | None" },
    { "point_inliers", &PoseResult::point_inliers, "Robust functions: bool (N,), the points that agree with the pose.",
      TRIPOSE_MASK " | None" },
    { "line_inliers", &PoseResult::line_inliers, "Robust functions: bool (M,), the lines that agree with the pose.",
      TRIPOSE_MASK " | None" },
    { "rms", &PoseResult::rms,
      "RMS reprojection error (px): over the inliers (robust functions; NaN without a pose), over every "
      "observation (refiners), the best candidate's (estimate_pose_*: candidate_rms[0]; None without one).",
      "float | None" },
    { "covariance", &PoseResult::covariance,
      "(6, 6) covariance of the pose for 1 px image noise, [rotation; translation] (help(tripose)); None "
      "when not asked for (robust functions: covariance=False), without refinement or not determined.",
      TRIPOSE_ARRAY " | None" },
    { "noise_variance", &PoseResult::noise_variance,
      "Estimate of the image noise variance (px^2) from the residuals; None with the covariance.",
      "float | None" },
    { "candidates", &PoseResult::candidates,
      "Robust functions: the minima of the final refinement that the data cannot tell apart, as (R, t), the "
      "returned pose first; empty without refinement or without a pose. estimate_pose_*: every candidate "
      "as (R, t), best first (R, t the first); empty when the geometry determines no pose.",
      "list[tuple[" TRIPOSE_ARRAY ", " TRIPOSE_ARRAY "]] | None" },
    { "candidate_rms", &PoseResult::candidate_rms,
      "The RMS reprojection error (px) of each candidate: robust functions over the inliers; estimate_pose_* "
      "in the estimated view(s), or with refine=True over every view.",
      "list[float] | None" },
    { "ambiguous", &PoseResult::ambiguous, "Robust functions: more than one candidate (the pose is a coin toss).",
      "bool | None" },
    { "points3d", &PoseResult::points3d, "Refiners: the refined points (N, 3) in the world (view 1's) frame.",
      TRIPOSE_ARRAY " | None" },
    { "lines3d", &PoseResult::lines3d, "Refiners: two refined points (M, 6) of each line.",
      TRIPOSE_ARRAY " | None" },
    { "Rs", &PoseResult::Rs, "adjust_poses_multiview: every view's rotation (the fixed ones as given).",
      "list[" TRIPOSE_ARRAY "] | None" },
    { "ts", &PoseResult::ts, "adjust_poses_multiview: every view's translation.",
      "list[" TRIPOSE_ARRAY "] | None" },
};

std::string vectorText(const Eigen::Vector3d& v)
{
    return tripose::formatString("[%.4g, %.4g, %.4g]", v[0], v[1], v[2]);
}

//! "12.3 deg about [0.1, 0.9, 0.1]": the rotation as an angle and an axis.
std::string rotationText(const Eigen::Matrix3d& R)
{
    const Eigen::AngleAxisd angleAxis(R);
    return tripose::formatString("%.4g deg about ", angleAxis.angle() * 180.0 / M_PI) + vectorText(angleAxis.axis());
}

std::string shapeText(const nb::object& value)
{
    if (value.is_none())
        return "None";
    const nb::object shape = value.attr("shape");
    return tripose::formatString("(%d, %d)", nb::cast<int>(shape[0]), nb::cast<int>(shape[1]));
}

std::string repr(const PoseResult& r)
{
    std::string text = "PoseResult(";
    if (r.kind == PoseResult::Kind::Adjusted)
        text += tripose::formatString("Rs, ts: %d poses", r.numPoses);
    else if (r.kind == PoseResult::Kind::Candidates && !r.hasPose)
        return text + "no pose, candidates=0)";
    else if (!r.hasPose)
        return text + tripose::formatString("no pose, num_inliers=0 of %d points and %d lines)", r.numPoints, r.numLines);
    else
        text += "rotation=" + rotationText(r.rotation) + ", t=" + vectorText(r.translation);
    if (r.kind == PoseResult::Kind::Robust)
        text += tripose::formatString(", num_inliers=%d (points %d/%d, lines %d/%d)", r.pointInliers + r.lineInliers,
                                      r.pointInliers, r.numPoints, r.lineInliers, r.numLines);
    text += tripose::formatString(", rms=%.4g px", r.rmsValue);
    if (r.kind != PoseResult::Kind::Adjusted)
        text += r.noise_variance.is_none()
                    ? std::string(", covariance=None")
                    : tripose::formatString(", noise_variance=%.4g px^2, covariance=(6, 6)",
                                            PyFloat_AsDouble(r.noise_variance.ptr()));
    if (r.kind == PoseResult::Kind::Robust)
        text += tripose::formatString(", candidates=%d, ambiguous=%s", r.numCandidates,
                                      r.numCandidates > 1 ? "True" : "False");
    else if (r.kind == PoseResult::Kind::Candidates)
        text += tripose::formatString(", candidates=%d", r.numCandidates);
    else
        text += ", points3d=" + shapeText(r.points3d) + ", lines3d=" + shapeText(r.lines3d);
    return text + ")";
}

/** The list of candidates that estimate_pose_* returned before, for the deprecated list-like use:
warns (DeprecationWarning) naming the field to read instead; TypeError for the other results, which
were never lists.
*/
const nb::object& deprecatedCandidates(const PoseResult& r, const char* use)
{
    if (r.kind != PoseResult::Kind::Candidates)
        throw nb::type_error(tripose::formatString("PoseResult: %s applies only to the result of estimate_pose_* "
                                                   "(read result.candidates)",
                                                   use)
                                 .c_str());
    const std::string message = tripose::formatString(
        "%s reads the candidates of estimate_pose_line_point, estimate_pose_line_point_stereo or "
        "estimate_pose_multiview as the list they returned before and is deprecated: they return a "
        "tripose.PoseResult; read result.candidates (every (R, t), best first) or result.R, result.t "
        "(None without a candidate) (README.md, 'Changes')",
        use);
    if (PyErr_WarnEx(PyExc_DeprecationWarning, message.c_str(), 1) != 0)
        throw nb::python_error();
    return r.candidates;
}

const Field* findField(const std::string& name)
{
    for (const Field& field : kFields)
        if (name == field.name)
            return &field;
    return nullptr;
}

} // namespace

void bindPoseResult(nb::module_& m)
{
    nb::class_<PoseResult> cls(m, "PoseResult",
                               "The result of the candidate estimators (estimate_pose_line_point, "
                               "estimate_pose_line_point_stereo, estimate_pose_multiview), the robust functions "
                               "(estimate_pose_*_ransac), the refiners (refine_pose_*) and adjust_poses_multiview: R, t, num_inliers, point_inliers, "
                               "line_inliers, rms, covariance, noise_variance, candidates, candidate_rms, ambiguous, "
                               "points3d, lines3d, Rs, ts; None where the function does not give one. "
                               "result['R'] reads a field as result.R does (the dictionaries of earlier releases); "
                               "len(result), iterating and result[0] read the candidates of estimate_pose_* as "
                               "the list of earlier releases (deprecated: read result.candidates).");
    for (const Field& field : kFields)
    {
        nb::object PoseResult::*member = field.member;
        // The signature's text lives as long as the module.
        static std::deque<std::string> signatures;
        signatures.push_back(std::string("def ") + field.name + "(self, /) -> " + field.type);
        cls.def_prop_ro(field.name, [member](const PoseResult& r) { return r.*member; },
                        nb::for_getter(nb::sig(signatures.back().c_str())), nb::for_getter(field.doc));
    }
    cls.def("__getitem__",
            [](const PoseResult& r, const std::string& key) {
                const Field* field = findField(key);
                if (!field)
                    throw nb::key_error(key.c_str());
                return r.*(field->member);
            })
        .def("__getitem__",
             [](const PoseResult& r, Py_ssize_t index) -> nb::object {
                 return deprecatedCandidates(r, "result[i]")[nb::int_(index)];
             },
             nb::arg("index"), "Deprecated: the candidate at index (result.candidates[index]).")
        .def("__getitem__",
             [](const PoseResult& r, nb::slice slice) -> nb::object {
                 return deprecatedCandidates(r, "result[i:j]")[slice];
             },
             nb::arg("index"), "Deprecated: the candidates of the slice (result.candidates[i:j]).")
        .def("__len__",
             [](const PoseResult& r) { return nb::len(deprecatedCandidates(r, "len(result)")); },
             "Deprecated: the number of candidates (len(result.candidates)).")
        .def("__iter__",
             [](const PoseResult& r) { return nb::iter(deprecatedCandidates(r, "iterating over the result")); },
             "Deprecated: the candidates as (R, t) (iter(result.candidates)).")
        .def("__bool__",
             [](const PoseResult& r) {
                 // Every other result was always true; the candidates' list was false when empty.
                 if (r.kind != PoseResult::Kind::Candidates)
                     return true;
                 return nb::len(deprecatedCandidates(r, "bool(result)")) > 0;
             },
             "True, except the result of estimate_pose_* without a candidate (deprecated: read result.R is not None).")
        .def("__contains__", [](const PoseResult&, const std::string& key) { return findField(key) != nullptr; })
        .def("get",
             [](const PoseResult& r, const std::string& key, nb::object fallback) {
                 const Field* field = findField(key);
                 return field ? r.*(field->member) : fallback;
             },
             nb::arg("key"), nb::arg("default") = nb::none())
        .def("keys",
             [](const PoseResult&) {
                 nb::list names;
                 for (const Field& field : kFields)
                     names.append(field.name);
                 return names;
             },
             "The names of every field, as a dictionary's keys.")
        .def("__repr__", &repr);
}
