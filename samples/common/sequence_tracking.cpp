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

} // namespace

bool registrationViews(const SequenceObservations& sequence, const std::vector<TrackedFrame>& frames, int frame,
                 const std::vector<int>& known, std::vector<cv::Mat>& p, std::vector<cv::Mat>& l,
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
    for (int w : known)
    {
        p.push_back(selectRows(sequence.points[w], points));
        l.push_back(selectRows(sequence.lines[w], lines));
        K.push_back(sequence.cameraMatrices[w]);
        Rs.push_back(frames[w].R);
        ts.push_back(frames[w].t);
    }
    p.push_back(selectRows(sequence.points[frame], points));
    l.push_back(selectRows(sequence.lines[frame], lines));
    K.push_back(sequence.cameraMatrices[frame]);
    if (points.empty())
        p.clear();
    if (lines.empty())
        l.clear();
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
        if (frames[j].status != FRAME_LOST && std::find(free.begin(), free.end(), j) == free.end())
            fixed.push_back(j);
    cv::tripose::RefineParams params;
    params.loss = cv::tripose::LOSS_HUBER;
    params.lossScale = options.ransac.threshold;
    adjustFrames(sequence, frames, free, fixed, params);
}

} // namespace

std::vector<TrackedFrame> trackSequence(const SequenceObservations& sequence, const TrackOptions& options)
{
    CV_Assert(options.window >= 2);
    const int F = (int)sequence.cameraMatrices.size();
    CV_Assert(F >= 2 && (int)sequence.points.size() == F && (int)sequence.lines.size() == F);
    std::vector<TrackedFrame> frames(F);
    frames[0].status = frames[1].status = FRAME_GIVEN;
    sequence.R0.convertTo(frames[0].R, CV_64F);
    sequence.t0.convertTo(frames[0].t, CV_64F);
    sequence.R1.convertTo(frames[1].R, CV_64F);
    sequence.t1.convertTo(frames[1].t, CV_64F);

    for (int k = 2; k < F; ++k)
    {
        TrackedFrame& frame = frames[k];
        const int64 start = cv::getTickCount();
        std::vector<int> window;
        for (int j = k - 1; j >= 0 && (int)window.size() < options.window; --j)
            if (frames[j].status != FRAME_LOST)
                window.insert(window.begin(), j);
        std::vector<cv::Mat> p, l, K, Rs, ts;
        frame.knownViews = (int)window.size();
        if (!registrationViews(sequence, frames, k, window, p, l, K, Rs, ts, frame.features))
        {
            frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
            continue; // lost: fewer than four features shared with the window
        }

        cv::Mat R, t;
        if (options.robust)
            frame.inliers = cv::tripose::estimatePoseMultiViewRansac(p, l, K, cv::noArray(), Rs, ts, R, t, options.ransac);
        else
            frame.inliers = cv::tripose::estimatePoseMultiView(p, l, K, cv::noArray(), Rs, ts, R, t) > 0 ? frame.features : 0;
        if (frame.inliers == 0 || R.empty())
        {
            frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
            continue; // lost: no pose
        }
        frame.status = FRAME_REGISTERED;
        frame.R = R;
        frame.t = t;
        if (options.localAdjustment)
            adjustWindow(sequence, frames, window, k, options);
        frame.milliseconds = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    }
    return frames;
}

std::vector<std::string> trackResultKeys()
{
    return { "sequence",           "correspondences", "window",      "method",        "local_refine",
             "poses",              "status",          "features",    "inliers",       "rotation_error_deg",
             "position_error",     "path_length",     "drift_percent", "ms_per_frame" };
}

} // namespace tripose_samples
