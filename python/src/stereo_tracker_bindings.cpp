// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The stereo tracker, bound as a class over the core's; python/tripose/tracking.py checks and
// converts the caller's arrays, as for the monocular tracker.

#include "stereo_tracker_bindings.hpp"
#include "tracking_conversions.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <nanobind/stl/tuple.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "tracking/stereo_tracker.hpp"

namespace nb = nanobind;
using namespace tracking_conversions;

namespace {

//! One image's features from tracking.py's arrays.
tripose::FrameFeatures frameFeatures(const nb::bytes& points, size_t numPoints, const nb::bytes& pointDescriptors,
                                     size_t pointWidth, bool pointBinary, const nb::bytes& segments,
                                     size_t numSegments, const nb::bytes& lineDescriptors, size_t lineWidth,
                                     bool lineBinary)
{
    tripose::FrameFeatures f;
    f.points = vectors<2>(points, numPoints);
    f.segments = vectors<4>(segments, numSegments);
    f.pointDescriptors = descriptors(pointDescriptors, numPoints, pointWidth, pointBinary);
    f.lineDescriptors = descriptors(lineDescriptors, numSegments, lineWidth, lineBinary);
    return f;
}

tripose::CameraPose pose(const nb::bytes& R, const nb::bytes& t)
{
    tripose::CameraPose p;
    p.R = matrix3(R);
    const Block tv(t, 3, 1, sizeof(double));
    for (int i = 0; i < 3; ++i)
        p.t[i] = tv.at<double>(i, 0);
    return p;
}

void checkFrame(const tripose::StereoTracker& self, int frame)
{
    if (frame < 0 || frame >= self.numFrames())
        throw nb::index_error(("frame " + std::to_string(frame) + " is not one of the " +
                               std::to_string(self.numFrames()) + " frames tracked").c_str());
}

} // namespace

void bindStereoTracker(nb::module_& m)
{
    nb::class_<tripose::StereoTracker>(m, "_StereoTracker")
        .def("__init__",
             [](tripose::StereoTracker* self, const nb::bytes& KLeft, const std::vector<double>& distLeft,
                const nb::bytes& KRight, const std::vector<double>& distRight, const nb::bytes& R, const nb::bytes& t,
                const tripose::TrackerOptions& options) {
                 new (self) tripose::StereoTracker(matrix3(KLeft), distLeft, matrix3(KRight), distRight, pose(R, t),
                                                   options);
             })
        .def("add_frame",
             [](tripose::StereoTracker& self, const nb::bytes& lp, size_t lnp, const nb::bytes& lpd, size_t lpw,
                bool lpb, const nb::bytes& ls, size_t lns, const nb::bytes& lld, size_t llw, bool llb,
                const nb::bytes& rp, size_t rnp, const nb::bytes& rpd, size_t rpw, bool rpb, const nb::bytes& rs,
                size_t rns, const nb::bytes& rld, size_t rlw, bool rlb, nb::handle R, nb::handle t) {
                 const tripose::FrameFeatures left = frameFeatures(lp, lnp, lpd, lpw, lpb, ls, lns, lld, llw, llb);
                 const tripose::FrameFeatures right = frameFeatures(rp, rnp, rpd, rpw, rpb, rs, rns, rld, rlw, rlb);
                 const bool hasPose = !R.is_none();
                 const tripose::CameraPose given =
                     hasPose ? pose(nb::cast<nb::bytes>(R), nb::cast<nb::bytes>(t)) : tripose::CameraPose();
                 nb::gil_scoped_release release;
                 return self.addFrame(left, right, hasPose ? &given : nullptr);
             },
             nb::arg("left_points"), nb::arg("left_num_points"), nb::arg("left_point_descriptors"),
             nb::arg("left_point_width"), nb::arg("left_point_binary"), nb::arg("left_segments"),
             nb::arg("left_num_segments"), nb::arg("left_line_descriptors"), nb::arg("left_line_width"),
             nb::arg("left_line_binary"), nb::arg("right_points"), nb::arg("right_num_points"),
             nb::arg("right_point_descriptors"), nb::arg("right_point_width"), nb::arg("right_point_binary"),
             nb::arg("right_segments"), nb::arg("right_num_segments"), nb::arg("right_line_descriptors"),
             nb::arg("right_line_width"), nb::arg("right_line_binary"), nb::arg("R").none(), nb::arg("t").none())
        .def("add_observations",
             [](tripose::StereoTracker& self, const nb::bytes& points, const std::vector<int64_t>& pointIds,
                const nb::bytes& rightPoints, const nb::bytes& segments, const std::vector<int64_t>& lineIds,
                const nb::bytes& rightSegments, nb::handle R, nb::handle t) {
                 tripose::StereoObservations o;
                 o.points = vectors<2>(points, pointIds.size());
                 o.pointIds = pointIds;
                 o.rightPoints = vectors<2>(rightPoints, pointIds.size());
                 o.segments = vectors<4>(segments, lineIds.size());
                 o.lineIds = lineIds;
                 o.rightSegments = vectors<4>(rightSegments, lineIds.size());
                 const bool hasPose = !R.is_none();
                 const tripose::CameraPose given =
                     hasPose ? pose(nb::cast<nb::bytes>(R), nb::cast<nb::bytes>(t)) : tripose::CameraPose();
                 nb::gil_scoped_release release;
                 return self.addObservations(o, hasPose ? &given : nullptr);
             },
             nb::arg("points"), nb::arg("point_ids"), nb::arg("right_points"), nb::arg("segments"),
             nb::arg("line_ids"), nb::arg("right_segments"), nb::arg("R").none(), nb::arg("t").none())
        .def_prop_ro("num_frames", &tripose::StereoTracker::numFrames)
        .def("pose", [](const tripose::StereoTracker& self, int frame) -> nb::object {
            checkFrame(self, frame);
            const tripose::StoredFrame& f = self.frame(frame);
            if (!f.hasPose())
                return nb::none();
            return nb::make_tuple(rotation(f.pose.R), array(f.pose.t.data(), { 3 }));
        })
        .def("map_of", [](const tripose::StereoTracker& self, int frame) -> int {
            checkFrame(self, frame);
            return self.frame(frame).hasPose() ? self.frame(frame).map : -1;
        }, nb::arg("frame"))
        .def("tracks", [](const tripose::StereoTracker& self, int frame) {
            checkFrame(self, frame);
            return nb::make_tuple(intArray(self.frame(frame).pointTrack), intArray(self.frame(frame).lineTrack));
        })
        .def("stereo_matches", [](const tripose::StereoTracker& self, int frame) {
            checkFrame(self, frame);
            return nb::make_tuple(intArray(self.stereoPoints(frame)), intArray(self.stereoSegments(frame)));
        })
        .def_prop_ro("options", &tripose::StereoTracker::options)
        .def_prop_ro("rig", [](const tripose::StereoTracker& self) {
            return nb::make_tuple(rotation(self.rig().R), array(self.rig().t.data(), { 3 }));
        });
}
