// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The option structs of the estimators and the trackers, bound as classes: their defaults are the
// core's structs', declared once; the core checks their values when a function is called with them.

#include "options_bindings.hpp"

#include <string>

#include <nanobind/stl/string.h>

#include "support/error.hpp"
#include "tracking/epipolar_matching.hpp"
#include "tracking/tracker_options.hpp"

namespace nb = nanobind;

tripose::RansacOptions checkedRansacOptions(const tripose::RansacOptions* given, const std::string& name)
{
    const tripose::RansacOptions options = given ? *given : tripose::RansacOptions();
    tripose::RansacOptionNames names;
    names.maxIterations = "max_iterations";
    names.minInliers = "min_inliers";
    names.refineOptions = "refine_options";
    names.refine.maxIterations = "max_iterations";
    names.refine.lossValues = "'squared', 'huber' or 'cauchy'";
    names.refine.lossScale = "loss_scale";
    tripose::checkRansacOptions(options, name.c_str(), names);
    return options;
}

tripose::RefineOptions checkedRefineOptions(const tripose::RefineOptions* given, const std::string& name)
{
    const tripose::RefineOptions options = given ? *given : tripose::RefineOptions();
    tripose::RefineOptionNames names;
    names.maxIterations = "max_iterations";
    names.lossValues = "'squared', 'huber' or 'cauchy'";
    names.lossScale = "loss_scale";
    tripose::checkRefineOptions(options, name.c_str(), names);
    return options;
}

