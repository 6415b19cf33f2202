// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The tracker, its results and the triplet matching, bound over the core's (their options are bound
// in options_bindings.cpp); python/tripose/tracking.py checks and converts the caller's arrays.

#include "tracker_bindings.hpp"
#include "tracking_conversions.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <nanobind/ndarray.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "support/error.hpp"

#include "tracking/tracker.hpp"
#include "tracking/triplet_matching.hpp"

namespace nb = nanobind;

namespace {

using namespace tracking_conversions;

//! The optional pose (R 3x3, t 3) and camera matrix of a frame.
struct FrameExtras
{
    bool hasPose = false, hasK = false;
    tripose::CameraPose pose;
    Eigen::Matrix3d K;

    FrameExtras(const nb::handle R, const nb::handle t, const nb::handle K)
    {
        if (!R.is_none())
        {
            pose.R = matrix3(nb::cast<nb::bytes>(R));
            const Block tv(nb::cast<nb::bytes>(t), 3, 1, sizeof(double));
            for (int i = 0; i < 3; ++i)
                pose.t[i] = tv.at<double>(i, 0);
            hasPose = true;
        }
        if (!K.is_none())
        {
            this->K = matrix3(nb::cast<nb::bytes>(K));
            hasK = true;
        }
    }
    const tripose::CameraPose* posePtr() const { return hasPose ? &pose : nullptr; }
    const Eigen::Matrix3d* KPtr() const { return hasK ? &K : nullptr; }
};

const char* statusName(tripose::FrameStatus status)
{
    switch (status)
    {
    case tripose::FrameStatus::Given: return "GIVEN";
    case tripose::FrameStatus::Registered: return "REGISTERED";
    case tripose::FrameStatus::Restarted: return "RESTARTED";
    default: return "LOST";
    }
}

} // namespace

