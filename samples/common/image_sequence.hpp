// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A sequence's observations (sequence_tracking.hpp) built from its images instead of given
// correspondences: frames 0 and 1 matched under their given poses, every later frame to the one
// before it (or, past a frame that matches it too poorly, to an earlier one) under the fundamental
// matrix of their descriptor matches, the matches chained into tracks.
#ifndef TRIPOSE_SAMPLES_IMAGE_SEQUENCE_HPP
#define TRIPOSE_SAMPLES_IMAGE_SEQUENCE_HPP

#include <vector>

#include <opencv2/core.hpp>

#include "feature_matching.hpp"
#include "image_features.hpp"
#include "sequence_tracking.hpp"

namespace tripose_samples {

/** Point and segment tracks of @p images (in order; K per frame in @p cameraMatrices, no distortion)
with the given poses of frames 0 and 1 (R0, t0, R1, t1). Frames 0-1 are matched under their
relative pose, frame k > 1 to frame k - 1 under the fundamental matrix estimated from their
descriptor matches. Where frames k - 1 and k share too few matches for that matrix, frame k is
matched to the nearest of frames k - 2 and k - 3 that shares enough, and only without one to frame
k - 1 by descriptor alone (mutual best and ratio test). A match extends the track of its feature in
the frame it was matched to, or starts one. A track has a row in every frame,
NaN where the frame does not see it. Adds the time per stage to @p times. @p givenPairAgreement, when
given, receives how far the points of frames 0-1 agree with their given poses (epipolarAgreement()),
for the caller to warn of images out of the cameras' order.
*/
SequenceObservations observationsFromImages(const std::vector<cv::Mat>& images,
                                            const std::vector<cv::Mat>& cameraMatrices, const cv::Mat& R0,
                                            const cv::Mat& t0, const cv::Mat& R1, const cv::Mat& t1,
                                            const FeatureOptions& featureOptions, const MatchOptions& matchOptions,
                                            StageTimes& times, EpipolarAgreement* givenPairAgreement = nullptr);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_IMAGE_SEQUENCE_HPP
