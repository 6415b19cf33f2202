// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "image_features.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/line_descriptor.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>

#include "segment_edge_fit.hpp"

namespace tripose_samples {

namespace {

/** OpenCV's SIFT finds its finest key points in the image doubled by bilinear resize, whose pixel
centres sit at (x + 0.5) / 2 - 0.5 of the original, and halves their coordinates: every position
comes out 0.25 px right of and below the feature (enable_precise_upscale, OpenCV 4.8 on, avoids it
but is off by default and absent from Debian's 4.6); key points found in an image and in its mirror
image show the offset (doc/studies/real_images.md). */
const double kSiftUpsamplingOffset = 0.25;

//! Segments (x0, y0, x1, y1) as contrib's key lines of one octave, the image's own, for LBD.
std::vector<cv::line_descriptor::KeyLine> fullResolutionKeyLines(const std::vector<cv::Vec4f>& segments,
                                                                 const cv::Size& imageSize)
{
    std::vector<cv::line_descriptor::KeyLine> keylines(segments.size());
    for (size_t i = 0; i < segments.size(); ++i)
    {
        const cv::Vec4f& s = segments[i];
        cv::line_descriptor::KeyLine& k = keylines[i];
        k.startPointX = k.sPointInOctaveX = s[0];
        k.startPointY = k.sPointInOctaveY = s[1];
        k.endPointX = k.ePointInOctaveX = s[2];
        k.endPointY = k.ePointInOctaveY = s[3];
        k.lineLength = (float)std::hypot(s[2] - s[0], s[3] - s[1]);
        k.numOfPixels = (int)std::lround(k.lineLength);
        k.angle = (float)std::atan2(s[3] - s[1], s[2] - s[0]);
        k.pt = cv::Point2f((s[0] + s[2]) / 2, (s[1] + s[3]) / 2);
        k.octave = 0;
        k.class_id = (int)i;
        k.response = k.lineLength / (float)std::max(imageSize.width, imageSize.height);
        k.size = std::abs((s[2] - s[0]) * (s[3] - s[1]));
    }
    return keylines;
}

double millisecondsSince(int64 start)
{
    return 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
}

/** The image features are detected in: @p grey itself, or reduced to @p maxImageSize on its longer
side. @p factor: the image's pixels per pixel of the result, along x and y. */
cv::Mat detectionImage(const cv::Mat& grey, int maxImageSize, cv::Vec2d& factor)
{
    const double scale = detectionScale(grey.size(), maxImageSize);
    factor = cv::Vec2d(1, 1);
    if (scale == 1.0)
        return grey;
    const cv::Size size(std::max(1, (int)std::lround(grey.cols / scale)), std::max(1, (int)std::lround(grey.rows / scale)));
    cv::Mat reduced;
    cv::resize(grey, reduced, size, 0, 0, cv::INTER_AREA);
    factor = cv::Vec2d(double(grey.cols) / size.width, double(grey.rows) / size.height);
    return reduced;
}

//! Positions (Nx2 CV_64F) of the detection image in the image's pixels: resize maps pixel centres
//! onto pixel centres, x = (x' + 0.5) * factor - 0.5.
void toImagePixels(cv::Mat& positions, const cv::Vec2d& factor)
{
    if (factor == cv::Vec2d(1, 1))
        return;
    for (int i = 0; i < positions.rows; ++i)
        for (int c = 0; c < 2; ++c)
            positions.at<double>(i, c) = (positions.at<double>(i, c) + 0.5) * factor[c] - 0.5;
}

//! Positions (Nx2 CV_64F) moved to the ideal pinhole image of K.
cv::Mat undistorted(const cv::Mat& positions, const cv::Matx33d& K, const cv::Mat& distCoeffs)
{
    if (distCoeffs.empty() || positions.rows == 0)
        return positions;
    cv::Mat moved;
    cv::undistortPoints(positions.reshape(2), moved, cv::Mat(K), distCoeffs, cv::noArray(), cv::Mat(K));
    return moved.reshape(1, positions.rows);
}

} // namespace

FeatureOptions trackingFeatureOptions()
{
    FeatureOptions options;
    options.contrastThreshold = 0.01;
    options.maxPoints = 8192;
    return options;
}

double detectionScale(const cv::Size& imageSize, int maxImageSize)
{
    const int longer = std::max(imageSize.width, imageSize.height);
    return maxImageSize > 0 && longer > maxImageSize ? double(longer) / maxImageSize : 1.0;
}

double detectionScale(const std::vector<cv::Mat>& images, int maxImageSize)
{
    double scale = 1.0;
    for (const cv::Mat& image : images)
        scale = std::max(scale, detectionScale(image.size(), maxImageSize));
    return scale;
}

std::string reductionNote(double pixelScale, int maxImageSize)
{
    return pixelScale > 1 ? cv::format("features detected in the images reduced by %.2f (--max-image-size %d)",
                                       pixelScale, maxImageSize)
                          : std::string();
}

bool parseFeatureKinds(const std::string& word, FeatureKinds& kinds)
{
    if (word == "points")
        kinds = FEATURES_POINTS;
    else if (word == "lines")
        kinds = FEATURES_LINES;
    else if (word == "all")
        kinds = FEATURES_ALL;
    else
        return false;
    return true;
}

StageTimes& StageTimes::operator+=(const StageTimes& other)
{
    points += other.points;
    segmentDetection += other.segmentDetection;
    segmentDescription += other.segmentDescription;
    matching += other.matching;
    estimation += other.estimation;
    featuresWall += other.featuresWall;
    return *this;
}

ImageFeatures extractFeatures(const cv::Mat& image, const cv::Matx33d& K, const cv::Mat& distCoeffs,
                              const FeatureOptions& options, StageTimes& times)
{
    CV_Assert(image.depth() == CV_8U && !image.empty());
    cv::Mat full = image;
    if (image.channels() != 1)
        cv::cvtColor(image, full, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
    cv::Vec2d factor;
    const cv::Mat grey = detectionImage(full, options.maxImageSize, factor);

    ImageFeatures out;
    out.points = cv::Mat(0, 2, CV_64F);
    out.segments = cv::Mat(0, 4, CV_64F);
    if (options.kinds & FEATURES_POINTS)
    {
        const cv::Ptr<cv::SIFT> sift = cv::SIFT::create(options.maxPoints, 3, options.contrastThreshold);
        std::vector<cv::KeyPoint> keypoints;
        const int64 start = cv::getTickCount();
        sift->detectAndCompute(grey, cv::noArray(), keypoints, out.pointDescriptors);
        times.points += millisecondsSince(start);
        cv::Mat positions((int)keypoints.size(), 2, CV_64F);
        for (size_t i = 0; i < keypoints.size(); ++i)
        {
            positions.at<double>((int)i, 0) = keypoints[i].pt.x - kSiftUpsamplingOffset;
            positions.at<double>((int)i, 1) = keypoints[i].pt.y - kSiftUpsamplingOffset;
        }
        toImagePixels(positions, factor);
        out.points = undistorted(positions, K, distCoeffs);
    }
    if (options.kinds & FEATURES_LINES)
    {
        using namespace cv::line_descriptor;
        int64 start = cv::getTickCount();
        const cv::Ptr<cv::ximgproc::EdgeDrawing> edgeDrawing = cv::ximgproc::createEdgeDrawing();
        edgeDrawing->detectEdges(grey);
        std::vector<cv::Vec4f> detected, longEnough;
        edgeDrawing->detectLines(detected);
        for (const cv::Vec4f& s : detected)
            if (std::hypot(s[2] - s[0], s[3] - s[1]) >= options.minSegmentLength)
                longEnough.push_back(s);
        const std::vector<cv::Vec4f> segments = fitSegmentsToEdges(grey, longEnough);
        times.segmentDetection += millisecondsSince(start);
        start = cv::getTickCount();
        std::vector<KeyLine> keylines = fullResolutionKeyLines(segments, grey.size());
        if (!keylines.empty())
            BinaryDescriptor::createBinaryDescriptor()->compute(grey, keylines, out.lineDescriptors);
        times.segmentDescription += millisecondsSince(start);
        // LBD keeps one descriptor per segment, in order: the rows below pair with them.
        CV_Assert(out.lineDescriptors.rows == (int)keylines.size());
        if (!keylines.empty())
        {
            cv::Mat ends((int)segments.size() * 2, 2, CV_64F);
            for (size_t i = 0; i < segments.size(); ++i)
                for (int c = 0; c < 4; ++c)
                    ends.at<double>(2 * (int)i + c / 2, c % 2) = segments[i][c];
            toImagePixels(ends, factor);
            out.segments = undistorted(ends, K, distCoeffs).reshape(1, (int)segments.size()).clone();
        }
    }
    return out;
}

std::vector<ImageFeatures> extractFeaturesOfImages(const std::vector<cv::Mat>& images,
                                                   const std::vector<cv::Matx33d>& K,
                                                   const std::vector<cv::Mat>& distCoeffs,
                                                   const FeatureOptions& options, StageTimes& times)
{
    const int n = (int)images.size();
    CV_Assert((int)K.size() == n && (distCoeffs.empty() || (int)distCoeffs.size() == n));
    // One task per image and kind: SIFT costs several times the segments, so three images' six tasks
    // share two cores more evenly than three whole images would (two images on one core).
    const FeatureKinds kinds[2] = { FEATURES_POINTS, FEATURES_LINES };
    std::vector<ImageFeatures> parts(2 * n);
    std::vector<StageTimes> perTask(2 * n);
    const int64 start = cv::getTickCount();
    cv::parallel_for_(cv::Range(0, 2 * n), [&](const cv::Range& range) {
        for (int task = range.start; task < range.end; ++task)
        {
            FeatureOptions part = options;
            part.kinds = kinds[task % 2];
            if (options.kinds & part.kinds)
                parts[task] = extractFeatures(images[task / 2], K[task / 2],
                                              distCoeffs.empty() ? cv::Mat() : distCoeffs[task / 2], part,
                                              perTask[task]);
        }
    }, 2 * n);
    std::vector<ImageFeatures> features(n);
    for (int k = 0; k < n; ++k)
    {
        const ImageFeatures& points = parts[2 * k];
        const ImageFeatures& lines = parts[2 * k + 1];
        features[k].points = points.points.empty() ? cv::Mat(0, 2, CV_64F) : points.points;
        features[k].pointDescriptors = points.pointDescriptors;
        features[k].segments = lines.segments.empty() ? cv::Mat(0, 4, CV_64F) : lines.segments;
        features[k].lineDescriptors = lines.lineDescriptors;
    }
    // The tasks overlap: the wall time of the features is the whole call's, not their sum.
    for (const StageTimes& t : perTask)
        times += t;
    times.featuresWall += millisecondsSince(start);
    return features;
}

} // namespace tripose_samples
