// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_FRAME_MATCHING_HPP
#define TRIPOSE_CORE_TRACKING_FRAME_MATCHING_HPP

#include <Eigen/Core>

#include "epipolar_matching.hpp"

namespace tripose {

/** The fundamental matrix of frames a and b (xb^T F xa = 0) where their relative pose is unknown:
their points matched by descriptor, then estimateFundamentalRansac() at
MatchOptions::epipolarDistance. False, @p F untouched, with fewer than
MatchOptions::minFundamentalInliers matches that agree with it: too few to trust the geometry. */
bool estimateFundamental(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options,
                         Eigen::Matrix3d& F);

/** Points and segments of frames a and b matched under the fundamental matrix of their descriptor
matches (estimateFundamental()). False, and no match, without enough matches for that geometry: for
callers that try another frame then, and need not pay for matching by descriptor alone. */
bool matchUnderFundamental(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options,
                           Matches& points, Matches& segments);

/** Points and segments of frames a and b where their relative pose is unknown: under the fundamental
matrix of their descriptor matches (estimateFundamental()), which rejects matches that no rigid
motion explains, or by descriptor alone without enough matches for that geometry. Returns true when
matched under the fundamental matrix. */
bool matchUnknownPose(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options, Matches& points,
                      Matches& segments);

/** How far the points of frames a and b agree with a known epipolar geometry @p F, judged without
it: points of a (an evenly spread subset of at most kAgreementSample) matched by descriptor alone,
and how many of those matches lie within MatchOptions::epipolarDistance of their epipolar lines. */
struct EpipolarAgreement
{
    int matches = 0;  //!< Descriptor matches of the subset.
    int agreeing = 0; //!< Of them, within the epipolar distance both ways.
    double fraction() const { return matches > 0 ? double(agreeing) / matches : 0.0; }
    //! Too few matches agree for the geometry to be the images': under 30 % of 20 matches or more
    //! (doc/studies/real_images.md measures both sides of that line).
    bool contradicts() const { return matches >= 20 && fraction() < 0.3; }
};
constexpr int kAgreementSample = 300;
EpipolarAgreement epipolarAgreement(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                                    const MatchOptions& options);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_FRAME_MATCHING_HPP
