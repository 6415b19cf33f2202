// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The option structs of the estimators and the trackers, bound as classes whose constructors take
// any field as a keyword: their defaults are the core's structs', declared once; the core checks
// their values when a function is called with them.

#include "options_bindings.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nanobind/stl/string.h>

#include "support/error.hpp"
#include "tracking/epipolar_matching.hpp"
#include "tracking/tracker_options.hpp"

namespace nb = nanobind;

namespace {

//! The Python name of a loss, as RefineOptions.loss takes and gives it.
const char* lossName(tripose::Loss loss)
{
    return loss == tripose::Loss::Huber ? "huber" : loss == tripose::Loss::Cauchy ? "cauchy" : "squared";
}

//! RefineOptions' repr, also the refine_options part of RansacOptions'.
std::string refineRepr(const tripose::RefineOptions& o)
{
    return tripose::formatString("RefineOptions(max_iterations=%d, loss='%s', loss_scale=%g, tolerance=%g)",
                                 o.maxIterations, lossName(o.loss), o.lossScale, o.tolerance);
}

/** The fields of a bound option class (its writable properties, in the order bound), their types
and defaults, read once from the class and a default-constructed struct.
*/
class OptionFields
{
public:
    OptionFields(nb::handle cls, nb::handle defaults) : className_(nb::cast<std::string>(cls.attr("__name__")))
    {
        const nb::object property = nb::module_::import_("builtins").attr("property");
        const nb::object members = cls.attr("__dict__");
        for (nb::handle key : members)
        {
            const nb::object member = members[key];
            if (!nb::isinstance(member, property) || member.attr("fset").is_none())
                continue;
            const nb::object value = nb::getattr(defaults, key);
            // Numbers, flags and names show their default; an option struct within shows "...".
            const bool literal = nb::isinstance<nb::bool_>(value) || nb::isinstance<nb::int_>(value) ||
                                 nb::isinstance<nb::str>(value) ||
                                 (nb::isinstance<nb::float_>(value) && std::isfinite(nb::cast<double>(value)));
            names_.push_back(nb::cast<std::string>(key));
            types_.push_back(nb::cast<std::string>(value.type().attr("__qualname__")));
            defaults_.push_back(literal ? nb::cast<std::string>(nb::repr(value)) : std::string("..."));
        }
    }

    //! "def __init__(self, *, threshold: float = 2.0, ...) -> None".
    std::string signature() const
    {
        std::string text = "def __init__(self, *";
        for (size_t i = 0; i < names_.size(); ++i)
            text += ", " + names_[i] + ": " + types_[i] + " = " + defaults_[i];
        return text + ") -> None";
    }

    //! A TypeError naming the first of @p values that is no field.
    void checkNames(const nb::kwargs& values) const
    {
        for (const auto& item : values)
        {
            const std::string key = nb::cast<std::string>(item.first);
            if (find(key) == names_.size())
            {
                std::string list;
                for (const std::string& name : names_)
                    list += (list.empty() ? "" : ", ") + name;
                throw nb::type_error((className_ + "() got an unexpected keyword argument '" + key +
                                      "'; its fields are " + list).c_str());
            }
        }
    }

    /** Each of @p values set on @p self as setting the field does: the setter's exception, its
    message naming the keyword, the setter's own as its cause. */
    void set(nb::handle self, const nb::kwargs& values) const
    {
        for (const auto& item : values)
        {
            try
            {
                nb::setattr(self, item.first, item.second);
            }
            catch (nb::python_error& e)
            {
                const std::string key = nb::cast<std::string>(item.first);
                if (e.matches(PyExc_TypeError))
                {
                    std::string value = nb::cast<std::string>(nb::repr(item.second));
                    if (value.size() > 40)
                        value = value.substr(0, 37) + "...";
                    nb::raise_from(e, PyExc_TypeError, "%s(): %s=%s is not a valid %s", className_.c_str(), key.c_str(),
                                   value.c_str(), types_[find(key)].c_str());
                }
                const nb::object type = nb::borrow(e.type());
                const std::string message = nb::cast<std::string>(nb::str(e.value()));
                nb::raise_from(e, type, "%s() argument %s: %s", className_.c_str(), key.c_str(), message.c_str());
            }
        }
    }

private:
    size_t find(const std::string& name) const
    {
        return std::find(names_.begin(), names_.end(), name) - names_.begin();
    }