void bindTracker(nb::module_& m)
{
    nb::enum_<tripose::FrameStatus>(m, "FrameStatus",
                                      "What the tracker made of a frame: GIVEN (its pose came with it), REGISTERED "
                                      "(registered against the window of keyframes), LOST (no pose: too little "
                                      "support; FrameResult.reason says why) or RESTARTED (a stereo tracker lost "
                                      "for longer began a new map here; FrameResult.map).")
        .value("GIVEN", tripose::FrameStatus::Given, "The pose came with the frame.")
        .value("REGISTERED", tripose::FrameStatus::Registered, "Registered against the window of keyframes.")
        .value("LOST", tripose::FrameStatus::Lost, "No pose: too little support (see FrameResult.reason).")
        .value("RESTARTED", tripose::FrameStatus::Restarted,
               "A stereo tracker lost for more than max_frame_gap frames began a new map at this frame, placed at the "
               "last pose known until a place of an earlier map joins them (FrameResult.map).");

    nb::class_<tripose::FrameResult>(m, "FrameResult",
                                      "What the tracker made of one frame: status, the pose R, t (x_cam = R @ X + t; "
                                      "None when lost), features and inliers, keyframe, the time, why it was lost, "
                                      "and each feature's track.")
        .def_ro("frame", &tripose::FrameResult::frame, "The frame's index, in the order given.")
        .def_ro("status", &tripose::FrameResult::status, "FrameStatus.GIVEN, REGISTERED, LOST or RESTARTED.")
        .def_prop_ro("R", [](const tripose::FrameResult& r) -> nb::object {
            return r.status == tripose::FrameStatus::Lost ? nb::none() : rotation(r.pose.R);
        }, "The rotation (3, 3) of x_cam = R @ X + t; None when lost.")
        .def_prop_ro("t", [](const tripose::FrameResult& r) -> nb::object {
            return r.status == tripose::FrameStatus::Lost ? nb::none() : array(r.pose.t.data(), { 3 });
        }, "The translation (3,); None when lost.")
        .def_ro("features", &tripose::FrameResult::features,
                "Features the frame shares with at least two window keyframes.")
        .def_ro("inliers", &tripose::FrameResult::inliers, "Of them, those that agree with the pose.")
        .def_ro("known_views", &tripose::FrameResult::knownViews, "Window keyframes registered against.")
        .def_ro("keyframe", &tripose::FrameResult::keyframe, "Later frames are registered against it.")
        .def_ro("recognised_keyframe", &tripose::FrameResult::recognisedKeyframe,
                "The keyframe of a place seen before through which the frame was registered: a loop it "
                "closed, or where the lost camera was found again; -1 for neither.")
        .def_ro("map", &tripose::FrameResult::map,
                "The map the pose is in: 0 (the world of the given poses) unless a stereo tracker restarted and "
                "has not yet joined its new map to an earlier one; then the new map's poses move into the earlier "
                "map (StereoTracker.pose and map_of give them as they are now).")
        .def_ro("milliseconds", &tripose::FrameResult::milliseconds, "Time of matching and registration.")
        .def_ro("reason", &tripose::FrameResult::reason, "Why the frame is lost; empty otherwise.")
        .def_prop_ro("covariance", [](const tripose::FrameResult& r) -> nb::object {
            if (!r.hasCovariance)
                return nb::none();
            const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> rowMajor = r.covariance;
            return array(rowMajor.data(), { 6, 6 });
        }, "With TrackerOptions.covariance, for a registered frame whose pose is determined: the (6, 6) "
           "covariance of its pose for 1 px noise, [rotation; translation], the window's poses held; "
           "multiply by noise_variance. None otherwise.")
        .def_prop_ro("noise_variance", [](const tripose::FrameResult& r) -> nb::object {
            return r.hasCovariance ? nb::cast(r.noiseVariance) : nb::none();
        }, "The noise variance (px^2) estimated from the inliers' residuals, with covariance; None otherwise.")
        .def_prop_ro("point_tracks", [](const tripose::FrameResult& r) { return intArray(r.pointTracks); },
                     "Per point of the frame, its track (-1: none).")
        .def_prop_ro("line_tracks", [](const tripose::FrameResult& r) { return intArray(r.lineTracks); },
                     "Per segment of the frame, its track (-1: none).")
        .def("__repr__", [](const tripose::FrameResult& r) {
            std::string text = tripose::formatString("FrameResult(frame=%d, status=%s", r.frame, statusName(r.status));
            if (r.status == tripose::FrameStatus::Lost)
                return text + ", reason='" + r.reason + "')";
            const Eigen::Vector3d c = r.pose.centre();
            return text + tripose::formatString(", centre=[%.4g, %.4g, %.4g], inliers=%d/%d, keyframe=%s)", c[0], c[1],
                                                c[2], r.inliers, r.features, r.keyframe ? "True" : "False");
        });

    m.def("_match_triplets",
          [](const std::vector<nb::bytes>& points, const std::vector<size_t>& numPoints,
             const std::vector<nb::bytes>& pointDescriptors, const std::vector<size_t>& pointWidths,
             const std::vector<bool>& pointBinary, const std::vector<nb::bytes>& segments,
             const std::vector<size_t>& numSegments, const std::vector<nb::bytes>& lineDescriptors,
             const std::vector<size_t>& lineWidths, const std::vector<bool>& lineBinary, const std::vector<nb::bytes>& K,
             const nb::bytes& R12, const nb::bytes& t12, const tripose::MatchOptions& options) {
              tripose::FrameFeatures views[3];
              Eigen::Matrix3d cameras[3];
              for (int v = 0; v < 3; ++v)
              {
                  views[v].points = vectors<2>(points[v], numPoints[v]);
                  views[v].segments = vectors<4>(segments[v], numSegments[v]);
                  views[v].pointDescriptors = descriptors(pointDescriptors[v], numPoints[v], pointWidths[v], pointBinary[v]);
                  views[v].lineDescriptors = descriptors(lineDescriptors[v], numSegments[v], lineWidths[v], lineBinary[v]);
                  cameras[v] = matrix3(K[v]);
              }
              tripose::CameraPose pose12;
              pose12.R = matrix3(R12);
              const Block t(t12, 3, 1, sizeof(double));
              for (int i = 0; i < 3; ++i)
                  pose12.t[i] = t.at<double>(i, 0);
              tripose::FeatureTriplets triplets;
              {
                  nb::gil_scoped_release release;
                  tripose::checkMatchOptions(options, "options");
                  triplets = tripose::matchTriplets(views, cameras, pose12, options);
              }
              nb::dict out;
              for (int v = 0; v < 3; ++v)
              {
                  out[("point_rows" + std::to_string(v + 1)).c_str()] = intArray(triplets.pointRows[v]);
                  out[("segment_rows" + std::to_string(v + 1)).c_str()] = intArray(triplets.segmentRows[v]);
              }
              out["point_pairs"] = triplets.pointPairs;
              out["segment_pairs"] = triplets.segmentPairs;
              out["pair_agreement"] = nb::make_tuple(triplets.pairAgreement.matches, triplets.pairAgreement.agreeing);
              return out;
          });

    nb::class_<tripose::Tracker>(m, "_Tracker")
        .def("__init__",
             [](tripose::Tracker* self, const nb::bytes& K, const std::vector<double>& dist,
                const tripose::TrackerOptions& options) { new (self) tripose::Tracker(matrix3(K), dist, options); })
        .def("add_features",
             [](tripose::Tracker& self, const nb::bytes& points, size_t numPoints, const nb::bytes& pointDescriptors,
                size_t pointWidth, bool pointBinary, const nb::bytes& segments, size_t numSegments,
                const nb::bytes& lineDescriptors, size_t lineWidth, bool lineBinary, nb::handle R, nb::handle t,
                nb::handle K) {
                 tripose::FrameFeatures f;
                 f.points = vectors<2>(points, numPoints);
                 f.segments = vectors<4>(segments, numSegments);
                 f.pointDescriptors = descriptors(pointDescriptors, numPoints, pointWidth, pointBinary);
                 f.lineDescriptors = descriptors(lineDescriptors, numSegments, lineWidth, lineBinary);
                 const FrameExtras extras(R, t, K);
                 nb::gil_scoped_release release;
                 return self.addFeatures(f, extras.posePtr(), extras.KPtr());
             },
             nb::arg("points"), nb::arg("num_points"), nb::arg("point_descriptors"), nb::arg("point_width"),
             nb::arg("point_binary"), nb::arg("segments"), nb::arg("num_segments"), nb::arg("line_descriptors"),
             nb::arg("line_width"), nb::arg("line_binary"), nb::arg("R").none(), nb::arg("t").none(),
             nb::arg("K").none())
        .def("add_observations",
             [](tripose::Tracker& self, const nb::bytes& points, const std::vector<int64_t>& pi,
                const nb::bytes& segments, const std::vector<int64_t>& li, nb::handle R, nb::handle t, nb::handle K) {
                 const std::vector<Eigen::Vector2d> p = vectors<2>(points, pi.size());
                 const std::vector<Eigen::Vector4d> s = vectors<4>(segments, li.size());
                 const FrameExtras extras(R, t, K);
                 nb::gil_scoped_release release;
                 return self.addObservations(p, pi, s, li, extras.posePtr(), extras.KPtr());
             },
             nb::arg("points"), nb::arg("point_ids"), nb::arg("segments"), nb::arg("line_ids"), nb::arg("R").none(),
             nb::arg("t").none(), nb::arg("K").none())
        .def_prop_ro("num_frames", &tripose::Tracker::numFrames)
        .def("pose", [](const tripose::Tracker& self, int frame) -> nb::object {
            if (frame < 0 || frame >= self.numFrames())
                throw nb::index_error(("frame " + std::to_string(frame) + " is not one of the " +
                                       std::to_string(self.numFrames()) + " frames tracked").c_str());
            const tripose::StoredFrame& f = self.frame(frame);
            if (!f.hasPose())
                return nb::none();
            return nb::make_tuple(rotation(f.pose.R), array(f.pose.t.data(), { 3 }));
        })
        .def("tracks", [](const tripose::Tracker& self, int frame) {
            if (frame < 0 || frame >= self.numFrames())
                throw nb::index_error(("frame " + std::to_string(frame) + " is not one of the " +
                                       std::to_string(self.numFrames()) + " frames tracked").c_str());
            return nb::make_tuple(intArray(self.frame(frame).pointTrack), intArray(self.frame(frame).lineTrack));
        })
        .def("status", [](const tripose::Tracker& self, int frame) { return self.frame(frame).status; })
        .def("keyframe", [](const tripose::Tracker& self, int frame) { return self.frame(frame).keyframe; })
        .def_prop_ro("options", &tripose::Tracker::options)
        .def_prop_ro("given_pair_agreement", [](const tripose::Tracker& self) {
            return nb::make_tuple(self.givenPairAgreement().matches, self.givenPairAgreement().agreeing);
        });
}
