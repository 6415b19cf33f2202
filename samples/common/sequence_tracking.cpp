// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "sequence_tracking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tripose_samples {

namespace {

// The linear method needs four features; with fewer shared with the window the frame is lost.
const int kMinFeatures = 4;

bool seen(const cv::Mat& rows, int i)
{
    return !rows.empty() && !std::isnan(rows.at<double>(i, 0));
}

//! The rows @p keep of @p rows (CV_64F), as a new matrix; empty when none are kept.
cv::Mat selectRows(const cv::Mat& rows, const std::vector<int>& keep)
{
    if (keep.empty())
        return cv::Mat();
    cv::Mat out((int)keep.size(), rows.cols, CV_64F);
    for (size_t k = 0; k < keep.size(); ++k)
        rows.row(keep[k]).copyTo(out.row((int)k));
    return out;
}

//! Features of kind @p rows (one Mat per frame) seen by @p frame and at least two of @p window.
std::vector<int> sharedFeatures(const std::vector<cv::Mat>& rows, int frame, const std::vector<int>& window)
{
    std::vector<int> shared;
    const int n = rows[frame].empty() ? 0 : rows[frame].rows;
    for (int i = 0; i < n; ++i)
    {
        if (!seen(rows[frame], i))
            continue;
        int count = 0;
        for (int w : window)
            count += seen(rows[w], i) ? 1 : 0;
        if (count >= 2)
            shared.push_back(i);
    }
    return shared;
}

/** What frame @p frame is registered from: the features it sees with at least two of the frames
@p known, and their observations (one array per known frame, then the frame's own, as
estimatePoseMultiView() takes them). */
struct Registration
{
    std::vector<int> points, lines; //!< The features' indices in the sequence.
    std::vector<cv::Mat> p, l, K, Rs, ts;
};

//! Row @p i of a frame's observations @p rows (N x width, CV_64F) set to NaN: the frame no longer sees feature i.
void drop(cv::Mat& rows, int i)
{
    rows.row(i).setTo(std::numeric_limits<double>::quiet_NaN());
}

/** Drops, feature by feature, the observation of the known frames furthest from the structure
triangulated from them (triangulateMultiView()) while it is more than @p threshold px off, and
returns the rows of the features that keep two known observations. @p p and @p l hold the known
frames' arrays (updated in place; at least one feature between them), @p Rs, @p ts their poses. */
void dropInconsistentObservations(std::vector<cv::Mat>& p, std::vector<cv::Mat>& l, const std::vector<cv::Mat>& K,
                                  const std::vector<cv::Mat>& Rs, const std::vector<cv::Mat>& ts, double threshold,
                                  std::vector<int>& keepPoints, std::vector<int>& keepLines)
{
    const int numPoints = p.empty() ? 0 : p[0].rows, numLines = l.empty() ? 0 : l[0].rows;
    // Each round drops at most one observation per feature; a feature has at most one per frame.
    for (size_t round = 0; round < Rs.size(); ++round)
    {
        cv::Mat points3d, lines3d, pointErrors, lineErrors;
        bool dropped = false;
        cv::tripose::triangulateMultiView(p, l, K, cv::noArray(), Rs, ts, points3d, lines3d, pointErrors, lineErrors);
        for (int kind = 0; kind < 2; ++kind)
        {
            const cv::Mat& errors = kind == 0 ? pointErrors : lineErrors;
            std::vector<cv::Mat>& rows = kind == 0 ? p : l;
            for (int i = 0; i < errors.rows; ++i)
            {
                double worst = 0;
                int at = -1;
                for (int v = 0; v < errors.cols; ++v)
                {
                    const double e = errors.at<double>(i, v);
                    if (!std::isnan(e) && e > worst)
                    {
                        worst = e;
                        at = v;
                    }
                }
                if (at >= 0 && worst > threshold)
                {
                    drop(rows[at], i);
                    dropped = true;
                }
            }
        }
        if (!dropped)
            break;
    }
    keepPoints.clear();
    keepLines.clear();
    for (int kind = 0; kind < 2; ++kind)
    {
        const std::vector<cv::Mat>& rows = kind == 0 ? p : l;
        std::vector<int>& keep = kind == 0 ? keepPoints : keepLines;
        for (int i = 0; i < (kind == 0 ? numPoints : numLines); ++i)
        {
            int count = 0;
            for (const cv::Mat& m : rows)
                count += seen(m, i) ? 1 : 0;
            if (count >= 2)
                keep.push_back(i);
        }
    }
}

/** The registration data of frame @p frame against the frames @p known; with @p checkThreshold > 0
the known frames' observations are checked first (dropInconsistentObservations()). False when fewer
than four features remain. */
bool buildRegistration(const SequenceObservations& sequence, const std::vector<TrackedFrame>& frames, int frame,
                       const std::vector<int>& known, double checkThreshold, Registration& out)
{
    out = Registration();
    out.points = sharedFeatures(sequence.points, frame, known);
    out.lines = sharedFeatures(sequence.lines, frame, known);
    for (int w : known)
    {
        out.p.push_back(selectRows(sequence.points[w], out.points));
        out.l.push_back(selectRows(sequence.lines[w], out.lines));
        out.K.push_back(sequence.cameraMatrices[w]);
        out.Rs.push_back(frames[w].R);
        out.ts.push_back(frames[w].t);
    }
    // estimatePoseMultiView() takes no arrays for a kind without features.
    const auto dropEmptyKinds = [&out] {
        if (out.points.empty())
            out.p.clear();
        if (out.lines.empty())
            out.l.clear();
    };
    dropEmptyKinds();
    if (checkThreshold > 0 && out.points.size() + out.lines.size() >= (size_t)kMinFeatures)
    {
        std::vector<int> keepPoints, keepLines;
        dropInconsistentObservations(out.p, out.l, out.K, out.Rs, out.ts, checkThreshold, keepPoints, keepLines);
        for (cv::Mat& m : out.p)
            m = selectRows(m, keepPoints);
        for (cv::Mat& m : out.l)
            m = selectRows(m, keepLines);
        for (int& i : keepPoints)
            i = out.points[i];
        for (int& i : keepLines)
            i = out.lines[i];
        out.points = keepPoints;
        out.lines = keepLines;
        dropEmptyKinds();
    }
    if (out.points.size() + out.lines.size() < (size_t)kMinFeatures)
        return false;
    if (!out.points.empty())
        out.p.push_back(selectRows(sequence.points[frame], out.points));
    if (!out.lines.empty())
        out.l.push_back(selectRows(sequence.lines[frame], out.lines));
    out.K.push_back(sequence.cameraMatrices[frame]);
    return true;
}

/** Frame @p frame's observations of @p features, and the later frames' of the same tracks, moved to
new tracks (rows appended to every frame's array, NaN in the earlier frames). */
void splitTracks(std::vector<cv::Mat>& rows, int frame, const std::vector<int>& features)
{
    if (features.empty())
        return;
    for (int f = 0; f < (int)rows.size(); ++f)
    {
        cv::Mat& m = rows[f];
        cv::Mat added((int)features.size(), m.cols, CV_64F, cv::Scalar::all(std::numeric_limits<double>::quiet_NaN()));
        if (f >= frame)
            for (size_t k = 0; k < features.size(); ++k)
            {
                m.row(features[k]).copyTo(added.row((int)k));
                drop(m, features[k]);
            }
        cv::vconcat(m, added, m);
    }
}

//! The entries of @p features whose @p inliers flag (CV_8U, one per entry) is zero.
std::vector<int> rejected(const std::vector<int>& features, const cv::Mat& inliers)
{
    std::vector<int> out;
    for (size_t k = 0; k < features.size(); ++k)
        if (inliers.at<uchar>((int)k) == 0)
            out.push_back(features[k]);
    return out;
}

/** The median, over the inlier points of registration @p r and the two end points of its inlier
lines, triangulated from its known frames, of the angle (degrees) between the rays from the last
known frame's centre and from the new frame's (pose @p R, @p t): how far the new frame has moved
for that structure. Empty inlier masks (the linear method) count every feature; +inf without
structure. */
double medianParallaxDeg(const Registration& r, const cv::Mat& R, const cv::Mat& t, const cv::Mat& pointInliers,
                         const cv::Mat& lineInliers)
{
    const size_t known = r.Rs.size();
    const std::vector<cv::Mat> p(r.p.begin(), r.p.begin() + std::min(known, r.p.size()));
    const std::vector<cv::Mat> l(r.l.begin(), r.l.begin() + std::min(known, r.l.size()));
    cv::Mat points3d, lines3d, pointErrors, lineErrors;
    cv::tripose::triangulateMultiView(p, l, std::vector<cv::Mat>(r.K.begin(), r.K.begin() + known), cv::noArray(),
                                      r.Rs, r.ts, points3d, lines3d, pointErrors, lineErrors);
    const cv::Vec3d last(cv::Mat(-r.Rs.back().t() * r.ts.back())), current(cv::Mat(-R.t() * t));
    std::vector<double> angles;
    const auto addAngles = [&](const cv::Mat& structure, const cv::Mat& inliers) {
        for (int i = 0; i < structure.rows; ++i)
        {
            if (!inliers.empty() && !inliers.at<uchar>(i))
                continue;
            for (int c = 0; c + 3 <= structure.cols; c += 3)
            {
                const cv::Vec3d X(structure.at<double>(i, c), structure.at<double>(i, c + 1),
                                  structure.at<double>(i, c + 2));
                const cv::Vec3d a = X - last, b = X - current;
                const double angle = std::atan2(cv::norm(a.cross(b)), a.dot(b));
                if (std::isfinite(angle))
                    angles.push_back(angle * 180.0 / CV_PI);
            }
        }
    };
    addAngles(points3d, pointInliers);
    addAngles(lines3d, lineInliers);
    if (angles.empty())
        return std::numeric_limits<double>::infinity();
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    return angles[angles.size() / 2];
}

} // namespace

