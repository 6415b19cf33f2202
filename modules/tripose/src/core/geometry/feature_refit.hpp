// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_FEATURE_REFIT_HPP
#define OPENCV_TRIPOSE_GEOMETRY_FEATURE_REFIT_HPP

#include <vector>

#include <Eigen/Core>

#include "line_parameterization.hpp"
#include "view_set.hpp"

namespace tripose {

/** A feature refit to every view of a ViewSet that sees it, at given poses: triangulated from all of
those views (geometry/triangulation), then measured in each of them by the residuals of
geometry/residuals. The estimators' final inlier test (PoseScorer::refitResiduals()) and the
structure and per-observation errors of triangulateStructure() are this, combined differently.

@p poses holds the pose of every view of @p set (viewPoses()). @p residuals receives one residual
per view of the set (a point: its projection minus the observation; a line: the signed distances of
the two observed end points to its image), zero for the views that do not see the feature. The
functions return false, leaving @p residuals unspecified, when the feature cannot be triangulated
(fewer than two views see it, a point's rays are parallel, a line's planes coincide) or lies behind a
view that sees it (a point at a depth <= @p minDepth; a line: the part of it the view saw,
geometry/segment_cheirality.hpp).
*/
bool refitPoint(const ViewSet& set, const CameraPose* poses, int point, double minDepth, Eigen::Vector3d& X,
                std::vector<Eigen::Vector2d>& residuals);

bool refitLine(const ViewSet& set, const CameraPose* poses, int line, PluckerLine& L,
               std::vector<Eigen::Vector2d>& residuals);

/** The points of @p L closest to the rays of the two observed end points of line @p line in
@p view, at @p viewPose: where that view saw the line end (closestPointToRay()).
*/
void lineEndsSeenBy(const View& view, const CameraPose& viewPose, int line, const PluckerLine& L,
                    Eigen::Vector3d& A, Eigen::Vector3d& B);

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_FEATURE_REFIT_HPP
