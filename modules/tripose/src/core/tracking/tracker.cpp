// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include <Eigen/Geometry>

#include "../problem/view_set_builder.hpp"
#include "../support/error.hpp"
#include "bundle_adjustment.hpp"
#include "frame_arguments.hpp"
#include "loop_correction.hpp"
#include "place_registration.hpp"
#include "window_registration.hpp"

namespace tripose {

namespace {

// Every adjustment splits off the observations that disagree with its result and adjusts again, at
// most this many times in all: rounds after the first remove the wrong links the first one hid.
const int kAdjustmentRounds = 3;

} // namespace

Tracker::Tracker(const Eigen::Matrix3d& K, const std::vector<double>& distortion, const TrackerOptions& options)
    : options_(options), K_(K), retrieval_(options.matching)
{
    checkCameraMatrix(K, "K");
    const size_t n = distortion.size();
    if (!(n == 0 || n == 4 || n == 5 || n == 8 || n == 12 || n == 14))
        fail(ErrorCode::BadArgument, "dist must hold 4, 5, 8, 12 or 14 coefficients (OpenCV's model), got %d", (int)n);
    for (size_t i = 0; i < n; ++i)
    {
        if (!std::isfinite(distortion[i]))
            fail(ErrorCode::BadArgument, "dist[%d] is not finite", (int)i);
        distortion_.k[i] = distortion[i];
        distorted_ = distorted_ || distortion[i] != 0;
    }
    checkTrackerOptions(options);
}

int Tracker::startFrame(const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector4d>& segments,
                        const CameraPose* pose, const Eigen::Matrix3d* K)
{
    const int index = numFrames();
    if (K)
        checkCameraMatrix(*K, "K");
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            fail(ErrorCode::BadArgument, "points[%d] of frame %d is not finite", (int)i, index);
    for (size_t i = 0; i < segments.size(); ++i)
        if (!segments[i].allFinite())
            fail(ErrorCode::BadArgument, "segments[%d] of frame %d is not finite", (int)i, index);
    if (!pose && index < 2)
        fail(ErrorCode::BadArgument, "pose: a monocular tracker needs the poses of its first two frames, which fix "
             "the world frame and the scale; frame %d has none", index);
    StoredFrame frame;
    frame.K = K ? *K : K_;
    frame.points = points;
    frame.segments = segments;
    if (distorted_)
    {
        distortion_.undistortPixels(frame.points, frame.K);
        std::vector<Eigen::Vector2d> ends;
        for (const Eigen::Vector4d& s : segments)
        {
            ends.emplace_back(s[0], s[1]);
            ends.emplace_back(s[2], s[3]);
        }
        distortion_.undistortPixels(ends, frame.K);
        for (size_t i = 0; i < segments.size(); ++i)
            frame.segments[i] << ends[2 * i], ends[2 * i + 1];
    }
    if (pose)
    {
        frame.pose = checkedPose(*pose);
        frame.status = FrameStatus::Given;
        frame.keyframe = true;
        if (index == 1 && !((frame.pose.centre() - store_.frames[0].pose.centre()).norm() >
                            1e-12 * std::max(1.0, frame.pose.centre().norm())))
            fail(ErrorCode::BadArgument, "pose: frames 0 and 1 have the same centre: no baseline fixes the scale");
    }
    frame.pointTrack.assign(points.size(), -1);
    frame.lineTrack.assign(segments.size(), -1);
    store_.frames.push_back(frame);
    return index;
}

void Tracker::link(FeatureKind kind, int from, int to, const Matches& matches)
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

void Tracker::associateByMatching(int frame, const FrameFeatures& features)
{
    const StoredFrame& current = store_.frames[frame];
    if (!recent_.empty() && recent_.back().first == frame - 1)
    {
        const int previous = frame - 1;
        const StoredFrame& before = store_.frames[previous];
        Matches points, segments;
        int from = previous;
        if (current.status == FrameStatus::Given && before.hasPose())
        {
            // Both poses known: matched under their epipolar geometry.
            const Eigen::Matrix3d F =
                fundamentalFromPose(before.K, current.K, poseRelativeTo(current.pose, before.pose));
            const FrameFeatures& a = recent_.back().second;
            if (frame == 1)
                givenPairAgreement_ = epipolarAgreement(a, features, F, options_.matching);
            points = matchPointsEpipolar(a, features, F, options_.matching);
            segments = matchSegmentsEpipolar(a, features, F, options_.matching);
        }
        else
        {
            bool underGeometry = matchUnknownPose(recent_.back().second, features, options_.matching, points, segments);
            // A frame that shares too few matches with the one before for their geometry (blurred,
            // covered, of another scene) would end every track: the nearest earlier frame that does
            // share enough takes its place.
            for (auto it = recent_.rbegin() + 1; !underGeometry && it != recent_.rend(); ++it)
            {
                Matches earlierPoints, earlierSegments;
                if (matchUnderFundamental(it->second, features, options_.matching, earlierPoints, earlierSegments))
                {
                    points.swap(earlierPoints);
                    segments.swap(earlierSegments);
                    from = it->first;
                    underGeometry = true;
                }
            }
        }
        link(FeatureKind::Point, from, frame, points);
        link(FeatureKind::Line, from, frame, segments);
    }
}

FrameResult Tracker::addFeatures(const FrameFeatures& features, const CameraPose* pose, const Eigen::Matrix3d* K)
{
    const double start = nowSeconds();
    if (byIds_)
        fail(ErrorCode::BadArgument, "features: this tracker was given linked observations; a tracker takes either "
             "features or observations");
    const int n = (int)features.points.size(), m = (int)features.segments.size();
    if (features.pointDescriptors.rows != n)
        fail(ErrorCode::BadSize, "point_descriptors must have one row per point: %d rows for %d points",
             features.pointDescriptors.rows, n);
    if (features.lineDescriptors.rows != m)
        fail(ErrorCode::BadSize, "line_descriptors must have one row per segment: %d rows for %d segments",
             features.lineDescriptors.rows, m);
    for (const Descriptors* d : { &features.pointDescriptors, &features.lineDescriptors })
        if (!d->binary)
            for (float v : d->real)
                if (!std::isfinite(v))
                    fail(ErrorCode::BadArgument, "%s holds a value that is not finite",
                         d == &features.pointDescriptors ? "point_descriptors" : "line_descriptors");
    for (const auto& r : recent_)
        for (int kind = 0; kind < 2; ++kind)
        {
            const Descriptors& a = kind == 0 ? r.second.pointDescriptors : r.second.lineDescriptors;
            const Descriptors& b = kind == 0 ? features.pointDescriptors : features.lineDescriptors;
            if (!a.empty() && !b.empty() && (a.binary != b.binary || a.cols != b.cols))
                fail(ErrorCode::BadArgument, "%s: every frame's descriptors must be of one kind and length (%s of "
                     "%d, got %s of %d)", kind == 0 ? "point_descriptors" : "line_descriptors",
                     a.binary ? "bytes" : "values", a.cols, b.binary ? "bytes" : "values", b.cols);
        }
    byFeatures_ = true;
    const int frame = startFrame(features.points, features.segments, pose, K);
    FrameFeatures undistorted = features;
    undistorted.points = store_.frames[frame].points;
    undistorted.segments = store_.frames[frame].segments;
    associateByMatching(frame, undistorted);
    recent_.emplace_back(frame, std::move(undistorted));
    while ((int)recent_.size() > options_.maxFrameGap)
        recent_.pop_front();
    return finishFrame(frame, start, &recent_.back().second);
}

FrameResult Tracker::addObservations(const std::vector<Eigen::Vector2d>& points, const std::vector<int64_t>& pointIds,
                                     const std::vector<Eigen::Vector4d>& segments, const std::vector<int64_t>& lineIds,
                                     const CameraPose* pose, const Eigen::Matrix3d* K)
{
    const double start = nowSeconds();
    if (byFeatures_)
        fail(ErrorCode::BadArgument, "point_ids: this tracker was given features; a tracker takes either features or "
             "observations");
    checkObservationIds(points.size(), pointIds, segments.size(), lineIds);
    byIds_ = true;
    const int frame = startFrame(points, segments, pose, K);
    for (int kind = 0; kind < 2; ++kind)
    {
        const FeatureKind k = kind == 0 ? FeatureKind::Point : FeatureKind::Line;
        const std::vector<int64_t>& ids = kind == 0 ? pointIds : lineIds;
        std::map<int64_t, int>& idTrack = kind == 0 ? pointIdTrack_ : lineIdTrack_;
        for (size_t i = 0; i < ids.size(); ++i)
        {
            auto it = idTrack.find(ids[i]);
            const int track = it != idTrack.end() ? it->second : (idTrack[ids[i]] = store_.newTrack(k));
            store_.observe(k, track, frame, (int)i);
        }
    }
    pointIdsOfFrame_.push_back(pointIds);
    lineIdsOfFrame_.push_back(lineIds);
    return finishFrame(frame, start, nullptr);
}

FrameResult Tracker::finishFrame(int frame, double startSeconds, const FrameFeatures* features)
{
    FrameResult result;
    result.frame = frame;
    int oldestRecent = -1; // The oldest of the latest keyframes in the window.
    if (store_.frames[frame].status != FrameStatus::Given)
        registerFrame(frame, features, result, oldestRecent);
    if (store_.frames[frame].keyframe)
    {
        const bool closed = features && keepKeyframe(frame, *features, oldestRecent, result);
        // A closed loop has just adjusted the frames; features and observations count alike.
        ++keyframesSinceAdjustment_;
        if (!closed && options_.globalAdjustmentInterval > 0 &&
            keyframesSinceAdjustment_ >= options_.globalAdjustmentInterval)
            adjustFramesAfter(-1);
    }
    describeFrame(store_.frames[frame], result);
    result.milliseconds = 1e3 * (nowSeconds() - startSeconds);
    return result;
}

void Tracker::registerFrame(int frame, const FrameFeatures* features, FrameResult& result, int& oldestRecent)
{
    std::vector<int> window;
    for (int j = frame - 1; j >= 0 && (int)window.size() < options_.window; --j)
        if (store_.frames[j].keyframe)
            window.insert(window.begin(), j);
    const int recent = (int)window.size();
    oldestRecent = window.empty() ? -1 : window.front();
    // With loop closure, older keyframes that see much of what the frame sees (a place the
    // camera came back to) join the window, so that the frame is held by the structure already
    // known there.
    if (options_.loopClosure)
        for (const auto& k : keyframesSharingTracks(store_, frame, options_.minInliers))
            if ((int)window.size() < recent + options_.window && (window.empty() || k.first < window.front()))
                window.push_back(k.first);
    std::sort(window.begin(), window.end());
    result.knownViews = (int)window.size();
    Registration r;
    // The window's own geometry can be degenerate (keyframes at one centre): the frame is lost,
    // not the tracker.
    if (window.size() < 2)
        r.reason = "fewer than two keyframes to register against";
    else
        runCatchingInputErrors([&] { r = registerAgainstWindow(store_, frame, window, options_); }, &r.reason);
    if (!r.registered && features && !keyframeFeatures_.empty())
    {
        // Lost against the window: any keyframe whose place the frame sees can take it back.
        int keyframe = -1;
        Registration found = recognisePlace(
            frame, *features, [](int) { return true; }, options_.minInliers, keyframe);
        if (found.registered)
        {
            r = found;
            r.keyframe = true;
            result.recognisedKeyframe = keyframe;
        }
    }
    result.features = r.features;
    result.inliers = r.inliers;
    result.reason = r.reason;
    if (r.registered)
    {
        result.hasCovariance = r.covariance.valid;
        result.covariance = r.covariance.covariance;
        result.noiseVariance = r.covariance.noiseVariance;
        StoredFrame& f = store_.frames[frame];
        f.status = FrameStatus::Registered;
        f.pose = r.pose;
        f.keyframe = r.keyframe;
        for (int kind = 0; kind < 2; ++kind)
        {
            const FeatureKind k = kind == 0 ? FeatureKind::Point : FeatureKind::Line;
            for (int track : kind == 0 ? r.rejectedPoints : r.rejectedLines)
            {
                const int row = store_.rowIn(k, track, frame);
                const int newTrack = store_.split(k, frame, row);
                // The caller's id now names the new track in the frames that follow.
                if (byIds_)
                    (kind == 0 ? pointIdTrack_ : lineIdTrack_)[(kind == 0 ? pointIdsOfFrame_
                                                                          : lineIdsOfFrame_)[frame][row]] = newTrack;
            }
        }
        if (options_.localAdjustment)
        {
            std::vector<int> free, fixed;
            for (int j : window)
                if (store_.frames[j].status == FrameStatus::Registered)
                    free.push_back(j);
            free.push_back(frame);
            for (int j = 0; j < frame; ++j)
                if (store_.frames[j].keyframe && std::find(free.begin(), free.end(), j) == free.end())
                    fixed.push_back(j);
            adjust(free, fixed);
        }
    }
}

bool Tracker::keepKeyframe(int frame, const FrameFeatures& features, int oldestRecent, FrameResult& result)
{
    bool closed = false;
    if (options_.loopClosure && store_.frames[frame].status == FrameStatus::Registered &&
        result.recognisedKeyframe < 0 && oldestRecent >= 0)
    {
        // The keyframes older than the window that look like the frame are places it may see
        // again: one it registers against is linked to it (its tracks join theirs), and closes a
        // loop when the frame's pose through it and its tracked pose disagree.
        int keyframe = -1;
        const Registration place = recognisePlace(
            frame, features, [&](int k) { return k < oldestRecent; }, 2 * options_.minInliers, keyframe);
        if (place.registered)
        {
            result.recognisedKeyframe = keyframe;
            if (mayCloseLoop(store_, keyframe, frame, 2 * options_.window, lastLoopFrame_, options_.window) &&
                closesLoop(store_.frames[frame].pose, place.pose, store_.frames[keyframe].pose))
            {
                closeLoop(frame, keyframe, place.pose);
                lastLoopFrame_ = frame;
                closed = true;
            }
        }
    }
    keyframeFeatures_[frame] = features;
    retrieval_.add(frame, features);
    return closed;
}

Registration Tracker::recognisePlace(int frame, const FrameFeatures& features,
                                     const std::function<bool(int)>& eligible, int minInliers, int& keyframe)
{
    // A place is worth the geometric check when a good share of the sample matches.
    const int minMatches = 20, candidates = 3;
    Registration out;
    out.reason = "no keyframe looks like it";
    for (const auto& candidate : retrieval_.rank(
             features, [&](int k) { return eligible(k) && store_.frames[k].hasPose(); }, minMatches, candidates))
    {
        const std::vector<int> neighbours = covisibleKeyframes(store_, candidate.first, options_.window);
        if (neighbours.size() < 2)
            continue;
        Registration r = registerAgainstPlace(store_, frame, features, candidate.first,
                                              keyframeFeatures_.at(candidate.first), neighbours, options_, minInliers);
        if (r.registered)
        {
            keyframe = candidate.first;
            return r;
        }
        out.reason = r.reason;
    }
    return out;
}

void Tracker::closeLoop(int frame, int keyframe, const CameraPose& loopPose)
{
    correctLoop(store_, keyframe, frame, loopPose, options_.minInliers, 2 * options_.window);
    adjustFramesAfter(keyframe);
}

void Tracker::adjustFramesAfter(int first)
{
    keyframesSinceAdjustment_ = 0;
    std::vector<int> free, fixed;
    for (int k = 0; k < numFrames(); ++k)
    {
        if (store_.frames[k].status == FrameStatus::Given || (k <= first && store_.frames[k].hasPose()))
            fixed.push_back(k);
        else if (store_.frames[k].status == FrameStatus::Registered)
            free.push_back(k);
    }
    if (fixed.size() < 2 || free.empty())
        return;
    adjust(free, fixed);
}

void Tracker::adjust(const std::vector<int>& free, const std::vector<int>& fixed)
{
    // Features the caller links (observations by id) are long tracks that the caller checks as it
    // follows them: an adjustment that cut them where they disagree with its frames would cut the
    // links to the held keyframes that stop them drifting. Matched features are linked here, frame
    // to frame, and a wrong link is split off.
    const std::vector<int> splitIn = byIds_ ? std::vector<int>() : free;
    runCatchingInputErrors(
        [&] { adjustAndSplitOutliers(store_, free, fixed, splitIn, options_, links(), kAdjustmentRounds); });
}

} // namespace tripose
