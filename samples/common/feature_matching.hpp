// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Matching the features of two images (image_features.hpp): with the two views' relative pose known
// (epipolar constraint, then descriptors), under a fundamental matrix estimated from descriptor
// matches, or by descriptor alone. Every match is mutual: each
// feature is the other's best candidate, and the best is clearly better than the second (ratio test).
#ifndef TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP
#define TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP

#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "image_features.hpp"

namespace tripose_samples {

//! (row in the first image's features, row in the second's).
using Matches = std::vector<std::pair<int, int>>;

struct MatchOptions
{
    //! A point pair is a candidate when each point lies within this distance (px) of the other's epipolar line.
    double epipolarDistance = 2.0;
    //! A segment pair is a candidate when the second segment covers at least this fraction of the
    //! shorter of itself and the band between the epipolar lines of the first's end points.
    double minBandOverlap = 0.5;
    //! Segments within this angle (deg) of the epipolar lines cross the band at no defined place
    //! (and have no depth from the two views): they are not matched with the pose.
    double minEpipolarAngleDeg = 5.0;
    double pointRatio = 0.8;   //!< SIFT: best L2 distance below this fraction of the second best.
    double lineRatio = 0.8;    //!< LBD: best Hamming distance below this fraction of the second best.
    int maxLineDistance = 80;  //!< LBD: Hamming distance (of 256 bits) above which segments never match.
    //! Views of unknown relative pose are matched under a fundamental matrix estimated from their
    //! descriptor matches (estimateFundamental), with at least this many matches consistent with it.
    int minFundamentalInliers = 30;
};

//! @p options with its pixel tolerance multiplied by @p pixelScale (detectionScale(): features detected
//! in reduced images are placed that much less precisely in the images' pixels).
MatchOptions withPixelScale(MatchOptions options, double pixelScale);

/** Points of views a and b under the known epipolar geometry @p F (x_b^T F x_a = 0): candidates within
MatchOptions::epipolarDistance of the epipolar lines both ways, then mutual best SIFT descriptor
with the ratio test among the candidates. */
Matches matchPointsEpipolar(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                            const MatchOptions& options);

/** Segments of views a and b under @p F: candidates overlap the band between the epipolar lines of
the other's end points (MatchOptions::minBandOverlap) and run the same way along it (segments are
oriented by their edge's polarity), then mutual best LBD descriptor with the ratio test among the
candidates. */
Matches matchSegmentsEpipolar(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                              const MatchOptions& options);

/** The fundamental matrix of views a and b (x_b^T F x_a = 0) where their relative pose is unknown: the
points matched by descriptor (matchByDescriptor), then cv::findFundamentalMat (RANSAC at
MatchOptions::epipolarDistance, confidence 0.999) on them. False, and @p F untouched, with fewer than
MatchOptions::minFundamentalInliers consistent matches: too few to trust the geometry. */
bool estimateFundamental(const ImageFeatures& a, const ImageFeatures& b, const MatchOptions& options, cv::Matx33d& F);

/** Points and segments of views a and b matched where their relative pose is unknown: under the
fundamental matrix of their descriptor matches (estimateFundamental(), then matchPointsEpipolar()
and matchSegmentsEpipolar()), which rejects descriptor matches that no rigid motion explains; by
descriptor alone (matchByDescriptor()) without enough matches for that geometry. Returns true when
the matches are under the fundamental matrix, false when by descriptor alone. */
bool matchUnknownPose(const ImageFeatures& a, const ImageFeatures& b, const MatchOptions& options, Matches& points,
                      Matches& segments);

/** How far the points of views a and b agree with a known epipolar geometry @p F, judged without it:
points of a (an evenly spread subset of at most kAgreementSample) matched by descriptor alone
(matchByDescriptor()), and how many of those matches lie within MatchOptions::epipolarDistance of
their epipolar lines both ways. On the VGG pairs with their own cameras 73-88 % of them do; with the
pose of view 2 inverted, the images swapped or one image twice, 0-11 % (measured with the Python
sample's same steps: test/evaluation/calibration_agreement.py). */
struct EpipolarAgreement
{
    int matches = 0;  //!< descriptor matches of the subset
    int agreeing = 0; //!< of them, within the epipolar distance both ways
    double fraction() const { return matches > 0 ? double(agreeing) / matches : 0.0; }
    //! Too few matches agree for the geometry to be the images': under 30 % of 20 matches or more.
    bool contradicts() const { return matches >= 20 && fraction() < 0.3; }
    //! "of N point matches found without the poses, k (p %) lie on their epipolar lines (73-88 % ...)",
    //! for the samples' warnings.
    std::string summary() const;
};
constexpr int kAgreementSample = 300;
EpipolarAgreement epipolarAgreement(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                                    const MatchOptions& options);

/** Rows of @p descriptorsA and @p descriptorsB (CV_32F: L2, CV_8U: Hamming), mutual best with the
ratio test @p ratio over all rows of B, and (Hamming) at most @p maxDistance. */
Matches matchByDescriptor(const cv::Mat& descriptorsA, const cv::Mat& descriptorsB, double ratio,
                          double maxDistance);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_FEATURE_MATCHING_HPP
