// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_PLANE_FIT_HPP
#define OPENCV_TRIPOSE_GEOMETRY_PLANE_FIT_HPP

#include <vector>

#include <Eigen/Core>

namespace tripose {

//! A least-squares plane through a set of positions, and how far the positions spread about it.
struct Plane
{
    //! Variances of the positions along the normal and along the two directions within the plane,
    //! ascending: extents(0) is the thickness squared.
    Eigen::Vector3d extents = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::Zero(); //!< Unit normal.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); //!< Mean of the positions: a point on the plane.
};

/** Accumulates the first and second moments of positions about the first one (about the origin,
the covariance would be a difference of two moments of the size of the squared depth, whose rounding
alone exceeds a planarity test for thin structure), without storing them.
*/
class PlaneAccumulator
{
public:
    void add(const Eigen::Vector3d& X);
    //! The plane of the positions added; false with fewer than four or a non-finite value.
    bool fit(Plane& plane) const;

private:
    Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(), sum_ = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second_ = Eigen::Matrix3d::Zero();
    int count_ = 0;
};

/** Refits @p plane (a fit of @p X) to the bulk of the positions: @p rounds times, without the
positions beyond three times the median distance from the previous fit. Noisy positions on one
plane triangulate with a few far off it (a point near the epipole of the known pair, a line near
an epipolar plane), and those tilt a plain fit and thicken it. False when fewer than four
positions are left or a value is not finite (@p plane then undefined).
*/
bool trimPlaneFit(const std::vector<Eigen::Vector3d>& X, int rounds, Plane& plane);

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_PLANE_FIT_HPP
