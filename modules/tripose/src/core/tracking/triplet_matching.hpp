// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_TRIPLET_MATCHING_HPP
#define TRIPOSE_CORE_TRACKING_TRIPLET_MATCHING_HPP

#include <vector>

#include "frame_matching.hpp"

namespace tripose {

//! Features seen in all three views: per view, the rows of that view's features, one per triplet.
struct FeatureTriplets
{
    std::vector<int> pointRows[3], segmentRows[3];
    int pointPairs = 0, segmentPairs = 0; //!< Matches of views 1-2, before view 3.
    EpipolarAgreement pairAgreement;      //!< Of views 1-2 with their given relative pose.
};

/** Matches three views: views 1-2 under their relative pose @p pose12 (view 1 at the origin), then
view 3 to those pairs' features in view 2 (the view a sequence saw last) under the fundamental
matrix of their descriptor matches, by descriptor alone without enough of them. */
FeatureTriplets matchTriplets(const FrameFeatures views[3], const Eigen::Matrix3d K[3], const CameraPose& pose12,
                              const MatchOptions& options);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_TRIPLET_MATCHING_HPP