void bindOptions(nb::module_& m)
{
    nb::class_<tripose::RefineOptions>(m, "RefineOptions",
                                       "Options of the maximum-likelihood refinement: Levenberg-Marquardt over the pose and the structure, "
                                       "minimising the reprojection error in pixels under a loss. Fields: max_iterations, "
                                       "loss, loss_scale, tolerance.")
        .def(nb::init<>())
        .def_rw("max_iterations", &tripose::RefineOptions::maxIterations, "Levenberg-Marquardt steps, accepted or rejected (> 0).")
        .def_prop_rw("loss",
                     [](const tripose::RefineOptions& o) {
                         return std::string(o.loss == tripose::Loss::Huber ? "huber"
                                            : o.loss == tripose::Loss::Cauchy ? "cauchy" : "squared");
                     },
                     [](tripose::RefineOptions& o, const std::string& loss) {
                         if (loss == "squared")
                             o.loss = tripose::Loss::Squared;
                         else if (loss == "huber")
                             o.loss = tripose::Loss::Huber;
                         else if (loss == "cauchy")
                             o.loss = tripose::Loss::Cauchy;
                         else
                             throw nb::value_error(("loss must be 'squared', 'huber' or 'cauchy', got '" + loss + "'").c_str());
                     },
                     "The loss of each reprojection error: 'squared', 'huber' or 'cauchy'.")
        .def_rw("loss_scale", &tripose::RefineOptions::lossScale, "Scale of the robust loss in pixels (> 0).")
        .def_rw("tolerance", &tripose::RefineOptions::tolerance,
                "Stop when an accepted step lowers the cost by less than this fraction (>= 0).")
        .def("__repr__", [](const tripose::RefineOptions& o) {
            return tripose::formatString("RefineOptions(max_iterations=%d, loss='%s', loss_scale=%g, tolerance=%g)",
                                         o.maxIterations,
                                         o.loss == tripose::Loss::Huber ? "huber" : o.loss == tripose::Loss::Cauchy ? "cauchy" : "squared",
                                         o.lossScale, o.tolerance);
        });

    nb::class_<tripose::RansacOptions>(m, "RansacOptions",
                                       "Options of the robust estimators (LO-MSAC over minimal samples, then the "
                                       "maximum-likelihood refinement over the inliers). Fields: threshold (px), "
                                       "confidence, max_iterations (samples), local_optimization, refine, "
                                       "refine_options (a RefineOptions), seed, min_inliers.")
        .def(nb::init<>())
        .def_rw("threshold", &tripose::RansacOptions::threshold, "Inlier threshold in pixels (> 0).")
        .def_rw("confidence", &tripose::RansacOptions::confidence,
                "Probability, in (0, 1), of drawing an all-inlier sample before stopping.")
        .def_rw("max_iterations", &tripose::RansacOptions::maxIterations, "Most samples drawn (> 0).")
        .def_rw("local_optimization", &tripose::RansacOptions::localOptimization,
                "Re-estimate from the inliers of every new best model.")
        .def_rw("refine", &tripose::RansacOptions::refine,
                "Finish with the maximum-likelihood refinement over the inliers.")
        .def_rw("refine_options", &tripose::RansacOptions::refineOptions, "Options of that refinement.")
        .def_rw("seed", &tripose::RansacOptions::seed, "Seed of the sampler: the same seed gives the same result.")
        .def_rw("min_inliers", &tripose::RansacOptions::minInliers,
                "Fewest inliers of a returned pose (>= 0); an estimate with fewer is no pose. Chance matches agree "
                "with a pose in numbers up to about a dozen: lower it only where every feature is known to be right.")
        .def("__repr__", [](const tripose::RansacOptions& o) {
            const tripose::RefineOptions& r = o.refineOptions;
            return tripose::formatString("RansacOptions(threshold=%g, confidence=%g, max_iterations=%d, "
                                         "local_optimization=%s, refine=%s, seed=%llu, min_inliers=%d, "
                                         "refine_options=RefineOptions(max_iterations=%d, loss='%s', loss_scale=%g, "
                                         "tolerance=%g))",
                                         o.threshold, o.confidence, o.maxIterations,
                                         o.localOptimization ? "True" : "False", o.refine ? "True" : "False",
                                         (unsigned long long)o.seed, o.minInliers, r.maxIterations,
                                         r.loss == tripose::Loss::Huber ? "huber" : r.loss == tripose::Loss::Cauchy ? "cauchy" : "squared",
                                         r.lossScale, r.tolerance);
        });

    nb::class_<tripose::MatchOptions>(m, "MatchOptions",
                                      "How the features of two frames are matched: candidates near the epipolar "
                                      "lines (or any, without a geometry), then mutual best descriptor with a ratio "
                                      "test. Fields: epipolar_distance (px), min_band_overlap, min_epipolar_angle_deg, "
                                      "point_ratio, line_ratio, max_line_distance, min_fundamental_inliers.")
        .def(nb::init<>())
        .def_rw("epipolar_distance", &tripose::MatchOptions::epipolarDistance,
                "Largest distance (px) of a point from the other's epipolar line; also the fundamental "
                "matrix's inlier distance.")
        .def_rw("min_band_overlap", &tripose::MatchOptions::minBandOverlap,
                "Fraction of a segment that must overlap the epipolar band of the other.")
        .def_rw("min_epipolar_angle_deg", &tripose::MatchOptions::minEpipolarAngleDeg,
                "Segments closer than this to the epipolar lines are not matched under the geometry.")
        .def_rw("point_ratio", &tripose::MatchOptions::pointRatio, "Ratio test of point descriptors.")
        .def_rw("line_ratio", &tripose::MatchOptions::lineRatio, "Ratio test of line descriptors.")
        .def_rw("max_line_distance", &tripose::MatchOptions::maxLineDistance,
                "Binary line descriptors further apart than this many bits never match.")
        .def_rw("min_fundamental_inliers", &tripose::MatchOptions::minFundamentalInliers,
                "Matches that must agree with the fundamental matrix for two frames to be matched under it.")
        .def("__repr__", [](const tripose::MatchOptions& o) {
            return tripose::formatString("MatchOptions(epipolar_distance=%g, point_ratio=%g, line_ratio=%g, "
                                         "min_fundamental_inliers=%d)",
                                         o.epipolarDistance, o.pointRatio, o.lineRatio, o.minFundamentalInliers);
        });

    nb::class_<tripose::TrackerOptions>(m, "TrackerOptions",
                                        "Options of tripose.Tracker: the window of keyframes a frame is registered "
                                        "against, the support a pose needs (min_inliers), keyframes by parallax, the "
                                        "track checks, the local adjustment, and the RansacOptions (ransac) and "
                                        "MatchOptions (matching) it uses. Defaults are the library's.")
        .def(nb::init<>())
        .def_rw("window", &tripose::TrackerOptions::window, "Keyframes a new frame is registered against (>= 2).")
        .def_rw("min_inliers", &tripose::TrackerOptions::minInliers,
                "A frame is registered only when at least this many features agree with its pose.")
        .def_rw("keyframe_parallax_deg", &tripose::TrackerOptions::keyframeParallaxDeg,
                "A registered frame is a keyframe when its structure's median parallax to the window's last "
                "keyframe is at least this (degrees; 0: every registered frame).")
        .def_rw("check_tracks", &tripose::TrackerOptions::checkTracks,
                "Drop the window's observations that disagree with its poses, and split the tracks a "
                "registration rejects.")
        .def_rw("local_adjustment", &tripose::TrackerOptions::localAdjustment,
                "Refine the window's registered frames and their structure after each registration.")
        .def_rw("robust", &tripose::TrackerOptions::robust,
                "Register with the robust estimator (else the linear one on every feature).")
        .def_rw("ransac", &tripose::TrackerOptions::ransac, "RansacOptions of the registration.")
        .def_rw("matching", &tripose::TrackerOptions::matching, "MatchOptions of consecutive frames.")
        .def_rw("covariance", &tripose::TrackerOptions::covariance,
                "Also the covariance of each registered frame's pose (FrameResult.covariance); it costs one "
                "more refinement per frame.")
        .def_rw("max_frame_gap", &tripose::TrackerOptions::maxFrameGap,
                "How many frames back a frame is matched when the nearer ones share too few matches with it.")
        .def("__repr__", [](const tripose::TrackerOptions& o) {
            return tripose::formatString("TrackerOptions(window=%d, min_inliers=%d, keyframe_parallax_deg=%g, "
                                         "check_tracks=%s, local_adjustment=%s, robust=%s, max_frame_gap=%d, ...)",
                                         o.window, o.minInliers, o.keyframeParallaxDeg,
                                         o.checkTracks ? "True" : "False", o.localAdjustment ? "True" : "False",
                                         o.robust ? "True" : "False", o.maxFrameGap);
        });
}
