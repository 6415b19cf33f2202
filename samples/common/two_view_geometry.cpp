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

cv::Matx34d projectionMatrix(const cv::Matx33d& K, const cv::Matx33d& R, const cv::Vec3d& t)
{
    cv::Matx34d Rt;
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
            Rt(r, c) = R(r, c);
        Rt(r, 3) = t[r];
    }
    return K * Rt;
}

cv::Mat triangulatePoints(const cv::Mat& points1, const cv::Mat& points2, const cv::Matx34d& P1,
                          const cv::Matx34d& P2)
{
    if (points1.rows == 0)
        return cv::Mat(0, 3, CV_64F);
    cv::Mat homogeneous;
    cv::triangulatePoints(cv::Mat(P1), cv::Mat(P2), points1.t(), points2.t(), homogeneous);
    cv::Mat X(points1.rows, 3, CV_64F);
    for (int i = 0; i < points1.rows; ++i)
        for (int c = 0; c < 3; ++c)
            X.at<double>(i, c) = homogeneous.at<double>(c, i) / homogeneous.at<double>(3, i);
    return X;
}

cv::Mat triangulateSegments(const cv::Mat& lines1, const cv::Mat& lines2, const cv::Matx34d& P1,
                            const cv::Matx34d& P2)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    cv::Mat X(lines1.rows, 6, CV_64F, cv::Scalar::all(nan));
    // View 1's centre and the directions of its rays: P1 = [M | p4], a pixel x sees C + s M^-1 x.
    const cv::Matx33d M(P1(0, 0), P1(0, 1), P1(0, 2), P1(1, 0), P1(1, 1), P1(1, 2), P1(2, 0), P1(2, 1), P1(2, 2));
    const cv::Matx33d Minv = M.inv();
    const cv::Vec3d C = -(Minv * cv::Vec3d(P1(0, 3), P1(1, 3), P1(2, 3)));
    for (int i = 0; i < lines1.rows; ++i)
    {
        const double* s1 = lines1.ptr<double>(i);
        const double* s2 = lines2.ptr<double>(i);
        const cv::Vec3d l2 = cv::Vec3d(s2[0], s2[1], 1).cross(cv::Vec3d(s2[2], s2[3], 1));
        const cv::Vec4d plane = P2.t() * l2; // the plane through view 2's centre and the segment
        const cv::Vec3d n(plane[0], plane[1], plane[2]);
        bool ok = true;
        cv::Vec3d ends[2];
        for (int e = 0; e < 2; ++e)
        {
            const cv::Vec3d direction = Minv * cv::Vec3d(s1[2 * e], s1[2 * e + 1], 1);
            const double along = n.dot(direction);
            // A ray within a degree or so of the plane: the depth is not defined by these views.
            if (std::abs(along) < 1e-2 * cv::norm(n) * cv::norm(direction))
            {
                ok = false;
                break;
            }
            const double s = -(n.dot(C) + plane[3]) / along;
            ends[e] = C + s * direction;
        }
        if (!ok)
            continue;
        for (int e = 0; e < 2; ++e)
            for (int c = 0; c < 3; ++c)
                X.at<double>(i, 3 * e + c) = ends[e][c];
    }
    return X;
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
