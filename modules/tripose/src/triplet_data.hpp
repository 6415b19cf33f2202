// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TRIPLET_DATA_HPP
#define OPENCV_TRIPOSE_TRIPLET_DATA_HPP

#include <vector>

#include <Eigen/Core>

namespace cv {
namespace tripose {
namespace detail {

//! A camera pose x ~ R X + t.
struct CameraPose
{
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

//! Observations of one view in undistorted pixels, with its intrinsic matrix.
struct ViewObservations
{
    Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
    std::vector<Eigen::Vector2d> points;   //!< One per point triplet.
    std::vector<Eigen::Vector2d> lineEnds; //!< Two per line triplet: the segment's end points (or two points on a homogeneous line).
};

//! The solver's view of a problem: undistorted, calibrated observations in three views.
//! Points are inhomogeneous calibrated coordinates (K^-1 applied). Lines are calibrated homogeneous
//! lines scaled so that their first two entries have unit norm. The pixel observations are kept for
//! errors measured in pixels (scoring, refinement).
struct TripletData
{
    CameraPose view2; //!< Known pose of view 2 (R12, t12).

    std::vector<Eigen::Vector2d> points1, points2, points3;
    std::vector<Eigen::Vector3d> lines1, lines2, lines3;

    ViewObservations pixels[3];

    int numPoints() const { return (int)points1.size(); }
    int numLines() const { return (int)lines1.size(); }
    int numFeatures() const { return numPoints() + numLines(); }

    //! Calibrated (K^-1 applied) end point @p end (0 or 1) of line @p line in view @p view.
    Eigen::Vector2d calibratedLineEnd(int view, int line, int end) const
    {
        const Eigen::Vector2d& e = pixels[view].lineEnds[2 * line + end];
        const Eigen::Matrix3d& K = pixels[view].K;
        // K is upper triangular: invert the affine map in closed form.
        const double y = (e.y() - K(1, 2)) / K(1, 1);
        const double x = (e.x() - K(0, 2) - K(0, 1) * y) / K(0, 0);
        return Eigen::Vector2d(x, y);
    }
};

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_TRIPLET_DATA_HPP
