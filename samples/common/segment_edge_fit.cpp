// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "segment_edge_fit.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace tripose_samples {

namespace {

//! Rows (columns) this close to an end point are left out: the edge bends into the next one there.
const double kEndMargin = 2.0;
//! Pixels searched on each side of the segment for the gradient's peak.
const int kSearchRadius = 2;
//! A peak further from the detected segment belongs to another edge.
const double kMaxPeakDistance = 1.0;
const int kMinPeaks = 5;

struct EdgePeak
{
    cv::Point2d position;
    bool positive; //!< The gradient across the segment points along its normal (-u.y, u.x).
};

//! The gradient's peaks across the segment from p0 along unit u (normal n), one per crossed row or column.
std::vector<EdgePeak> edgePeaks(const cv::Mat& gx, const cv::Mat& gy, const cv::Point2d& p0, const cv::Point2d& p1,
                                const cv::Point2d& u, const cv::Point2d& n)
{
    // Walk the axis the segment runs along most, search along the other.
    const bool walkRows = std::abs(n.x) >= std::abs(n.y);
    const double a0 = walkRows ? p0.y : p0.x, a1 = walkRows ? p1.y : p1.x;
    const double ua = walkRows ? u.y : u.x, ub = walkRows ? u.x : u.y;
    const double b0 = walkRows ? p0.x : p0.y;
    const int walkSize = walkRows ? gx.rows : gx.cols, searchSize = walkRows ? gx.cols : gx.rows;
    const double margin = kEndMargin * std::abs(ua);
    const int first = (int)std::ceil(std::min(a0, a1) + margin), last = (int)std::floor(std::max(a0, a1) - margin);
    std::vector<EdgePeak> peaks;
    for (int r = std::max(first, 0); r <= std::min(last, walkSize - 1); ++r)
    {
        const double across = b0 + (r - a0) / ua * ub;
        const int k0 = (int)std::lround(across);
        if (k0 - kSearchRadius - 1 < 0 || k0 + kSearchRadius + 1 >= searchSize)
            continue;
        double g[2 * kSearchRadius + 3];
        for (int j = 0; j < 2 * kSearchRadius + 3; ++j)
        {
            const int k = k0 - kSearchRadius - 1 + j;
            const int row = walkRows ? r : k, col = walkRows ? k : r;
            g[j] = gx.at<float>(row, col) * n.x + gy.at<float>(row, col) * n.y;
        }
        int best = 1;
        for (int j = 2; j <= 2 * kSearchRadius + 1; ++j)
            if (std::abs(g[j]) > std::abs(g[best]))
                best = j;
        const double left = std::abs(g[best - 1]), centre = std::abs(g[best]), right = std::abs(g[best + 1]);
        const double curvature = left - 2 * centre + right;
        if (!(curvature < 0))
            continue;
        const double at = k0 - kSearchRadius - 1 + best + 0.5 * (left - right) / curvature;
        if (std::abs(at - across) * std::abs(walkRows ? n.x : n.y) > kMaxPeakDistance)
            continue;
        const cv::Point2d position = walkRows ? cv::Point2d(at, r) : cv::Point2d(r, at);
        peaks.push_back({ position, g[best] > 0 });
    }
    return peaks;
}

} // namespace

std::vector<cv::Vec4f> fitSegmentsToEdges(const cv::Mat& image, const std::vector<cv::Vec4f>& segments)
{
    CV_Assert(image.type() == CV_8UC1);
    cv::Mat smooth, gx, gy;
    image.convertTo(smooth, CV_32F);
    cv::GaussianBlur(smooth, smooth, cv::Size(0, 0), 1.0);
    cv::Sobel(smooth, gx, CV_32F, 1, 0, 3);
    cv::Sobel(smooth, gy, CV_32F, 0, 1, 3);

    std::vector<cv::Vec4f> fitted;
    fitted.reserve(segments.size());
    for (const cv::Vec4f& s : segments)
    {
        cv::Point2d p0(s[0], s[1]), p1(s[2], s[3]);
        const double length = cv::norm(p1 - p0);
        if (!(length > 0))
            continue;
        const cv::Point2d u = (p1 - p0) / length, n(-u.y, u.x);
        const std::vector<EdgePeak> peaks = edgePeaks(gx, gy, p0, p1, u, n);
        int positive = 0;
        for (const EdgePeak& p : peaks)
            positive += p.positive;
        const bool brighterOnRight = 2 * positive >= (int)peaks.size();
        // The peaks of the dominant polarity: a peak of the other belongs to a neighbouring edge.
        std::vector<cv::Point2d> onEdge;
        for (const EdgePeak& p : peaks)
            if (p.positive == brighterOnRight)
                onEdge.push_back(p.position);
        if ((int)onEdge.size() >= kMinPeaks)
        {
            cv::Point2d mean(0, 0);
            for (const cv::Point2d& p : onEdge)
                mean += p;
            mean *= 1.0 / onEdge.size();
            double sxx = 0, sxy = 0, syy = 0;
            for (const cv::Point2d& p : onEdge)
            {
                const cv::Point2d d = p - mean;
                sxx += d.x * d.x;
                sxy += d.x * d.y;
                syy += d.y * d.y;
            }
            // The principal direction of the peaks' scatter.
            const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
            cv::Point2d direction(std::cos(angle), std::sin(angle));
            if (direction.dot(u) < 0)
                direction = -direction;
            p0 = mean + (p0 - mean).dot(direction) * direction;
            p1 = mean + (p1 - mean).dot(direction) * direction;
        }
        if (!brighterOnRight)
            std::swap(p0, p1);
        fitted.emplace_back((float)p0.x, (float)p0.y, (float)p1.x, (float)p1.y);
    }
    return fitted;
}

} // namespace tripose_samples
