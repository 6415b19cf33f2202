// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_BUNDLE_ADJUSTMENT_HPP
#define TRIPOSE_CORE_TRACKING_BUNDLE_ADJUSTMENT_HPP

#include <vector>

#include "track_store.hpp"
#include "tracker_options.hpp"

namespace tripose {

//! Who linked the observations of the tracks an adjustment refines, which sets how it weighs them.
enum class TrackLinks
{
    //! The tracker's matching: a wrong link may lie within the RANSAC threshold (Cauchy loss at a
    //! quarter of the threshold).
    Matched,
    //! The caller, who checks them as it follows them (Huber loss at the threshold).
    ByCaller
};

/** Refines the poses of frames @p free and the structure of the tracks they see with at least one
other frame of @p free or @p fixed, with @p fixed held, under the loss of @p links. False, poses
unchanged, when fewer than four features qualify or the refinement fails. @p fixed must hold two
frames at distinct centres.
*/
bool adjustFrames(TrackStore& store, const std::vector<int>& free, const std::vector<int>& fixed,
                  const TrackerOptions& options, TrackLinks links);

/** Splits off every observation in frames @p among (a subset of @p frames) of the tracks seen by one
of @p among and at least twice in @p frames whose reprojection error at the structure triangulated
from @p frames (with their current poses) exceeds @p threshold px: a wrong link leaves its track,
which then agrees with the poses again, while the observations in the other frames stay, for they
hold the structure where the poses were before. Returns the number of observations split off.
*/
int splitDisagreeingObservations(TrackStore& store, const std::vector<int>& among, const std::vector<int>& frames,
                                 double threshold);

/** adjustFrames(), then splitDisagreeingObservations() of the observations in frames @p splitIn (of
@p free; none: the adjustment alone), judged over every frame involved, at the RANSAC threshold,
repeated while observations are split, at most @p rounds times: a bundle adjustment that is not
pulled by the wrong links it finds. False when the first adjustment fails. */
bool adjustAndSplitOutliers(TrackStore& store, const std::vector<int>& free, const std::vector<int>& fixed,
                            const std::vector<int>& splitIn, const TrackerOptions& options, TrackLinks links,
                            int rounds);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_BUNDLE_ADJUSTMENT_HPP
