// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_WINDOW_REGISTRATION_HPP
#define TRIPOSE_CORE_TRACKING_WINDOW_REGISTRATION_HPP

#include <string>
#include <vector>

#include "../refine/ml_refinement.hpp"
#include "track_store.hpp"
#include "tracker_options.hpp"

namespace tripose {

//! The registration of one frame against a window of posed frames.
struct Registration
{
    bool registered = false;
    CameraPose pose;
    int features = 0, inliers = 0;
    bool keyframe = false;
    std::string reason; //!< Why it was not registered.
    //! With TrackerOptions::covariance: the pose's uncertainty (valid false when not determined).
    PoseCovariance covariance;
    //! Tracks whose observation in the frame the estimate rejected (robust estimation only).
    std::vector<int> rejectedPoints, rejectedLines;
};

/** Registers frame @p frame of @p store against the frames @p window (which have poses) with the
multi-view estimator, on the tracks the frame sees with at least two window frames. With
TrackerOptions::checkTracks, the window's observations that disagree with its poses are dropped
first (feature by feature, the furthest while it exceeds the RANSAC threshold). Registered only with
TrackerOptions::minInliers inliers; then a keyframe when its inlier structure, triangulated from
the window, subtends TrackerOptions::keyframeParallaxDeg between it and the window's last frame.
*/
Registration registerAgainstWindow(const TrackStore& store, int frame, const std::vector<int>& window,
                                   const TrackerOptions& options);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_WINDOW_REGISTRATION_HPP
