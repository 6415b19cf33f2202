// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "two_view_geometry.hpp"

#include <limits>

#include <opencv2/calib3d.hpp>

namespace tripose_samples {

cv::Matx33d fundamentalMatrix(const cv::Matx33d& K1, const cv::Matx33d& K2, const cv::Matx33d& R12,
                              const cv::Vec3d& t12)
{
    const cv::Matx33d tx(0, -t12[2], t12[1], t12[2], 0, -t12[0], -t12[1], t12[0], 0);
    return K2.inv().t() * (tx * R12) * K1.inv();
}

bool projectPoint(const cv::Matx34d& P, const cv::Vec3d& X, cv::Point2d& x)
{
    const cv::Vec3d h = P * cv::Vec4d(X[0], X[1], X[2], 1);
    if (!(h[2] > 0))
        return false;
    x = cv::Point2d(h[0] / h[2], h[1] / h[2]);
    return true;
}

} // namespace tripose_samples
