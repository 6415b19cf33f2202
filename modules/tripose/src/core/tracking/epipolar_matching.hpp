// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_EPIPOLAR_MATCHING_HPP
#define TRIPOSE_CORE_TRACKING_EPIPOLAR_MATCHING_HPP

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "descriptor_matching.hpp"
#include "frame_features.hpp"

namespace tripose {

//! How the features of two frames are matched. Every match is mutual best with a ratio test.
struct MatchOptions
{
    //! A point pair is a candidate when each point lies within this distance (px) of the other's
    //! epipolar line; also the inlier distance of the fundamental matrix estimated from descriptors.
    double epipolarDistance = 2.0;
    //! A segment pair is a candidate when the second segment covers at least this fraction of the
    //! shorter of itself and the band between the epipolar lines of the first's end points.
    double minBandOverlap = 0.5;
    //! Segments within this angle (deg) of the epipolar lines cross the band at no defined place
    //! and have no depth from the two views: they are not matched under the geometry.
    double minEpipolarAngleDeg = 5.0;
    double pointRatio = 0.8; //!< Point descriptors: best distance below this fraction of the second best.
    double lineRatio = 0.8;  //!< Line descriptors: the same.
    //! Binary line descriptors further apart than this many bits never match (80 of LBD's 256 bits).
    double maxLineDistance = 80;
    //! Frames of unknown relative pose are matched under the fundamental matrix of their descriptor
    //! matches when at least this many matches agree with it; by descriptor alone otherwise.
    int minFundamentalInliers = 30;
};

//! F with xb^T F xa = 0 for a view at the identity (K @p Ka) and one at @p relative (K @p Kb).
Eigen::Matrix3d fundamentalFromPose(const Eigen::Matrix3d& Ka, const Eigen::Matrix3d& Kb, const CameraPose& relative);

//! Whether @p xa and @p xb each lie within @p distance (px) of the other's epipolar line under @p F.
bool withinEpipolarDistance(const Eigen::Matrix3d& F, const Eigen::Vector2d& xa, const Eigen::Vector2d& xb,
                            double distance);

/** Points of frames a and b under the epipolar geometry @p F (xb^T F xa = 0): candidates within
MatchOptions::epipolarDistance of the epipolar lines both ways, then mutual best descriptor with the
ratio test among the candidates. */
Matches matchPointsEpipolar(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                            const MatchOptions& options);

/** Segments of frames a and b under @p F: candidates overlap the band between the epipolar lines of
the other's end points (MatchOptions::minBandOverlap) and run the same way along it, then mutual best
descriptor with the ratio test among the candidates. */
Matches matchSegmentsEpipolar(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                              const MatchOptions& options);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_EPIPOLAR_MATCHING_HPP
