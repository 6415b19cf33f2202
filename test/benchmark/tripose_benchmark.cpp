// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_benchmark: median time per call of our estimators (estimatePoseLinePoint, the same
// followed by refinePoseLinePoint) beside "triangulate the points from views 1-2, then
// cv::solvePnP in view 3" (SQPnP and EPnP) on the same scenes, in the same process, one thread;
// each peer's time is also printed as a ratio to the linear solver's, and the median rotation and
// translation errors of every method are printed so that speed is read together with accuracy.
// PoseLib (a Python package here) is compared by test/evaluation/run_evaluation.py; the robust
// estimator is compared by tripose_ransac_benchmark.
//
//   tripose_benchmark [--scenes 200] [--repeats 20] [--noise 1.0] [--motion large|small]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

#include "benchmark_common.hpp"
#include "tripose_support/pose_error.hpp"
#include "tripose_support/synthetic_scene.hpp"

namespace {

using tripose_benchmark::median;

//! Triangulates the points from views 1-2 and solves PnP in view 3 (the baseline a user would write).
bool triangulateThenPnP(const cv::tripose::support::SyntheticScene& s, int flags, cv::Mat& R, cv::Mat& t)
{
    const cv::Mat& K1 = s.cameraMatrices[0];
    const cv::Mat P1 = K1 * cv::Mat::eye(3, 4, CV_64F);
    cv::Mat Rt2;
    cv::hconcat(s.R12, s.t12, Rt2);
    const cv::Mat P2 = s.cameraMatrices[1] * Rt2;
    cv::Mat X4;
    cv::triangulatePoints(P1, P2, s.points1.t(), s.points2.t(), X4);
    cv::Mat X;
    cv::convertPointsFromHomogeneous(X4.t(), X);
    cv::Mat rvec, tvec;
    if (!cv::solvePnP(X, s.points3, s.cameraMatrices[2], cv::noArray(), rvec, tvec, false, flags))
        return false;
    cv::Rodrigues(rvec, R);
    t = tvec;
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    int scenes = 200, repeats = 20;
    double noise = 1.0;
    int motion = cv::tripose::support::MOTION_LARGE;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string arg = argv[i], value = argv[i + 1];
        if (arg == "--scenes") scenes = std::stoi(value);
        else if (arg == "--repeats") repeats = std::stoi(value);
        else if (arg == "--noise") noise = std::stod(value);
        else if (arg == "--motion") motion = value == "small" ? cv::tripose::support::MOTION_SMALL : cv::tripose::support::MOTION_LARGE;
        else { std::fprintf(stderr, "unknown argument %s\n", arg.c_str()); return 1; }
    }
    if (scenes < 1 || repeats < 1)
    {
        std::fprintf(stderr, "--scenes and --repeats must be >= 1\n");
        return 1;
    }
    cv::setNumThreads(1);

    typedef std::function<bool(const cv::tripose::support::SyntheticScene&, int, cv::Mat&, cv::Mat&)> Solver;
    const std::vector<std::pair<std::string, Solver>> methods = {
        { "linear", [](const cv::tripose::support::SyntheticScene& s, int, cv::Mat& R, cv::Mat& t) {
              return cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                        s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t) > 0;
          } },
        { "lin+refine", [](const cv::tripose::support::SyntheticScene& s, int, cv::Mat& R, cv::Mat& t) {
              if (cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                     s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t) == 0)
                  return false;
              return std::isfinite(cv::tripose::refinePoseLinePoint(s.points1, s.points2, s.points3, s.lines1,
                                                                    s.lines2, s.lines3, s.cameraMatrices,
                                                                    cv::noArray(), s.R12, s.t12, R, t));
          } },
        { "tri+SQPnP", [](const cv::tripose::support::SyntheticScene& s, int, cv::Mat& R, cv::Mat& t) {
              return triangulateThenPnP(s, cv::SOLVEPNP_SQPNP, R, t);
          } },
        { "tri+EPnP", [](const cv::tripose::support::SyntheticScene& s, int, cv::Mat& R, cv::Mat& t) {
              return triangulateThenPnP(s, cv::SOLVEPNP_EPNP, R, t);
          } },
    };
    const size_t M = methods.size();

    const int configs[][2] = { { 4, 4 }, { 5, 5 }, { 10, 10 }, { 20, 20 }, { 45, 45 } };
    std::printf("%d scenes x %d repeats, noise %.2f px, %s motion, one thread\n", scenes, repeats, noise,
                motion == cv::tripose::support::MOTION_LARGE ? "large" : "small");
    std::printf("per method: median time (us) [ratio to linear] median rotation error (deg) / median relative "
                "translation error; failures count as infinite error\n");
    std::printf("%-9s", "features");
    for (const auto& m : methods)
        std::printf(" | %-34s", m.first.c_str());
    std::printf("\n");
    for (const auto& c : configs)
    {
        std::vector<std::vector<double>> times(M), rot(M), trans(M);
        for (int k = 0; k < scenes; ++k)
        {
            cv::tripose::support::SyntheticSceneParams params;
            params.numPoints = c[0];
            params.numLines = c[1];
            params.noiseSigma = noise;
            params.motion = motion;
            params.seed = 1000 + k;
            const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
            std::vector<double> sceneTimes;
            std::vector<cv::tripose::support::PoseError> sceneErrors;
            tripose_benchmark::runInterleaved(s, k, methods, repeats, 1e6, sceneTimes, sceneErrors);
            for (size_t m = 0; m < M; ++m)
            {
                times[m].push_back(sceneTimes[m]);
                rot[m].push_back(sceneErrors[m].rotationDeg);
                trans[m].push_back(sceneErrors[m].relativeTranslation);
            }
        }
        const double base = median(times[0]);
        char label[32];
        std::snprintf(label, sizeof(label), "%dP+%dL", c[0], c[1]);
        std::printf("%-9s", label);
        for (size_t m = 0; m < M; ++m)
        {
            const double tm = median(times[m]);
            char cell[64];
            std::snprintf(cell, sizeof(cell), "%7.1f [x%5.2f] %.3f/%.4f", tm, tm / base, median(rot[m]), median(trans[m]));
            std::printf(" | %-34s", cell);
        }
        std::printf("\n");
    }
    std::printf("ratio = method time / linear time (> 1: the linear solver is faster)\n");
    return tripose_benchmark::failureStatus();
}