bool registrationViews(const SequenceObservations& sequence, const std::vector<TrackedFrame>& frames, int frame,
                 const std::vector<int>& known, std::vector<cv::Mat>& p, std::vector<cv::Mat>& l,
                 std::vector<cv::Mat>& K, std::vector<cv::Mat>& Rs, std::vector<cv::Mat>& ts, int& features)
{
    Registration r;
    const bool enough = buildRegistration(sequence, frames, frame, known, 0, r);
    features = (int)(r.points.size() + r.lines.size());
    if (!enough)
        return false;
    p = r.p;
    l = r.l;
    K = r.K;
    Rs = r.Rs;
    ts = r.ts;
    return true;
}

double adjustFrames(const SequenceObservations& sequence, std::vector<TrackedFrame>& frames,
                    const std::vector<int>& free, const std::vector<int>& fixed, const cv::tripose::RefineParams& params)
{
    std::vector<int> all = fixed;
    all.insert(all.end(), free.begin(), free.end());
    std::vector<int> points, lines;
    for (int kind = 0; kind < 2; ++kind)
    {
        const std::vector<cv::Mat>& rows = kind == 0 ? sequence.points : sequence.lines;
        std::vector<int>& keep = kind == 0 ? points : lines;
        const int n = rows[all[0]].empty() ? 0 : rows[all[0]].rows;
        for (int i = 0; i < n; ++i)
        {
            int seenAll = 0, seenFree = 0;
            for (int f : all)
                seenAll += seen(rows[f], i) ? 1 : 0;
            for (int f : free)
                seenFree += seen(rows[f], i) ? 1 : 0;
            if (seenAll >= 2 && seenFree >= 1)
                keep.push_back(i);
        }
    }
    std::vector<cv::Mat> p, l, K, Rs, ts;
    cv::Mat fixedMask((int)all.size(), 1, CV_8U, cv::Scalar(0));
    for (size_t v = 0; v < all.size(); ++v)
    {
        const int f = all[v];
        p.push_back(selectRows(sequence.points[f], points));
        l.push_back(selectRows(sequence.lines[f], lines));
        K.push_back(sequence.cameraMatrices[f]);
        Rs.push_back(frames[f].R);
        ts.push_back(frames[f].t);
        fixedMask.at<uchar>((int)v) = v < fixed.size() ? 1 : 0;
    }
    if (points.empty())
        p.clear();
    if (lines.empty())
        l.clear();
    if (points.size() + lines.size() < (size_t)kMinFeatures)
        return std::numeric_limits<double>::infinity();
    std::vector<cv::Mat> refinedRs = Rs, refinedTs = ts; // refined in place
    const double rms = cv::tripose::adjustPosesMultiView(p, l, K, cv::noArray(), fixedMask, refinedRs, refinedTs, params);
    if (!std::isfinite(rms))
        return rms;
    for (size_t v = fixed.size(); v < all.size(); ++v)
    {
        if (!(cv::checkRange(refinedRs[v]) && cv::checkRange(refinedTs[v])))
            return std::numeric_limits<double>::infinity();
    }
    for (size_t v = fixed.size(); v < all.size(); ++v)
    {
        frames[all[v]].R = refinedRs[v];
        frames[all[v]].t = refinedTs[v];
    }
    return rms;
}

