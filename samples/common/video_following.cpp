// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "video_following.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <opencv2/ximgproc.hpp>

namespace tripose_samples {

namespace {

// A point found in the right image farther than this (px) from its epipolar line is not the left
// point: the flow slid along an edge or onto a repeated texture.
const double kEpipolarTolerancePx = 2.0;

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

cv::Mat toGrey(const cv::Mat& image, const char* name)
{
    if (image.depth() != CV_8U)
        throw std::runtime_error(std::string(name) + ": expected 8-bit pixels");
    if (image.channels() == 1)
        return image;
    if (image.channels() != 3 && image.channels() != 4)
        throw std::runtime_error(std::string(name) + ": expected a grey, BGR or BGRA image");
    cv::Mat grey;
    cv::cvtColor(image, grey, image.channels() == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
    return grey;
}

/** The flow of @p start from image @p a into image @p b (@p moved); per point whether it was found,
the flow back returned within options.maxFlowError px of where it started, and it lies inside @p b. */
std::vector<bool> flowThereAndBack(const cv::Mat& a, const cv::Mat& b, const std::vector<cv::Point2f>& start,
                                   std::vector<cv::Point2f>& moved, const FollowOptions& options)
{
    std::vector<bool> kept(start.size(), false);
    if (start.empty())
    {
        moved.clear();
        return kept;
    }
    const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
    const cv::Size window(options.windowSize, options.windowSize);
    std::vector<unsigned char> found, returned;
    std::vector<float> error;
    std::vector<cv::Point2f> back;
    cv::calcOpticalFlowPyrLK(a, b, start, moved, found, error, window, options.pyramidLevels, criteria);
    cv::calcOpticalFlowPyrLK(b, a, moved, back, returned, error, window, options.pyramidLevels, criteria);
    for (size_t i = 0; i < start.size(); ++i)
    {
        const cv::Point2f& p = moved[i];
        kept[i] = found[i] && returned[i] && cv::norm(back[i] - start[i]) <= options.maxFlowError && p.x >= 0 &&
                  p.y >= 0 && p.x <= b.cols - 1 && p.y <= b.rows - 1;
    }
    return kept;
}

float lengthOf(const cv::Vec4f& s)
{
    return std::hypot(s[2] - s[0], s[3] - s[1]);
}

//! Whether @p candidate's midpoint lies within @p distance px of a followed segment's line and between
//! its ends: the same edge seen again.
bool nearFollowed(const cv::Vec4f& candidate, const std::vector<cv::Vec4f>& followed, double distance)
{
    const cv::Point2f mid(0.5f * (candidate[0] + candidate[2]), 0.5f * (candidate[1] + candidate[3]));
    for (const cv::Vec4f& s : followed)
    {
        const cv::Point2f a(s[0], s[1]), direction(s[2] - s[0], s[3] - s[1]);
        const double length = std::max<double>(cv::norm(direction), 1e-9);
        const cv::Point2f rel = mid - a;
        const double along = (rel.x * direction.x + rel.y * direction.y) / length;
        const double across = std::abs(rel.x * direction.y - rel.y * direction.x) / length;
        if (across <= distance && along >= 0 && along <= length)
            return true;
    }
    return false;
}

cv::Mat rowsOf(const std::vector<cv::Point2f>& points)
{
    cv::Mat m((int)points.size(), 2, CV_64F);
    for (int i = 0; i < m.rows; ++i)
    {
        m.at<double>(i, 0) = points[i].x;
        m.at<double>(i, 1) = points[i].y;
    }
    return m;
}

cv::Mat rowsOf(const std::vector<cv::Vec4f>& segments)
{
    cv::Mat m((int)segments.size(), 4, CV_64F);
    for (int i = 0; i < m.rows; ++i)
        for (int c = 0; c < 4; ++c)
            m.at<double>(i, c) = segments[i][c];
    return m;
}

cv::Mat notFound(int rows, int cols)
{
    return cv::Mat(rows, cols, CV_64F, cv::Scalar::all(std::numeric_limits<double>::quiet_NaN()));
}

std::vector<cv::Point2f> undistorted(const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K, const cv::Mat& dist)
{
    if (dist.empty() || cv::countNonZero(dist) == 0)
        return pixels;
    std::vector<cv::Point2f> out;
    cv::undistortPoints(pixels, out, K, dist, cv::noArray(), K);
    return out;
}

} // namespace

VideoFrontEnd::VideoFrontEnd(const FollowOptions& options) : options_(options)
{
    if (options.maxPoints < 1 || options.minPoints < 0 || options.minPoints > options.maxPoints)
        throw std::runtime_error("video options: expected 0 <= minPoints <= maxPoints, maxPoints >= 1");
    if (options.windowSize < 3 || options.windowSize % 2 == 0 || options.pyramidLevels < 0)
        throw std::runtime_error("video options: expected an odd windowSize >= 3 and pyramidLevels >= 0");
}

VideoFrontEnd::VideoFrontEnd(const FollowOptions& options, const VideoRig& rig) : VideoFrontEnd(options)
{
    stereo_ = true;
    rig_ = rig;
    const cv::Vec3d& t = rig.t;
    const cv::Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
    fundamental_ = rig.K[1].inv().t() * tx * rig.R * rig.K[0].inv();
}

VideoObservations VideoFrontEnd::next(const cv::Mat& left, const cv::Mat& right)
{
    VideoObservations o;
    read_ = !left.empty();
    if (!read_)
    {
        // The features are followed on from the last image read.
        o.points.create(0, 2, CV_64F);
        o.segments.create(0, 4, CV_64F);
        o.rightPoints.create(0, 2, CV_64F);
        o.rightSegments.create(0, 4, CV_64F);
        o.pointIds.create(0, 1, CV_32S);
        o.lineIds.create(0, 1, CV_32S);
        return o;
    }
    const cv::Mat grey = toGrey(left, "left image");
    if (!previous_.empty() && grey.size() != previous_.size())
        throw std::runtime_error(cv::format("image of %dx%d px after frames of %dx%d", grey.cols, grey.rows,
                                            previous_.cols, previous_.rows));
    auto clock = std::chrono::steady_clock::now();
    if (!previous_.empty())
        follow(grey);
    times_.flow += millisecondsSince(clock);
    clock = std::chrono::steady_clock::now();
    o.detected = renew_ || (int)points_.size() < options_.minPoints;
    if (o.detected)
        detect(grey);
    times_.detection += millisecondsSince(clock);
    previous_ = grey;

    o.points = rowsOf(points_);
    o.segments = rowsOf(segments_);
    cv::Mat(pointIds_, true).copyTo(o.pointIds);
    cv::Mat(lineIds_, true).copyTo(o.lineIds);
    if (!stereo_)
        return o;
    clock = std::chrono::steady_clock::now();
    if (right.empty())
    {
        o.rightPoints = notFound(o.points.rows, 2);
        o.rightSegments = notFound(o.segments.rows, 4);
    }
    else
    {
        const cv::Mat rightGrey = toGrey(right, "right image");
        if (rightGrey.size() != grey.size())
            throw std::runtime_error(cv::format("right image of %dx%d px beside a left one of %dx%d", rightGrey.cols,
                                                rightGrey.rows, grey.cols, grey.rows));
        std::vector<cv::Point2f> ends;
        for (const cv::Vec4f& s : segments_)
        {
            ends.emplace_back(s[0], s[1]);
            ends.emplace_back(s[2], s[3]);
        }
        o.rightPoints = inRight(grey, rightGrey, points_);
        o.rightSegments = inRight(grey, rightGrey, ends).reshape(1, (int)segments_.size());
        if (segments_.empty())
            o.rightSegments = cv::Mat(0, 4, CV_64F);
    }
    times_.stereo += millisecondsSince(clock);
    return o;
}

void VideoFrontEnd::keyframeDone(bool keyframe)
{
    if (read_)
        renew_ = keyframe;
}

void VideoFrontEnd::follow(const cv::Mat& grey)
{
    std::vector<cv::Point2f> start = points_;
    for (const cv::Vec4f& s : segments_)
    {
        start.emplace_back(s[0], s[1]);
        start.emplace_back(s[2], s[3]);
    }
    std::vector<cv::Point2f> moved;
    const std::vector<bool> kept = flowThereAndBack(previous_, grey, start, moved, options_);
    std::vector<cv::Point2f> points;
    std::vector<int> pointIds;
    for (size_t i = 0; i < points_.size(); ++i)
        if (kept[i])
        {
            points.push_back(moved[i]);
            pointIds.push_back(pointIds_[i]);
        }
    std::vector<cv::Vec4f> segments;
    std::vector<int> lineIds;
    for (size_t j = 0; j < segments_.size(); ++j)
    {
        const size_t a = points_.size() + 2 * j;
        const cv::Vec4f s(moved[a].x, moved[a].y, moved[a + 1].x, moved[a + 1].y);
        const float before = lengthOf(segments_[j]), after = lengthOf(s);
        if (kept[a] && kept[a + 1] && std::abs(after - before) <= options_.maxLengthChange * before &&
            after >= options_.minSegmentLength)
        {
            segments.push_back(s);
            lineIds.push_back(lineIds_[j]);
        }
    }
    points_.swap(points);
    pointIds_.swap(pointIds);
    segments_.swap(segments);
    lineIds_.swap(lineIds);
}

void VideoFrontEnd::detect(const cv::Mat& grey)
{
    const int wantedPoints = options_.maxPoints - (int)points_.size();
    if (wantedPoints > 0)
    {
        cv::Mat mask(grey.size(), CV_8U, cv::Scalar(255));
        const int radius = (int)std::ceil(options_.minDistance);
        for (const cv::Point2f& p : points_)
            cv::circle(mask, cv::Point(cvRound(p.x), cvRound(p.y)), radius, cv::Scalar(0), cv::FILLED);
        std::vector<cv::Point2f> corners;
        cv::goodFeaturesToTrack(grey, corners, wantedPoints, options_.qualityLevel, options_.minDistance, mask);
        for (const cv::Point2f& c : corners)
        {
            points_.push_back(c);
            pointIds_.push_back(nextId_++);
        }
    }
    const int wantedSegments = options_.maxSegments - (int)segments_.size();
    if (!options_.segments || wantedSegments <= 0)
        return;
    const cv::Ptr<cv::ximgproc::EdgeDrawing> edgeDrawing = cv::ximgproc::createEdgeDrawing();
    edgeDrawing->detectEdges(grey);
    std::vector<cv::Vec4f> found;
    edgeDrawing->detectLines(found);
    std::vector<size_t> order(found.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return lengthOf(found[a]) > lengthOf(found[b]); });
    const std::vector<cv::Vec4f> followed = segments_;
    int added = 0;
    for (size_t i : order)
    {
        if (added == wantedSegments || lengthOf(found[i]) < options_.minSegmentLength)
            break;
        if (nearFollowed(found[i], followed, options_.minDistance))
            continue;
        segments_.push_back(found[i]);
        lineIds_.push_back(nextId_++);
        ++added;
    }
}

cv::Mat VideoFrontEnd::inRight(const cv::Mat& grey, const cv::Mat& right, const std::vector<cv::Point2f>& pixels) const
{
    cv::Mat out = notFound((int)pixels.size(), 2);
    if (pixels.empty())
        return out;
    std::vector<cv::Point2f> moved;
    const std::vector<bool> kept = flowThereAndBack(grey, right, pixels, moved, options_);
    const std::vector<cv::Point2f> l = undistorted(pixels, rig_.K[0], rig_.dist[0]);
    const std::vector<cv::Point2f> r = undistorted(moved, rig_.K[1], rig_.dist[1]);
    for (size_t i = 0; i < pixels.size(); ++i)
    {
        if (!kept[i])
            continue;
        const cv::Vec3d line = fundamental_ * cv::Vec3d(l[i].x, l[i].y, 1);
        const double distance = std::abs(line.dot(cv::Vec3d(r[i].x, r[i].y, 1))) /
                                std::max(std::hypot(line[0], line[1]), 1e-12);
        if (distance > kEpipolarTolerancePx)
            continue;
        out.at<double>((int)i, 0) = moved[i].x;
        out.at<double>((int)i, 1) = moved[i].y;
    }
    return out;
}

} // namespace tripose_samples
