// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_INPUT_PROBLEM_INPUT_HPP
#define OPENCV_TRIPOSE_INPUT_PROBLEM_INPUT_HPP

#include "opencv2/core.hpp"
#include "../geometry/view_set.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** Validates the arguments shared by the three-view functions and converts them into the views of
the three-view problem (ViewSet: view 1 at [I|0], view 2 at [R12|t12], view 3 estimated; every
feature seen in all three), undistorted and calibrated. Every violation raises cv::Exception (StsBadArg or StsBadSize) whose
message names the argument and states what was expected. Requires at least @p minFeatures
features (points + lines).

Homogeneous lines (Mx3) carry no extent; where end points are needed (scoring, cheirality) two
points on the line, kHomogeneousLineHalfLength px either side of the point closest to the principal
point, stand in for them.
*/
ViewSet readThreeViewInput(InputArray points1, InputArray points2, InputArray points3,
                             InputArray lines1, InputArray lines2, InputArray lines3,
                             InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                             InputArray R12, InputArray t12, int minFeatures = 4);

/** The stereo-rig problem: views = {left camera at time A at [I|0], right camera at time A at the
rig [R12|t12], left camera at time B (estimated), right camera at time B (mounted on it at
[R12|t12])}. Points and lines are seen in views 1 and 2 and in view 3, view 4 or both: in points3,
points4, lines3 and lines4 a row of NaN marks a feature that view does not see, and an empty array
a view that sees none of that kind. Validation as readThreeViewInput(); additionally every feature
must be seen in view 3 or 4.
*/
ViewSet readStereoRigInput(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                           InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, int minFeatures);

/** Registration against several known views: views = {known view 0, ..., known view V-1 at their
world poses Rs[k], ts[k], the new view (estimated)}. @p points and @p lines hold one array per view
(the known views, then the new view), a row of NaN where a view does not see the feature, an empty
array where it sees none of that kind. Validation as readThreeViewInput(), plus: at least two known
views, not all at one centre; every feature seen in the new view and in at least two known views.
*/
ViewSet readMultiViewInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                           InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts, int minFeatures);

/** Several poses refined together (refinePosesMultiView()): views = {view 0, ..., view V-1}, all with
the world poses Rs[k], ts[k]; @p fixedViews (V values, nonzero: fixed) says which stay. The free
views are marked estimated, each a camera of its own, and @p poseOfView receives the index of each
free view's pose among the free views (-1 for a fixed view), @p initialPoses their poses from
@p Rs, @p ts in that order. @p points and @p lines hold one array
per view as in readMultiViewInput(). Validation as readThreeViewInput(), plus: at least one free
view, at least two fixed views at distinct centres, every feature seen in at least two views.
The returned set's free views hold the identity as their mount.
*/
ViewSet readSeveralPosesInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                              InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                              InputArray fixedViews, std::vector<int>& poseOfView,
                              std::vector<CameraPose>& initialPoses);

constexpr double kHomogeneousLineHalfLength = 50.0;

/** A rotation given as a 3x3 matrix or a Rodrigues vector (CV_32F/CV_64F), checked (finite,
orthonormal within the input precision, det +1; cv::Exception naming @p name otherwise) and
returned as the nearest exact rotation.
*/
Eigen::Matrix3d readRotation(InputArray arr, const char* name);

/** A translation of 3 elements (CV_32F/CV_64F, any shape), finite; cv::Exception naming @p name
otherwise, and when @p nonZero is set and it is zero.
*/
Eigen::Vector3d readTranslation(InputArray arr, const char* name, bool nonZero);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_INPUT_PROBLEM_INPUT_HPP
