// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Links against the installed tripose package and solves one exact problem of three points and
// three line segments, built here from a few 3D features and three cameras (the installed package
// has nothing to generate scenes with). Exit status 0 only if the pose is recovered.

#include <cmath>
#include <iostream>

#include <opencv2/tripose.hpp>

namespace {

//! Rotation by angle a (rad) about the z axis, then b about the y axis.
cv::Matx33d rotation(double a, double b)
{
    const cv::Matx33d Rz(std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1);
    const cv::Matx33d Ry(std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b));
    return Ry * Rz;
}

//! Pixel of world point X in the camera x ~ K (R X + t).
cv::Point2d project(const cv::Matx33d& K, const cv::Matx33d& R, const cv::Vec3d& t, const cv::Vec3d& X)
{
    const cv::Vec3d p = K * (R * X + t);
    return cv::Point2d(p[0] / p[2], p[1] / p[2]);
}

} // namespace

int main()
{
    const cv::Matx33d K(800, 0, 319.5, 0, 800, 239.5, 0, 0, 1);
    // View 1 is the world frame; views 2 and 3 look at the structure around (0, 0, 10) from aside.
    const cv::Matx33d R12 = rotation(0.05, -0.15), R13 = rotation(-0.1, 0.25);
    const cv::Vec3d t12(1.5, 0.1, 0.3), t13(-2.4, 0.2, 1.0);
    const cv::Vec3d points[3] = { { -1.0, -0.5, 9.0 }, { 1.2, 0.4, 10.5 }, { 0.3, 1.1, 11.0 } };
    const cv::Vec3d segments[3][2] = { { { -1.5, -1.0, 9.5 }, { 1.0, -0.8, 10.0 } },
                                       { { -0.8, 0.9, 10.0 }, { -0.2, -1.2, 11.5 } },
                                       { { 0.6, -0.2, 8.8 }, { 1.4, 1.3, 10.2 } } };

    const cv::Matx33d Rs[3] = { cv::Matx33d::eye(), R12, R13 };
    const cv::Vec3d ts[3] = { cv::Vec3d(0, 0, 0), t12, t13 };
    cv::Mat observedPoints[3], observedLines[3];
    for (int v = 0; v < 3; ++v)
    {
        observedPoints[v].create(3, 2, CV_64F);
        observedLines[v].create(3, 4, CV_64F);
        for (int i = 0; i < 3; ++i)
        {
            const cv::Point2d x = project(K, Rs[v], ts[v], points[i]);
            const cv::Point2d a = project(K, Rs[v], ts[v], segments[i][0]);
            const cv::Point2d b = project(K, Rs[v], ts[v], segments[i][1]);
            observedPoints[v].at<double>(i, 0) = x.x;
            observedPoints[v].at<double>(i, 1) = x.y;
            double* line = observedLines[v].ptr<double>(i);
            line[0] = a.x;
            line[1] = a.y;
            line[2] = b.x;
            line[3] = b.y;
        }
    }

    cv::Mat R, t;
    const int n = cv::tripose::estimatePoseLinePoint(observedPoints[0], observedPoints[1], observedPoints[2],
                                                     observedLines[0], observedLines[1], observedLines[2], cv::Mat(K),
                                                     cv::noArray(), cv::Mat(R12), cv::Mat(t12), R, t);
    if (n == 0)
    {
        std::cerr << "tripose_consumer: no solution\n";
        return 1;
    }
    const double rotationError = cv::norm(R, cv::Mat(R13), cv::NORM_INF);
    const double translationError = cv::norm(t, cv::Mat(t13), cv::NORM_L2) / cv::norm(t13);
    std::cout << "tripose_consumer: " << n << " solution(s), |R - R_true|_inf = " << rotationError
              << ", relative translation error = " << translationError << "\n";
    return rotationError < 1e-6 && translationError < 1e-6 ? 0 : 1;
}
