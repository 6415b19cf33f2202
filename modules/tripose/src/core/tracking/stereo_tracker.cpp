// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "stereo_tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "../linear/rig_pose_solver.hpp"
#include "../pipeline/pose_pipelines.hpp"
#include "../pipeline/posed_structure.hpp"
#include "../problem/view_set_builder.hpp"
#include "../support/error.hpp"
#include "epipolar_matching.hpp"
#include "frame_arguments.hpp"
#include "frame_matching.hpp"
#include "place_registration.hpp"

namespace tripose {

namespace {

// The rig's linear solver needs three features.
const int kMinFeatures = 3;

// A frame whose stereo matches the keyframe's pair sees less than this fraction of is a keyframe.
const double kMinOverlap = 0.5;

// A place is worth its geometric check when this many of the retrieval sample's descriptors match;
// the best few are checked.
const int kMinPlaceMatches = 20;
const int kPlacesChecked = 3;

const FeatureKind kKinds[2] = { FeatureKind::Point, FeatureKind::Line };

ArgumentMatrix rotationArgument(const std::string& name, const Eigen::Matrix3d& R)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMajor = R;
    return matrixArgument(name, 3, 3, rowMajor.data());
}

//! Checks one image's features: a descriptor row per feature, finite values.
void checkFeatures(const FrameFeatures& f, const std::string& name, int frame)
{
    const int n = (int)f.points.size(), m = (int)f.segments.size();
    if (f.pointDescriptors.rows != n)
        fail(ErrorCode::BadSize, "%s.point_descriptors must have one row per point: %d rows for %d points",
             name.c_str(), f.pointDescriptors.rows, n);
    if (f.lineDescriptors.rows != m)
        fail(ErrorCode::BadSize, "%s.line_descriptors must have one row per segment: %d rows for %d segments",
             name.c_str(), f.lineDescriptors.rows, m);
    for (const Descriptors* d : { &f.pointDescriptors, &f.lineDescriptors })
        if (!d->binary)
            for (float v : d->real)
                if (!std::isfinite(v))
                    fail(ErrorCode::BadArgument, "%s.%s holds a value that is not finite", name.c_str(),
                         d == &f.pointDescriptors ? "point_descriptors" : "line_descriptors");
    for (size_t i = 0; i < f.points.size(); ++i)
        if (!f.points[i].allFinite())
            fail(ErrorCode::BadArgument, "%s.points[%d] of frame %d is not finite", name.c_str(), (int)i, frame);
    for (size_t i = 0; i < f.segments.size(); ++i)
        if (!f.segments[i].allFinite())
            fail(ErrorCode::BadArgument, "%s.segments[%d] of frame %d is not finite", name.c_str(), (int)i, frame);
}

//! Descriptors of one kind must agree in kind and length wherever both are given.
void checkSameKind(const Descriptors& a, const Descriptors& b, const std::string& name, const char* with)
{
    if (!a.empty() && !b.empty() && (a.binary != b.binary || a.cols != b.cols))
        fail(ErrorCode::BadArgument, "%s: descriptors must be of one kind and length in every image (%s of %d in %s, "
             "got %s of %d)", name.c_str(), a.binary ? "bytes" : "values", a.cols, with, b.binary ? "bytes" : "values",
             b.cols);
}

//! The pixels of @p f undistorted in place (segments by their end points).
void undistort(const Distortion& distortion, const Eigen::Matrix3d& K, FrameFeatures& f)
{
    distortion.undistortPixels(f.points, K);
    std::vector<Eigen::Vector2d> ends;
    for (const Eigen::Vector4d& s : f.segments)
    {
        ends.emplace_back(s[0], s[1]);
        ends.emplace_back(s[2], s[3]);
    }
    distortion.undistortPixels(ends, K);
    for (size_t i = 0; i < f.segments.size(); ++i)
        f.segments[i] << ends[2 * i], ends[2 * i + 1];
}

//! The median of @p values (+inf when empty).
double median(std::vector<double> values)
{
    if (values.empty())
        return std::numeric_limits<double>::infinity();
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

} // namespace

//! One registration of a frame against a keyframe.
struct StereoTracker::Attempt
{
    bool registered = false;
    CameraPose relative; //!< Of the frame's left camera in the frame of the keyframe's.
    PoseCovariance covariance; //!< Of relative, with TrackerOptions::covariance.
    int features = 0, inliers = 0;
    double parallaxDeg = 0;
    //! Of the frame's stereo matches, the fraction that the keyframe's stereo pair also sees.
    double overlap = 1;
    std::string reason;
    std::vector<int> rejected[2]; //!< Tracks (points, lines) whose observation in the frame the estimate rejected.
};

StereoTracker::StereoTracker(const Eigen::Matrix3d& KLeft, const std::vector<double>& distortionLeft,
                             const Eigen::Matrix3d& KRight, const std::vector<double>& distortionRight,
                             const CameraPose& rig, const TrackerOptions& options)
    : options_(options), retrieval_(options.matching)
{
    checkCameraMatrix(KLeft, "K_left");
    checkCameraMatrix(KRight, "K_right");
    K_[0] = KLeft;
    K_[1] = KRight;
    distorted_[0] = readDistortion(distortionLeft, "dist_left", distortion_[0]);
    distorted_[1] = readDistortion(distortionRight, "dist_right", distortion_[1]);
    rig_ = checkedPose(rig, "R", "t");
    if (!(rig_.t.norm() > 0))
        fail(ErrorCode::BadArgument, "t (the rig: the right camera's position relative to the left) must be non-zero: "
             "the baseline fixes the metric scale");
    checkTrackerOptions(options);
    F_ = fundamentalFromPose(K_[0], K_[1], rig_);
}

void StereoTracker::link(FeatureKind kind, int from, int to, const std::vector<std::pair<int, int>>& matches)
{
    for (const auto& m : matches)
    {
        const StoredFrame& source = store_.frames[from];
        int track = (kind == FeatureKind::Point ? source.pointTrack : source.lineTrack)[m.first];
        if (track < 0)
        {
            track = store_.newTrack(kind);
            store_.observe(kind, track, from, m.first);
        }
        store_.observe(kind, track, to, m.second);
    }
}

void StereoTracker::linkToRecent(int frame, const FrameFeatures& left)
{
    if (recent_.empty())
        return;
    Matches points, segments;
    int from = recent_.back().first;
    bool underGeometry = matchUnknownPose(recent_.back().second, left, options_.matching, points, segments);
    // As Tracker: past a frame that shares too few matches for their geometry, the nearest earlier
    // one that does.
    for (auto it = recent_.rbegin() + 1; !underGeometry && it != recent_.rend(); ++it)
    {
        Matches earlierPoints, earlierSegments;
        if (matchUnderFundamental(it->second, left, options_.matching, earlierPoints, earlierSegments))
        {
            points.swap(earlierPoints);
            segments.swap(earlierSegments);
            from = it->first;
            underGeometry = true;
        }
    }
    // Past more lost frames than that, the keyframes older than the recent frames.
    const int oldestRecent = recent_.front().first;
    for (auto it = keyframeFeatures_.rbegin(); !underGeometry && it != keyframeFeatures_.rend(); ++it)
    {
        Matches earlierPoints, earlierSegments;
        if (it->first < oldestRecent &&
            matchUnderFundamental(it->second, left, options_.matching, earlierPoints, earlierSegments))
        {
            points.swap(earlierPoints);
            segments.swap(earlierSegments);
            from = it->first;
            underGeometry = true;
        }
    }
    link(FeatureKind::Point, from, frame, points);
    link(FeatureKind::Line, from, frame, segments);
}

StoredFrame StereoTracker::newFrame(const CameraPose* pose) const
{
    StoredFrame frame;
    frame.K = K_[0];
    if (pose)
    {
        frame.pose = checkedPose(*pose, "R", "t");
        frame.status = FrameStatus::Given;
        frame.keyframe = true;
    }
    else if (numFrames() == 0)
    {
        // The first frame's left camera is the world's origin.
        frame.status = FrameStatus::Given;
        frame.keyframe = true;
    }
    return frame;
}

FrameResult StereoTracker::addFrame(const FrameFeatures& left, const FrameFeatures& right, const CameraPose* pose)
{
    const double start = nowSeconds();
    const int index = numFrames();
    if (byIds_)
        fail(ErrorCode::BadArgument, "left: this tracker was given observations; a tracker takes either features or "
             "observations");
    checkFeatures(left, "left", index);
    checkFeatures(right, "right", index);
    checkSameKind(left.pointDescriptors, right.pointDescriptors, "right.point_descriptors", "the left image");
    checkSameKind(left.lineDescriptors, right.lineDescriptors, "right.line_descriptors", "the left image");
    for (const auto& r : recent_)
        for (const FrameFeatures* f : { &left, &right })
        {
            const std::string name = f == &left ? "left" : "right";
            checkSameKind(r.second.pointDescriptors, f->pointDescriptors, name + ".point_descriptors",
                          "an earlier frame");
            checkSameKind(r.second.lineDescriptors, f->lineDescriptors, name + ".line_descriptors",
                          "an earlier frame");
        }
    StoredFrame frame = newFrame(pose);
    byFeatures_ = true;

    FrameFeatures undistorted[2] = { left, right };
    for (int c = 0; c < 2; ++c)
        if (distorted_[c])
            undistort(distortion_[c], K_[c], undistorted[c]);
    StereoFrame stereo;
    stereo.points = undistorted[1].points;
    stereo.segments = undistorted[1].segments;
    stereo.pointRight.assign(left.points.size(), -1);
    stereo.lineRight.assign(left.segments.size(), -1);
    for (const auto& m : matchPointsEpipolar(undistorted[0], undistorted[1], F_, options_.matching))
        stereo.pointRight[m.first] = m.second;
    for (const auto& m : matchSegmentsEpipolar(undistorted[0], undistorted[1], F_, options_.matching))
        stereo.lineRight[m.first] = m.second;

    frame.points = undistorted[0].points;
    frame.segments = undistorted[0].segments;
    frame.pointTrack.assign(left.points.size(), -1);
    frame.lineTrack.assign(left.segments.size(), -1);
    store_.frames.push_back(frame);
    stereo_.push_back(std::move(stereo));

    linkToRecent(index, undistorted[0]);
    recent_.emplace_back(index, std::move(undistorted[0]));
    while ((int)recent_.size() > options_.maxFrameGap)
        recent_.pop_front();
    FrameResult result = finishFrame(index, recent_.back().second, start);
    if (result.keyframe)
    {
        keyframeFeatures_.emplace_back(index, recent_.back().second);
        while ((int)keyframeFeatures_.size() > options_.window)
            keyframeFeatures_.pop_front();
        placeFeatures_[index] = recent_.back().second;
        retrieval_.add(index, recent_.back().second);
    }
    return result;
}

FrameResult StereoTracker::addObservations(const StereoObservations& observations, const CameraPose* pose)
{
    const double start = nowSeconds();
    const int index = numFrames();
    if (byFeatures_)
        fail(ErrorCode::BadArgument, "point_ids: this tracker was given features; a tracker takes either features or "
             "observations");
    const StereoObservations& o = observations;
    checkObservationIds(o.points.size(), o.pointIds, o.segments.size(), o.lineIds);
    if (o.rightPoints.size() != o.points.size())
        fail(ErrorCode::BadSize, "right_points must hold one row per point (NaN: not seen): %d rows for %d points",
             (int)o.rightPoints.size(), (int)o.points.size());
    if (o.rightSegments.size() != o.segments.size())
        fail(ErrorCode::BadSize, "right_segments must hold one row per segment (NaN: not seen): %d rows for %d "
             "segments", (int)o.rightSegments.size(), (int)o.segments.size());
    for (size_t i = 0; i < o.points.size(); ++i)
        if (!o.points[i].allFinite())
            fail(ErrorCode::BadArgument, "points[%d] of frame %d is not finite", (int)i, index);
    for (size_t i = 0; i < o.segments.size(); ++i)
        if (!o.segments[i].allFinite())
            fail(ErrorCode::BadArgument, "segments[%d] of frame %d is not finite", (int)i, index);
    StoredFrame frame = newFrame(pose);
    byIds_ = true;

    FrameFeatures left, right;
    left.points = o.points;
    left.segments = o.segments;
    StereoFrame stereo;
    stereo.pointRight.assign(o.points.size(), -1);
    stereo.lineRight.assign(o.segments.size(), -1);
    for (size_t i = 0; i < o.points.size(); ++i)
        if (o.rightPoints[i].allFinite())
        {
            stereo.pointRight[i] = (int)right.points.size();
            right.points.push_back(o.rightPoints[i]);
        }
    for (size_t i = 0; i < o.segments.size(); ++i)
        if (o.rightSegments[i].allFinite())
        {
            stereo.lineRight[i] = (int)right.segments.size();
            right.segments.push_back(o.rightSegments[i]);
        }
    if (distorted_[0])
        undistort(distortion_[0], K_[0], left);
    if (distorted_[1])
        undistort(distortion_[1], K_[1], right);
    stereo.points = right.points;
    stereo.segments = right.segments;
    frame.points = left.points;
    frame.segments = left.segments;
    frame.pointTrack.assign(o.points.size(), -1);
    frame.lineTrack.assign(o.segments.size(), -1);
    store_.frames.push_back(frame);
    stereo_.push_back(std::move(stereo));
    for (int kind = 0; kind < 2; ++kind)
    {
        const FeatureKind k = kKinds[kind];
        const std::vector<int64_t>& ids = kind == 0 ? o.pointIds : o.lineIds;
        std::map<int64_t, int>& idTrack = kind == 0 ? pointIdTrack_ : lineIdTrack_;
        for (size_t i = 0; i < ids.size(); ++i)
        {
            auto it = idTrack.find(ids[i]);
            const int track = it != idTrack.end() ? it->second : (idTrack[ids[i]] = store_.newTrack(k));
            store_.observe(k, track, index, (int)i);
        }
    }
    // Without descriptors no place is recognised: the frame is registered against the window only.
    return finishFrame(index, FrameFeatures(), start);
}

StereoTracker::Attempt StereoTracker::registerAgainst(int keyframe, int frame) const
{
    Attempt out;
    const StoredFrame& b = store_.frames[frame];
    const StereoFrame& stereoA = stereo_[keyframe];
    const StereoFrame& stereoB = stereo_[frame];
    const StoredFrame& a = store_.frames[keyframe];

    // Per kind, the features both cameras of A see and B's left camera sees: (track, row in left A,
    // row in right A, row in left B, row in right B or -1).
    struct Shared
    {
        int track, leftA, rightA, leftB, rightB;
    };
    std::vector<Shared> shared[2];
    for (int kind = 0; kind < 2; ++kind)
    {
        const std::vector<int>& tracks = kind == 0 ? b.pointTrack : b.lineTrack;
        const std::vector<int>& rightOfA = kind == 0 ? stereoA.pointRight : stereoA.lineRight;
        const std::vector<int>& rightOfB = kind == 0 ? stereoB.pointRight : stereoB.lineRight;
        for (int row = 0; row < (int)tracks.size(); ++row)
        {
            if (tracks[row] < 0)
                continue;
            const int rowA = store_.rowIn(kKinds[kind], tracks[row], keyframe);
            if (rowA < 0 || rightOfA[rowA] < 0)
                continue;
            shared[kind].push_back({ tracks[row], rowA, rightOfA[rowA], row, rightOfB[row] });
        }
    }
    out.features = (int)(shared[0].size() + shared[1].size());
    int stereoMatches = 0, sharedStereo = 0;
    for (int kind = 0; kind < 2; ++kind)
    {
        for (int right : kind == 0 ? stereoB.pointRight : stereoB.lineRight)
            stereoMatches += right >= 0 ? 1 : 0;
        for (const Shared& s : shared[kind])
            sharedStereo += s.rightB >= 0 ? 1 : 0;
    }
    out.overlap = stereoMatches > 0 ? double(sharedStereo) / stereoMatches : 0.0;
    const int needed = std::max(kMinFeatures, options_.minInliers);
    if (out.features < needed)
    {
        out.reason = formatString("shares %d features with the stereo pair of keyframe %d; at least %d are needed",
                                  out.features, keyframe, needed);
        return out;
    }

    // Views {left A, right A, left B, right B}, their rows one per shared feature.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ProblemArguments arguments;
    for (int v = 0; v < 4; ++v)
    {
        ViewArguments view;
        view.mayMiss = v >= 2;
        for (int kind = 0; kind < 2; ++kind)
        {
            const int width = kind == 0 ? 2 : 4;
            ArgumentMatrix& m = kind == 0 ? view.points : view.lines;
            m.name = formatString("%s%d", kind == 0 ? "points" : "lines", v + 1);
            if (shared[kind].empty())
                continue;
            m.rows = (int)shared[kind].size();
            m.cols = width;
            for (const Shared& s : shared[kind])
            {
                const int row = v == 0 ? s.leftA : v == 1 ? s.rightA : v == 2 ? s.leftB : s.rightB;
                const bool right = v % 2 == 1;
                for (int c = 0; c < width; ++c)
                {
                    double value = nan;
                    if (row >= 0)
                    {
                        if (kind == 0)
                            value = right ? (v == 1 ? stereoA : stereoB).points[row][c]
                                          : (v == 0 ? a : b).points[row][c];
                        else
                            value = right ? (v == 1 ? stereoA : stereoB).segments[row][c]
                                          : (v == 0 ? a : b).segments[row][c];
                    }
                    m.values.push_back(value);
                }
            }
        }
        arguments.views.push_back(view);
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> K = K_[v % 2];
        arguments.cameraMatrices.push_back(matrixArgument("K", 3, 3, K.data()));
    }
    const ArgumentMatrix R12 = rotationArgument("R", rig_.R), t12 = matrixArgument("t", 3, 1, rig_.t.data());
    const ViewSet set = buildStereoRigSet(arguments, R12, t12, kMinFeatures);

    std::vector<unsigned char> inliers[2];
    if (options_.robust)
    {
        // The tracker's floor is the one that decides: the estimate's own is set to it.
        RansacOptions ransac = options_.ransac;
        ransac.minInliers = options_.minInliers;
        RobustEstimate estimate;
        if (estimateRobustRig(set, ransac, estimate))
        {
            out.relative = estimate.pose;
            out.inliers = estimate.numInliers;
            inliers[0] = estimate.pointInliers;
            inliers[1] = estimate.lineInliers;
        }
    }
    else
    {
        const RigPoseSolver solver(set);
        const std::vector<ScoredPose> candidates = estimateCandidates(set, solver, false);
        if (!candidates.empty())
        {
            out.relative = candidates.front().pose;
            out.inliers = out.features;
        }
    }
    if (out.inliers < options_.minInliers || !out.relative.allFinite())
    {
        out.reason = formatString("%d of the %d features it shares with keyframe %d agree with the best pose; at "
                                  "least %d must", out.inliers, out.features, keyframe, options_.minInliers);
        out.inliers = 0;
        return out;
    }
    out.registered = true;
    if (options_.covariance)
        out.covariance = covarianceOfEstimate(set, out.relative, options_.ransac.refineOptions,
                                              options_.robust ? &inliers[0] : nullptr,
                                              options_.robust ? &inliers[1] : nullptr);
    if (options_.checkTracks && options_.robust)
        for (int kind = 0; kind < 2; ++kind)
            for (size_t i = 0; i < inliers[kind].size(); ++i)
                if (!inliers[kind][i])
                    out.rejected[kind].push_back(shared[kind][i].track);

    // The parallax of the inlier structure, triangulated from A's stereo pair, between the left
    // cameras of A (the origin here) and B.
    ProblemArguments pair = arguments;
    pair.views.resize(2);
    pair.cameraMatrices.resize(2);
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    const std::vector<ArgumentMatrix> Rs = { rotationArgument("Rs[0]", Eigen::Matrix3d::Identity()),
                                             rotationArgument("Rs[1]", rig_.R) };
    const std::vector<ArgumentMatrix> ts = { matrixArgument("ts[0]", 3, 1, zero.data()),
                                             matrixArgument("ts[1]", 3, 1, rig_.t.data()) };
    const PosedStructure structure = triangulateStructure(buildPosedViewSet(pair, Rs, ts));
    const Eigen::Vector3d centre = out.relative.centre();
    std::vector<double> angles;
    const auto add = [&](const std::vector<Eigen::Vector3d>& X, int perFeature, const std::vector<unsigned char>& in) {
        for (size_t k = 0; k < X.size(); ++k)
        {
            if (!in.empty() && !in[k / perFeature])
                continue;
            const Eigen::Vector3d rayA = X[k], rayB = X[k] - centre;
            const double angle = std::atan2(rayA.cross(rayB).norm(), rayA.dot(rayB));
            if (std::isfinite(angle))
                angles.push_back(angle * 180.0 / M_PI);
        }
    };
    add(structure.points, 1, inliers[0]);
    add(structure.lineEnds, 2, inliers[1]);
    out.parallaxDeg = median(angles);
    return out;
}

StereoTracker::Attempt StereoTracker::registerAtPlace(int frame, const FrameFeatures& left,
                                                      const std::function<bool(int)>& eligible, int& keyframe)
{
    Attempt out;
    out.reason = "no keyframe looks like it";
    for (const auto& candidate : retrieval_.rank(
             left, [&](int k) { return eligible(k) && store_.frames[k].hasPose(); }, kMinPlaceMatches,
             kPlacesChecked))
    {
        const int k = candidate.first;
        Matches points, segments;
        if (!matchUnderFundamental(placeFeatures_.at(k), left, options_.matching, points, segments))
        {
            out.reason = formatString("too few matches with keyframe %d for their epipolar geometry", k);
            continue;
        }
        TrackStore before = store_;
        joinToKeyframeTracks(store_, k, frame, points, segments);
        Attempt attempt;
        runCatchingInputErrors([&] { attempt = registerAgainst(k, frame); }, &attempt.reason);
        // Matches to a place are checked by no earlier frame: a pose few of them support, or most of
        // them contradict, is a coincidence of repeated texture, not the place.
        if (attempt.registered && (attempt.inliers < 2 * options_.minInliers || 2 * attempt.inliers < attempt.features))
        {
            attempt.registered = false;
            attempt.reason = formatString("%d of the %d features shared with the place of keyframe %d agree with its "
                                          "pose; at least %d and half must", attempt.inliers, attempt.features, k,
                                          2 * options_.minInliers);
        }
        if (attempt.registered)
        {
            keyframe = k;
            return attempt;
        }
        store_ = std::move(before);
        out = attempt;
    }
    return out;
}

void StereoTracker::restart(int frame)
{
    StoredFrame& f = store_.frames[frame];
    for (int j = frame - 1; j >= 0; --j)
        if (store_.frames[j].hasPose())
        {
            f.pose = store_.frames[j].pose;
            break;
        }
    f.status = FrameStatus::Restarted;
    f.keyframe = true;
    f.map = numMaps_++;
    liveMaps_.insert(f.map);
}

void StereoTracker::joinMaps(int frame, int keyframe, const CameraPose& placePose)
{
    const StoredFrame& f = store_.frames[frame];
    const int own = f.map, place = store_.frames[keyframe].map;
    const int keep = std::min(own, place), drop = std::max(own, place);
    // The frame's pose in each map: a pose T in the map dropped is T * G in the map kept.
    const CameraPose inKeep = keep == place ? placePose : f.pose;
    const CameraPose inDrop = keep == place ? f.pose : placePose;
    const CameraPose G = composePose(inversePose(inDrop), inKeep);
    for (StoredFrame& other : store_.frames)
        if (other.hasPose() && other.map == drop)
        {
            other.pose = composePose(other.pose, G);
            other.map = keep;
        }
    liveMaps_.erase(drop);
}

FrameResult StereoTracker::finishFrame(int frame, const FrameFeatures& left, double startSeconds)
{
    // A place attempt that fails restores the store, whose frames then live elsewhere: the frame is
    // looked up afresh at each use, never held across an attempt.
    const auto current = [&]() -> StoredFrame& { return store_.frames[frame]; };
    FrameResult result;
    result.frame = frame;
    if (current().status != FrameStatus::Given)
    {
        std::vector<int> keyframes; // newest first
        for (int j = frame - 1; j >= 0 && (int)keyframes.size() < options_.window; --j)
            if (store_.frames[j].keyframe && store_.frames[j].hasPose())
                keyframes.push_back(j);
        Attempt chosen;
        int used = -1;
        for (int k : keyframes)
        {
            Attempt attempt;
            // Degenerate input of one registration loses the frame, not the tracker.
            runCatchingInputErrors([&] { attempt = registerAgainst(k, frame); }, &attempt.reason);
            if (attempt.registered)
            {
                chosen = attempt;
                used = k;
                break;
            }
            // The newest keyframe's failure says most about the frame.
            if (used < 0 && chosen.reason.empty())
                chosen = attempt;
        }
        if (keyframes.empty())
            chosen.reason = "no keyframe to register against";
        if (used < 0)
        {
            // Lost against the window: the older keyframes' places.
            int place = -1;
            Attempt found = registerAtPlace(
                frame, left, [&](int k) { return std::find(keyframes.begin(), keyframes.end(), k) == keyframes.end(); },
                place);
            if (found.registered)
            {
                chosen = found;
                used = place;
                result.recognisedKeyframe = place;
            }
        }
        result.features = chosen.features;
        result.inliers = chosen.inliers;
        if (used >= 0)
        {
            result.knownViews = 1;
            const CameraPose& a = store_.frames[used].pose;
            current().pose = composePose(chosen.relative, a);
            if (!current().pose.allFinite())
            {
                current().pose = CameraPose();
                result.reason = "the registration gave no finite pose";
                result.features = result.inliers = 0;
                result.recognisedKeyframe = -1;
            }
            else
            {
                if (chosen.covariance.valid)
                {
                    // The world pose is the relative one composed with the keyframe's (held): a
                    // rotation error d of the relative pose moves the world translation by
                    // d x (R_rel t_keyframe).
                    Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Identity();
                    const Eigen::Vector3d lever = chosen.relative.R * a.t;
                    Eigen::Matrix3d cross;
                    cross << 0, -lever[2], lever[1], lever[2], 0, -lever[0], -lever[1], lever[0], 0;
                    J.block<3, 3>(3, 0) = -cross;
                    result.hasCovariance = true;
                    result.covariance = J * chosen.covariance.covariance * J.transpose();
                    result.noiseVariance = chosen.covariance.noiseVariance;
                }
                current().status = FrameStatus::Registered;
                current().map = store_.frames[used].map;
                current().keyframe = !(chosen.parallaxDeg < options_.keyframeParallaxDeg) ||
                                     chosen.overlap < kMinOverlap || result.recognisedKeyframe >= 0;
                for (int kind = 0; kind < 2; ++kind)
                    for (int track : chosen.rejected[kind])
                        store_.split(kKinds[kind], frame, store_.rowIn(kKinds[kind], track, frame));
            }
        }
        if (!current().hasPose())
        {
            result.reason = chosen.reason;
            result.inliers = 0;
            result.recognisedKeyframe = -1;
            int stereoMatches = 0;
            for (int right : stereo_[frame].pointRight)
                stereoMatches += right >= 0 ? 1 : 0;
            for (int right : stereo_[frame].lineRight)
                stereoMatches += right >= 0 ? 1 : 0;
            // A new map needs a place that holds together: the frame before, lost too, registers
            // against this frame's stereo pair, which chance matches of unrelated images do not.
            if (++lostRun_ > options_.maxFrameGap && stereoMatches >= 2 * options_.minInliers)
            {
                Attempt confirmation;
                runCatchingInputErrors([&] { confirmation = registerAgainst(frame, frame - 1); }, &confirmation.reason);
                if (confirmation.registered)
                {
                    restart(frame);
                    result.features = stereoMatches;
                    result.reason.clear();
                }
            }
        }
        if (current().hasPose())
            lostRun_ = 0;
        // While another map holds frames, each new keyframe looks for its places.
        if (current().hasPose() && current().keyframe && liveMaps_.size() > 1)
        {
            int place = -1;
            const int own = current().map;
            Attempt found = registerAtPlace(frame, left, [&](int k) { return store_.frames[k].map != own; }, place);
            if (found.registered)
            {
                joinMaps(frame, place, composePose(found.relative, store_.frames[place].pose));
                result.recognisedKeyframe = place;
            }
        }
    }
    describeFrame(current(), result);
    result.milliseconds = 1e3 * (nowSeconds() - startSeconds);
    return result;
}

} // namespace tripose
