// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "image_features.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/line_descriptor.hpp>

namespace tripose_samples {

namespace {

/** OpenCV's SIFT finds its finest key points in the image doubled by bilinear resize, whose pixel
centres sit at (x + 0.5) / 2 - 0.5 of the original, and halves their coordinates: every position
comes out 0.25 px right of and below the feature (enable_precise_upscale, OpenCV 4.8 on, avoids it
but is off by default and absent from Debian's 4.6). Key points found in an image and in its mirror
image show it: +0.25 px on both axes on Model House and Merton College I (doc/real_images.md). */
const double kSiftUpsamplingOffset = 0.25;

/** LSD detects on the image scaled by 0.8 (cv::resize: pixel centres at (x + 0.5) / 0.8 - 0.5 of the
original) and divides its coordinates by 0.8 alone: every end point comes out 0.5 / 0.8 - 0.5 =
0.125 px left of and above the edge. An edge rendered at a known sub-pixel position shows it (-0.125
px on average over positions, slopes and polarities), and so do segments found in an image and in
its mirror image (-0.11 to -0.13 px, doc/real_images.md). */
const double kLsdDownsamplingOffset = 0.125;

double millisecondsSince(int64 start)
{
    return 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
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
    cv::Mat grey = image;
    if (image.channels() != 1)
        cv::cvtColor(image, grey, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);

    ImageFeatures out;
    out.points = cv::Mat(0, 2, CV_64F);
    out.segments = cv::Mat(0, 4, CV_64F);
    if (options.kinds & FEATURES_POINTS)
    {
        const cv::Ptr<cv::SIFT> sift = cv::SIFT::create(options.maxPoints);
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
        out.points = undistorted(positions, K, distCoeffs);
    }
    if (options.kinds & FEATURES_LINES)
    {
        using namespace cv::line_descriptor;
        std::vector<KeyLine> keylines;
        int64 start = cv::getTickCount();
        // One octave: LBD is computed at the scale the segment was found, and a single scale keeps the
        // end points at full resolution.
        LSDDetector::createLSDDetector()->detect(grey, keylines, 2, 1);
        std::vector<KeyLine> kept;
        for (const KeyLine& k : keylines)
            if (k.lineLength >= options.minSegmentLength)
            {
                kept.push_back(k);
                kept.back().class_id = (int)kept.size() - 1;
            }
        times.segmentDetection += millisecondsSince(start);
        start = cv::getTickCount();
        if (!kept.empty())
            BinaryDescriptor::createBinaryDescriptor()->compute(grey, kept, out.lineDescriptors);
        times.segmentDescription += millisecondsSince(start);
        // LBD keeps one descriptor per segment, in order: the rows below pair with them.
        CV_Assert(out.lineDescriptors.rows == (int)kept.size());
        if (!kept.empty())
        {
            cv::Mat ends((int)kept.size() * 2, 2, CV_64F);
            for (size_t i = 0; i < kept.size(); ++i)
            {
                ends.at<double>(2 * (int)i, 0) = kept[i].startPointX + kLsdDownsamplingOffset;
                ends.at<double>(2 * (int)i, 1) = kept[i].startPointY + kLsdDownsamplingOffset;
                ends.at<double>(2 * (int)i + 1, 0) = kept[i].endPointX + kLsdDownsamplingOffset;
                ends.at<double>(2 * (int)i + 1, 1) = kept[i].endPointY + kLsdDownsamplingOffset;
            }
            out.segments = undistorted(ends, K, distCoeffs).reshape(1, (int)kept.size()).clone();
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
    // One task per image and kind: SIFT costs about three times LSD + LBD, so three images' six tasks
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