namespace {

/** The local adjustment of TrackOptions::localAdjustment after frame @p k is registered: the
registered frames of the window and frame k, against every earlier frame with a pose. */
void adjustWindow(const SequenceObservations& sequence, std::vector<TrackedFrame>& frames,
                  const std::vector<int>& window, int k, const TrackOptions& options)
{
    std::vector<int> free;
    for (int j : window)
        if (frames[j].status == FRAME_REGISTERED)
            free.push_back(j);
    free.push_back(k);
    std::vector<int> fixed;
    for (int j = 0; j < k; ++j)
        if (frames[j].keyframe && std::find(free.begin(), free.end(), j) == free.end())
            fixed.push_back(j);
    cv::tripose::RefineParams params;
    params.loss = cv::tripose::LOSS_HUBER;
    params.lossScale = options.ransac.threshold;
    adjustFrames(sequence, frames, free, fixed, params);
}

} // namespace

std::vector<TrackedFrame> trackSequence(SequenceObservations& sequence, const TrackOptions& options)
{
    CV_Assert(options.window >= 2);
    const int F = (int)sequence.cameraMatrices.size();
    CV_Assert(F >= 2 && (int)sequence.points.size() == F && (int)sequence.lines.size() == F);
    std::vector<TrackedFrame> frames(F);
    frames[0].status = frames[1].status = FRAME_GIVEN;
    frames[0].keyframe = frames[1].keyframe = true;
    sequence.R0.convertTo(frames[0].R, CV_64F);
    sequence.t0.convertTo(frames[0].t, CV_64F);
    sequence.R1.convertTo(frames[1].R, CV_64F);
    sequence.t1.convertTo(frames[1].t, CV_64F);
    const double checkThreshold = options.checkTracks && options.robust ? options.ransac.threshold : 0;

    for (int k = 2; k < F; ++k)
    {
        TrackedFrame& frame = frames[k];
        const int64 start = cv::getTickCount();
        std::vector<int> window;
        for (int j = k - 1; j >= 0 && (int)window.size() < options.window; --j)
            if (frames[j].keyframe)
                window.insert(window.begin(), j);
        frame.knownViews = (int)window.size();
        Registration r;
        const bool enough = buildRegistration(sequence, frames, k, window, checkThreshold, r);
        frame.features = (int)(r.points.size() + r.lines.size());
        // Fewer features than the inliers a pose needs: no estimate could be kept, so none is made
        // (on a few chance matches the robust estimator's search of several basins takes long).
        if (!enough || frame.features < options.minInliers)
        {
            frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
            continue; // lost: too few features shared with the window
        }

        cv::Mat R, t, pointInliers, lineInliers;
        if (options.robust)
            frame.inliers = cv::tripose::estimatePoseMultiViewRansac(r.p, r.l, r.K, cv::noArray(), r.Rs, r.ts, R, t,
                                                                     options.ransac, pointInliers, lineInliers);
        else
            frame.inliers = cv::tripose::estimatePoseMultiView(r.p, r.l, r.K, cv::noArray(), r.Rs, r.ts, R, t) > 0 ?
                                frame.features : 0;
        if (frame.inliers < std::max(1, options.minInliers) || R.empty())
        {
            frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
            continue; // lost: no pose, or too little support for it
        }
        frame.status = FRAME_REGISTERED;
        frame.R = R;
        frame.t = t;
        // Judged on the registration's own poses, which the local adjustment below moves by a small
        // fraction of any parallax that matters here.
        frame.keyframe = !(medianParallaxDeg(r, R, t, pointInliers, lineInliers) < options.keyframeParallaxDeg);
        if (options.checkTracks && options.robust)
        {
            splitTracks(sequence.points, k, rejected(r.points, pointInliers));
            splitTracks(sequence.lines, k, rejected(r.lines, lineInliers));
        }
        if (options.localAdjustment)
            adjustWindow(sequence, frames, window, k, options);
        frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    }
    return frames;
}

std::vector<std::string> trackResultKeys()
{
    return { "sequence",           "correspondences", "window",        "method",       "local_refine",
             "check_tracks",       "poses",           "status",        "keyframe",     "features",
             "inliers",            "rotation_error_deg", "position_error", "path_length", "drift_percent",
             "ms_per_frame" };
}

} // namespace tripose_samples
