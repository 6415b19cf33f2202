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

//! The rows of @p rows that the frame sees (positions) and their feature indices (ids).
void seenRows(const cv::Mat& rows, cv::Mat& positions, std::vector<int>& ids)
{
    ids.clear();
    for (int i = 0; i < rows.rows; ++i)
        if (seen(rows, i))
            ids.push_back(i);
    positions = selectRows(rows, ids);
}

} // namespace

std::vector<cv::tripose::TrackedFrame> trackSequence(SequenceObservations& sequence,
                                                     const cv::tripose::TrackerParams& params)
{
    const int F = (int)sequence.cameraMatrices.size();
    CV_Assert(F >= 2 && (int)sequence.points.size() == F && (int)sequence.lines.size() == F);
    const cv::Ptr<cv::tripose::Tracker> tracker =
        cv::tripose::Tracker::create(sequence.cameraMatrices[0], cv::noArray(), params);
    std::vector<cv::tripose::TrackedFrame> frames;
    std::vector<cv::Mat> pointRows(F), lineRows(F);
    std::vector<std::vector<int>> pointTracks(F), lineTracks(F);
    for (int k = 0; k < F; ++k)
    {
        std::vector<int> pointIds, lineIds;
        seenRows(sequence.points[k], pointRows[k], pointIds);
        seenRows(sequence.lines[k], lineRows[k], lineIds);
        const bool given = k < 2;
        frames.push_back(tracker->addObservations(pointRows[k], pointIds, lineRows[k], lineIds,
                                                  given ? (k == 0 ? sequence.R0 : sequence.R1) : cv::Mat(),
                                                  given ? (k == 0 ? sequence.t0 : sequence.t1) : cv::Mat(),
                                                  sequence.cameraMatrices[k]));
    }
    // The poses a local adjustment moved after their frame's result, the tracks as they ended.
    for (int k = 0; k < F; ++k)
    {
        if (frames[k].status != cv::tripose::FRAME_LOST)
            tracker->getPose(k, frames[k].R, frames[k].t);
        cv::Mat pointTrack, lineTrack;
        tracker->getTracks(k, pointTrack, lineTrack);
        pointTracks[k] = pointTrack.empty() ? std::vector<int>() : std::vector<int>(pointTrack);
        lineTracks[k] = lineTrack.empty() ? std::vector<int>() : std::vector<int>(lineTrack);
    }
    sequence.points = observationsByTrack(pointRows, pointTracks, 2);
    sequence.lines = observationsByTrack(lineRows, lineTracks, 4);
    return frames;
}

std::vector<cv::Mat> observationsByTrack(const std::vector<cv::Mat>& rows, const std::vector<std::vector<int>>& tracks,
                                         int width)
{
    int numTracks = 0;
    for (const std::vector<int>& frame : tracks)
        for (int t : frame)
            numTracks = std::max(numTracks, t + 1);
    std::vector<cv::Mat> out;
    for (size_t f = 0; f < rows.size(); ++f)
    {
        cv::Mat m(numTracks, width, CV_64F, cv::Scalar::all(std::numeric_limits<double>::quiet_NaN()));
        for (size_t i = 0; i < tracks[f].size(); ++i)
            if (tracks[f][i] >= 0)
                rows[f].row((int)i).copyTo(m.row(tracks[f][i]));
        out.push_back(numTracks > 0 ? m : cv::Mat());
    }
    return out;
}

bool registrationViews(const SequenceObservations& sequence, const std::vector<cv::tripose::TrackedFrame>& frames,
                       int frame, const std::vector<int>& known, std::vector<cv::Mat>& p, std::vector<cv::Mat>& l,
                       std::vector<cv::Mat>& K, std::vector<cv::Mat>& Rs, std::vector<cv::Mat>& ts, int& features)
{
    const std::vector<int> points = sharedFeatures(sequence.points, frame, known);
    const std::vector<int> lines = sharedFeatures(sequence.lines, frame, known);
    features = (int)(points.size() + lines.size());
    if (features < kMinFeatures)
        return false;
    p.clear();
    l.clear();
    K.clear();
    Rs.clear();
    ts.clear();
    std::vector<int> views = known;
    views.push_back(frame);
    for (int v : views)
    {
        if (!points.empty())
            p.push_back(selectRows(sequence.points[v], points));
        if (!lines.empty())
            l.push_back(selectRows(sequence.lines[v], lines));
        K.push_back(sequence.cameraMatrices[v]);
        if (v != frame)
        {
            Rs.push_back(frames[v].R);
            ts.push_back(frames[v].t);
        }
    }
    return true;
}

double adjustFrames(const SequenceObservations& sequence, std::vector<cv::tripose::TrackedFrame>& frames,
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

std::vector<std::string> trackResultKeys()
{
    return { "sequence",           "correspondences", "window",        "method",       "local_refine",
             "check_tracks",       "poses",           "status",        "keyframe",     "features",
             "inliers",            "rotation_error_deg", "position_error", "path_length", "drift_percent",
             "ms_per_frame" };
}

} // namespace tripose_samples
