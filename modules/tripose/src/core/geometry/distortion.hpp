// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_GEOMETRY_DISTORTION_HPP
#define TRIPOSE_CORE_GEOMETRY_DISTORTION_HPP

#include <array>
#include <vector>

#include <Eigen/Core>

namespace tripose {

/** OpenCV's lens distortion model (its 4, 5, 8, 12 or 14 coefficients: k1 k2 p1 p2 [k3 [k4 k5 k6
[s1 s2 s3 s4 [tauX tauY]]]]), so that a calibration made with OpenCV applies unchanged.

With (x, y) the ideal normalised coordinates and r^2 = x^2 + y^2:
  x' = x (1 + k1 r^2 + k2 r^4 + k3 r^6) / (1 + k4 r^2 + k5 r^4 + k6 r^6)
       + 2 p1 x y + p2 (r^2 + 2 x^2) + s1 r^2 + s2 r^4,
  y' = y (...) / (...) + p1 (r^2 + 2 y^2) + 2 p2 x y + s3 r^2 + s4 r^4,
then the sensor tilt (tauX, tauY) maps (x', y') through a projective transformation, and K gives
the observed pixel.
*/
struct Distortion
{
    std::array<double, 14> k{}; //!< The coefficients, zero past those given.

    //! Undistorts pixels in place: the inverse of the model, as cv::undistortPoints() computes it
    //! with the same K as input and output camera (fixed-point iterations to convergence).
    void undistortPixels(std::vector<Eigen::Vector2d>& pixels, const Eigen::Matrix3d& K) const;
};

} // namespace tripose

#endif // TRIPOSE_CORE_GEOMETRY_DISTORTION_HPP
