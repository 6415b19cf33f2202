// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Points and line segments of one image, detected and described for matching: SIFT key points
// (features2d) and EDLines segments (contrib ximgproc) fitted to their edges, with LBD descriptors
// (contrib line_descriptor).
#ifndef TRIPOSE_SAMPLES_IMAGE_FEATURES_HPP
#define TRIPOSE_SAMPLES_IMAGE_FEATURES_HPP

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/tripose/features.hpp>

namespace tripose_samples {

//! Which kinds of feature an image front end extracts.
enum FeatureKinds
{
    FEATURES_POINTS = 1,
    FEATURES_LINES = 2,
    FEATURES_ALL = FEATURES_POINTS | FEATURES_LINES,
};

//! "points", "lines" or "all" as FeatureKinds; false for any other word.
bool parseFeatureKinds(const std::string& word, FeatureKinds& kinds);

/** The features of one image as the library takes them: here Nx2 CV_64F SIFT key point positions
with NxD CV_32F descriptors, Mx4 CV_64F segments with Mx32 CV_8U LBD descriptors. Coordinates are
those of an ideal pinhole camera with the image's K: undistorted when distortion coefficients were
given. */
using ImageFeatures = cv::tripose::ImageFeatures;

//! Milliseconds spent per stage (summed over the images of a run).
struct StageTimes
{
    //! SIFT detects and describes in one pass over one scale space, cheaper than two passes, so
    //! points have one figure.
    double points = 0;
    double segmentDetection = 0, segmentDescription = 0; //!< EDLines and the fit to the edges, LBD.
    double matching = 0, estimation = 0;
    //! Wall-clock time of the feature stages: below their sum when images are processed in parallel.
    double featuresWall = 0;
    //! The stages' sum: the work, as if one image after the other on one core.
    double total() const { return points + segmentDetection + segmentDescription + matching + estimation; }
    //! What a caller waits for.
    double wallTotal() const { return featuresWall + matching + estimation; }
    StageTimes& operator+=(const StageTimes& other);
};

struct FeatureOptions
{
    FeatureKinds kinds = FEATURES_ALL;
    int maxPoints = 4000;            //!< The strongest SIFT key points kept (0: all).
    //! SIFT's contrast threshold: lower finds more, fainter points, which hold a trajectory better
    //! where texture is scarce, at more time per frame.
    double contrastThreshold = 0.04;
    double minSegmentLength = 20;    //!< Shorter segments are dropped (px of the detection image): they are too short to give a direction.
    /** Images whose longer side exceeds this (px) are detected in a copy reduced to it (area
    averaging), and the features' positions mapped back to the image's pixels; 0: always the full
    image. SIFT's scale space grows with the image, and that of a camera's full-size photograph takes
    gigabytes and tens of seconds (doc/studies/real_images.md). Pixel tolerances downstream scale
    with detectionScale(). */
    int maxImageSize = 1600;
};

/** The features a tracker is fed: the FeatureOptions defaults with more and fainter SIFT points
(contrast threshold 0.01, the strongest 8192 kept): a sequence's error accumulates from frame to
frame, and more points hold it (doc/studies/front_end_and_tracker.md, "Against COLMAP"). */
FeatureOptions trackingFeatureOptions();

/** How many pixels of an image of @p imageSize one pixel of its detection image spans
(FeatureOptions::maxImageSize): 1 when the image is not reduced. The features' positions are that
much less precise in the image's pixels, so their tolerances (matching, RANSAC) grow by it. */
double detectionScale(const cv::Size& imageSize, int maxImageSize);

//! The largest detectionScale() of @p images.
double detectionScale(const std::vector<cv::Mat>& images, int maxImageSize);

//! "features detected in the images reduced by <pixelScale> (--max-image-size <maxImageSize>)" for
//! the samples' messages; empty when @p pixelScale is 1 (nothing reduced).
std::string reductionNote(double pixelScale, int maxImageSize);

/** Detects and describes the features of a grey or colour 8-bit image (converted to grey), reduced to
FeatureOptions::maxImageSize when it is larger; positions are in the image's own pixels. With
non-empty @p distCoeffs, positions are undistorted with @p K (cv::undistortPoints, new camera K).
Adds the time of each stage to @p times.
*/
ImageFeatures extractFeatures(const cv::Mat& image, const cv::Matx33d& K, const cv::Mat& distCoeffs,
                              const FeatureOptions& options, StageTimes& times);

/** extractFeatures on every image, in parallel (cv::parallel_for_, one task per image and kind of
feature: on few cores this keeps each core busy through the whole detection, which OpenCV
parallelises only in parts). @p distCoeffs is empty (no distortion) or has one entry per image. Adds the stage times of
all images and the wall-clock time to @p times.
*/
std::vector<ImageFeatures> extractFeaturesOfImages(const std::vector<cv::Mat>& images,
                                                   const std::vector<cv::Matx33d>& K,
                                                   const std::vector<cv::Mat>& distCoeffs,
                                                   const FeatureOptions& options, StageTimes& times);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_IMAGE_FEATURES_HPP
