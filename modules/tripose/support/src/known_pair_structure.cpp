// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tripose_support/known_pair_structure.hpp"

#include <cmath>
#include <limits>

#include "opencv_geometry.hpp"

namespace cv {
namespace tripose {
namespace support {

Matx34d projectionMatrix(const Matx33d& K, const Matx33d& R, const Vec3d& t)
{
    Matx34d Rt;
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
            Rt(r, c) = R(r, c);
        Rt(r, 3) = t[r];
    }
    return K * Rt;
}

Mat triangulateKnownPair(const Matx33d& K1, const Matx33d& K2, const Matx33d& R12, const Vec3d& t12,
                         const Mat& points1, const Mat& points2)
{
    if (points1.rows == 0)
        return Mat(0, 3, CV_64F);
    const Mat P1(projectionMatrix(K1, Matx33d::eye(), Vec3d())), P2(projectionMatrix(K2, R12, t12));
    Mat X4, X;
    cv::triangulatePoints(P1, P2, points1.t(), points2.t(), X4);
    convertPointsFromHomogeneous(X4.t(), X);
    return X.reshape(1, points1.rows);
}

Mat liftSegmentsKnownPair(const Matx33d& K1, const Matx33d& K2, const Matx33d& R12, const Vec3d& t12,
                          const Mat& lines1, const Mat& lines2, double minSine)
{
    Mat L(lines1.rows, 6, CV_64F, Scalar::all(std::numeric_limits<double>::quiet_NaN()));
    const Matx34d P2 = projectionMatrix(K2, R12, t12);
    const Matx33d K1inv = K1.inv();
    for (int i = 0; i < lines1.rows; ++i)
    {
        const double* s2 = lines2.ptr<double>(i);
        const Vec3d l2 = Vec3d(s2[0], s2[1], 1.0).cross(Vec3d(s2[2], s2[3], 1.0));
        const Vec4d plane = P2.t() * l2; // through view 2's centre and its segment
        const Vec3d n(plane[0], plane[1], plane[2]);
        const double* s1 = lines1.ptr<double>(i);
        for (int e = 0; e < 2; ++e)
        {
            // View 1 is at the origin: its ray through a pixel x is s K1^-1 x.
            const Vec3d ray = K1inv * Vec3d(s1[2 * e], s1[2 * e + 1], 1.0);
            const double along = n.dot(ray);
            if (std::abs(along) < minSine * norm(n) * norm(ray))
                continue;
            const double s = -plane[3] / along;
            for (int k = 0; k < 3; ++k)
                L.at<double>(i, 3 * e + k) = s * ray[k];
        }
    }
    return L;
}

} // namespace support
} // namespace tripose
} // namespace cv
