// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_POSE_CONVERSION_HPP
#define OPENCV_TRIPOSE_POSE_CONVERSION_HPP

#include <Eigen/Core>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! 3x3 CV_64F copy of an Eigen matrix (the form every public function returns rotations in).
inline Mat toMat(const Eigen::Matrix3d& R)
{
    Mat m(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m.at<double>(r, c) = R(r, c);
    return m;
}

//! 3x1 CV_64F copy of an Eigen vector.
inline Mat toMat(const Eigen::Vector3d& t)
{
    return (Mat_<double>(3, 1) << t.x(), t.y(), t.z());
}

//! Writes R (3x3) and t (3x1) as CV_64F into the outputs directly (no temporary Mat).
inline void writePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, OutputArray Rout, OutputArray tout)
{
    Rout.create(3, 3, CV_64F);
    Mat Rm = Rout.getMat();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            Rm.at<double>(r, c) = R(r, c);
    tout.create(3, 1, CV_64F);
    Mat tm = tout.getMat();
    for (int r = 0; r < 3; ++r)
        tm.at<double>(r) = t(r);
}

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_POSE_CONVERSION_HPP
