// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_VIEW_SET_HPP
#define OPENCV_TRIPOSE_GEOMETRY_VIEW_SET_HPP

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "camera.hpp"

namespace tripose {

/** One camera and what it sees of the features of a problem.

A view's pose is either known (`estimated == false`: `pose` is the view's pose in the world frame)
or moves with the pose being estimated (`estimated == true`: `pose` is where the view is mounted
in the frame of the estimated camera, the identity for that camera itself, a stereo rig's offset
for its second camera).

Observations are undistorted. Features are indexed per kind (points 0..numPoints-1, lines
0..numLines-1) across all views of a ViewSet; a view holds an entry for every feature and says which
it sees.
*/
struct View
{
    Intrinsics camera;
    bool estimated = false;
    CameraPose pose;

    std::vector<Eigen::Vector2d> points;   //!< Pixels, one per point feature.
    std::vector<Eigen::Vector2d> lineEnds; //!< Pixels, two per line feature: the segment's end points
                                           //!< (or two points on a homogeneous line).
    std::vector<Eigen::Vector2d> calibratedPoints; //!< K^-1 applied to points.
    std::vector<Eigen::Vector3d> calibratedLines;  //!< Calibrated homogeneous lines, (a, b) of unit norm.
    std::vector<unsigned char> pointSeen, lineSeen; //!< Per feature, 1 if seen; empty: every feature is seen.

    bool seesPoint(int i) const { return pointSeen.empty() || pointSeen[i] != 0; }
    bool seesLine(int i) const { return lineSeen.empty() || lineSeen[i] != 0; }

    //! This view's pose when the estimated camera is at @p estimatedPose.
    CameraPose poseFor(const CameraPose& estimatedPose) const
    {
        return estimated ? composePose(pose, estimatedPose) : pose;
    }

    //! Calibrated end point @p end (0 or 1) of line @p line.
    Eigen::Vector2d calibratedLineEnd(int line, int end) const
    {
        return camera.calibrate(lineEnds[2 * line + end]);
    }
};

/** The views of a problem: cameras whose poses are known and the camera(s) that move with the
pose being estimated.

The three-view problem of estimatePoseLinePoint() is the case views = {view 1 at [I|0], view 2 at
[R12|t12], view 3 estimated}, every feature seen in all three; the linear solver works on that case
(kView1, kView2, kView3). The stereo rig adds view 4, mounted on view 3 at [R12|t12], and lets
features be missing in view 3 or 4 (kRigLeftB, kRigRightB). Registration against several known
views (estimatePoseMultiView()) lists the known views at their world poses, then the estimated one,
each feature seen by any subset. Scoring, triangulation and refinement take any list.
*/
struct ViewSet
{
    static const int kView1 = 0, kView2 = 1, kView3 = 2;
    static const int kRigLeftB = 2, kRigRightB = 3;

    std::vector<View> views;
    int numPoints = 0, numLines = 0;

    int numFeatures() const { return numPoints + numLines; }

    //! Pose of view 2 relative to view 1 in the three-view problem.
    const CameraPose& pose12() const { return views[kView2].pose; }

    //! Distance between the centres of the first two known views (1 when there are fewer): the
    //! problem's length scale, against which "at a camera centre" and "behind a camera" are judged.
    double knownBaseline() const
    {
        const CameraPose* first = nullptr;
        for (const View& view : views)
        {
            if (view.estimated)
                continue;
            if (!first)
                first = &view.pose;
            else
                return (view.pose.centre() - first->centre()).norm();
        }
        return 1.0;
    }
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_VIEW_SET_HPP
