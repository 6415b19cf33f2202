// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Three-view correspondences from the features of three images: views 1 and 2 matched under their
// known relative pose, view 3 matched to those pairs under the fundamental matrix of its descriptor
// matches with view 2 (by descriptor alone without one). The result is what the
// module's three-view estimators take (points1..3, lines1..3).
#ifndef TRIPOSE_SAMPLES_FEATURE_TRIPLETS_HPP
#define TRIPOSE_SAMPLES_FEATURE_TRIPLETS_HPP

#include <opencv2/core.hpp>

#include "feature_matching.hpp"
#include "image_features.hpp"

namespace tripose_samples {

struct FeatureTriplets
{
    cv::Mat points[3]; //!< Nx2 CV_64F point tracks, one row per track in every view.
    cv::Mat lines[3];  //!< Mx4 CV_64F segment triplets.
    int pointPairs = 0, segmentPairs = 0; //!< Matches of views 1-2, before view 3.
};

/** Matches three views: views 1-2 under their relative pose (R12, t12; view 1 at the origin),
then view 3 to those pairs' features in view 2 (the view a sequence saw last) under the fundamental
matrix estimated from their descriptor matches (estimateFundamental), by descriptor alone when
there are too few. Adds the
matching time to @p times. @p pairAgreement, when given, receives how far the points of views 1-2
agree with R12, t12 (epipolarAgreement()), for the caller to warn of a calibration that contradicts
the images.
*/
FeatureTriplets matchTriplets(const ImageFeatures views[3], const cv::Matx33d K[3], const cv::Matx33d& R12,
                              const cv::Vec3d& t12, const MatchOptions& options, StageTimes& times,
                              EpipolarAgreement* pairAgreement = nullptr);

//! The rows @p pairs.second (or .first, with @p first) of @p rows, in the order of @p pairs.
cv::Mat matchedRows(const cv::Mat& rows, const Matches& pairs, bool first);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_FEATURE_TRIPLETS_HPP
