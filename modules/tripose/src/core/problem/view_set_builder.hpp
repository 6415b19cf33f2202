// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_PROBLEM_VIEW_SET_BUILDER_HPP
#define TRIPOSE_CORE_PROBLEM_VIEW_SET_BUILDER_HPP

#include <vector>

#include "../geometry/view_set.hpp"
#include "problem_arguments.hpp"

namespace tripose {

/** The problems of the entry points, validated, undistorted and calibrated into ViewSets. Every
violation throws Error (BadArgument or BadSize) whose message names the caller's argument (the
names the ArgumentMatrix objects carry) and states what was expected.

Homogeneous lines (Mx3) carry no extent; where end points are needed (scoring, cheirality) two
points on the line, kHomogeneousLineHalfLength px either side of the point closest to the principal
point, stand in for them.
*/
constexpr double kHomogeneousLineHalfLength = 50.0;

/** The three-view problem: views = {view 1 at [I|0], view 2 at [R12|t12], view 3 estimated}, every
feature seen in all three; at least @p minFeatures features (points + lines).
*/
ViewSet buildThreeViewSet(const ProblemArguments& arguments, const ArgumentMatrix& R12, const ArgumentMatrix& t12,
                          int minFeatures);

/** The stereo-rig problem: views = {left camera at time A at [I|0], right camera at time A at the
rig [R12|t12], left camera at time B (estimated), right camera at time B (mounted on it at
[R12|t12])}. Views 3 and 4 may miss features (NaN rows, empty arrays); every feature must be seen
in view 3 or 4.
*/
ViewSet buildStereoRigSet(const ProblemArguments& arguments, const ArgumentMatrix& R12, const ArgumentMatrix& t12,
                          int minFeatures);

/** The multi-view layouts name their per-view arguments points[v], lines[v], Rs[k] and ts[k], in
every adapter; their errors name those.

Registration against several known views: views = {known view 0, ..., known view V-1 at their
world poses Rs[k], ts[k], the new view (estimated)}. At least two known views, not all at one
centre; every feature seen in the new view and in at least two known views.
*/
ViewSet buildMultiViewSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                          const std::vector<ArgumentMatrix>& ts, int minFeatures);

/** Several poses refined together: views = {view 0, ..., view V-1}, all at the world poses Rs[k],
ts[k]; @p fixedViews (V values, nonzero: fixed, named @p fixedViewsName) says which stay. The free
views are marked estimated, each a camera of its own; @p poseOfView receives the index of each free
view's pose among the free views (-1 for a fixed view), @p initialPoses their poses in that order.
At least one free view, at least two fixed views at distinct centres, every feature seen in at
least two views.
*/
ViewSet buildSeveralPosesSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                             const std::vector<ArgumentMatrix>& ts, const std::vector<int>& fixedViews,
                             const char* fixedViewsName, std::vector<int>& poseOfView,
                             std::vector<CameraPose>& initialPoses);

/** Views of known pose only (triangulateStructure()): views = {view 0, ..., view V-1} at the world
poses Rs[k], ts[k], V >= 2; at least one feature. A feature may be seen by any number of views.
*/
ViewSet buildPosedViewSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                          const std::vector<ArgumentMatrix>& ts);

/** A rotation given as a 3x3 matrix or a 3-element rotation vector (axis times angle), checked
(finite, |R^T R - I| <= 1e-4, det > 0) and returned as the nearest exact rotation.
*/
Eigen::Matrix3d readRotation(const ArgumentMatrix& rotation);

//! A translation of 3 elements, finite, and non-zero when @p nonZero is set.
Eigen::Vector3d readTranslation(const ArgumentMatrix& translation, bool nonZero);

} // namespace tripose

#endif // TRIPOSE_CORE_PROBLEM_VIEW_SET_BUILDER_HPP
