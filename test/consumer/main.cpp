// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Links against the installed tripose package and solves one exact synthetic problem.
// Exit status 0 only if the pose is recovered.

#include <iostream>

#include <opencv2/tripose.hpp>

int main()
{
    cv::tripose::SyntheticSceneParams params;
    params.numPoints = 3;
    params.numLines = 3;
    params.seed = 42;
    const cv::tripose::SyntheticScene s = cv::tripose::generateSyntheticScene(params);

    cv::Mat R, t;
    const int n = cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                     s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t);
    if (n == 0)
    {
        std::cerr << "tripose_consumer: no solution\n";
        return 1;
    }
    const double rotationError = cv::norm(R, s.R, cv::NORM_INF);
    const double translationError = cv::norm(t, s.t, cv::NORM_L2) / cv::norm(s.t, cv::NORM_L2);
    std::cout << "tripose_consumer: " << n << " solution(s), |R - R_true|_inf = " << rotationError
              << ", relative translation error = " << translationError << "\n";
    return rotationError < 1e-6 && translationError < 1e-6 ? 0 : 1;
}