    std::string className_;
    std::vector<std::string> names_, types_, defaults_;
};

/** The class of the option struct T, its constructor to come from defKeywordConstructor() once its
fields are bound. The placeholder keeps __init__ first among the class's attributes, where the stubs
list it.
*/
template <class T>
nb::class_<T> optionsClass(nb::module_& m, const char* name, const char* doc)
{
    nb::class_<T> cls(m, name, doc);
    nb::setattr(cls, "__init__", nb::none());
    return cls;
}

/** The constructor T(field=value, ...) of the option class @p cls, whose fields are all bound: the
struct's defaults, then each keyword set as setting its field does. A keyword that is no field is a
TypeError naming it.
*/
template <class T>
void defKeywordConstructor(nb::class_<T>& cls)
{
    const OptionFields fields(cls, nb::cast(T()));
    cls.def("__init__",
            [fields](nb::pointer_and_handle<T> self, const nb::kwargs& values) {
                fields.checkNames(values);
                new (self.p) T();
                nb::inst_mark_ready(self.h); // the fields' setters take only a constructed instance
                fields.set(self.h, values);
            },
            nb::sig(fields.signature().c_str()), "The defaults, with any field given as a keyword set to its value.");
}

} // namespace

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
    auto refine = optionsClass<tripose::RefineOptions>(
        m, "RefineOptions",
        "Options of the maximum-likelihood refinement: Levenberg-Marquardt over the pose and the "
        "structure, minimising the reprojection error in pixels under a loss. Fields: max_iterations, "
        "loss, loss_scale, tolerance.");
    refine
        .def_rw("max_iterations", &tripose::RefineOptions::maxIterations, "Levenberg-Marquardt steps, accepted or rejected (> 0).")
        .def_prop_rw("loss",
                     [](const tripose::RefineOptions& o) {
                         return std::string(lossName(o.loss));
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
        .def("__repr__", &refineRepr);
    defKeywordConstructor(refine);

    auto ransac = optionsClass<tripose::RansacOptions>(
        m, "RansacOptions",
        "Options of the robust estimators (LO-MSAC over minimal samples, then the maximum-likelihood "
        "refinement over the inliers). Fields: threshold (px), confidence, max_iterations (samples), "
        "local_optimization, refine, refine_options (a RefineOptions), seed, min_inliers.");
    ransac
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
            return tripose::formatString("RansacOptions(threshold=%g, confidence=%g, max_iterations=%d, "
                                         "local_optimization=%s, refine=%s, seed=%llu, min_inliers=%d, "
                                         "refine_options=%s)",
                                         o.threshold, o.confidence, o.maxIterations,
                                         o.localOptimization ? "True" : "False", o.refine ? "True" : "False",
                                         (unsigned long long)o.seed, o.minInliers, refineRepr(o.refineOptions).c_str());
        });
    defKeywordConstructor(ransac);

    auto matching = optionsClass<tripose::MatchOptions>(
        m, "MatchOptions",
        "How the features of two frames are matched: candidates near the epipolar lines (or any, without "
        "a geometry), then mutual best descriptor with a ratio test. Fields: epipolar_distance (px), "
        "min_band_overlap, min_epipolar_angle_deg, point_ratio, line_ratio, max_line_distance, "
        "min_fundamental_inliers.");
    matching
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
    defKeywordConstructor(matching);

    auto tracker = optionsClass<tripose::TrackerOptions>(
        m, "TrackerOptions",
        "Options of tripose.Tracker: the window of keyframes a frame is registered against, the support a "
        "pose needs (min_inliers), keyframes by parallax, the track checks, the local adjustment, and the "
        "RansacOptions (ransac) and MatchOptions (matching) it uses. Defaults are the library's.");
    tracker
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
                "Refine the window's registered frames and their structure after each registration, splitting "
                "off the features matched by the tracker that disagree with the result.")
        .def_rw("loop_closure", &tripose::TrackerOptions::loopClosure,
                "After each new keyframe, look for a place seen before among the keyframes older than the "
                "window (by descriptors); registered against it, join the tracks and, once per loop for a place "
                "more than two windows of keyframes before the frame, correct the frames since by a pose graph "
                "and adjust every frame (frames given as features only).")
        .def_rw("global_adjustment_interval", &tripose::TrackerOptions::globalAdjustmentInterval,
                "Every this many new keyframes, adjust every registered frame and the structure together, "
                "the given frames held, and split off the observations that disagree, except those linked by id "
                "in track_observations() (0: only at a loop).")
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
                                         "check_tracks=%s, local_adjustment=%s, loop_closure=%s, "
                                         "global_adjustment_interval=%d, robust=%s, max_frame_gap=%d, ...)",
                                         o.window, o.minInliers, o.keyframeParallaxDeg,
                                         o.checkTracks ? "True" : "False", o.localAdjustment ? "True" : "False",
                                         o.loopClosure ? "True" : "False", o.globalAdjustmentInterval, o.robust ? "True" : "False", o.maxFrameGap);
        });
    defKeywordConstructor(tracker);
}
