// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_ransac_benchmark: median time per call of the robust estimator, end to end
// (estimatePoseLinePointRansac: sampling, local optimisation, refinement over the three views),
// beside what a user without tripose would run on the same scenes, in the same process, one
// thread: triangulate the points from views 1-2 (cv::triangulatePoints), cv::solvePnPRansac in view
// 3, then cv::solvePnPRefineLM on its inliers. Scenes: points and segments in the paper's cube,
// a fraction of them with a random wrong match in view 3. Printed per method: median time, ratio
// to tripose, median rotation and translation errors, and the share of scenes within 1 degree and
// 5 % translation, so that speed is read together with accuracy.
//
//   tripose_ransac_benchmark [--scenes 30] [--repeats 5] [--points 1000] [--lines 400]
//                            [--outliers 0.5] [--noise 1.0] [--threshold 2]

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

struct Options
{
    int scenes = 30, repeats = 5, points = 1000, lines = 400;
    double outliers = 0.5, noise = 1.0, threshold = 2.0;
};

/** The alternative a user would write: 3D points from views 1-2, RANSAC PnP in view 3 (AP3P
samples; the threshold is doubled because the triangulated points carry the error of two views,
as tripose's own sampling threshold is), then Levenberg-Marquardt on the inliers.
*/
bool triangulatePnPRansacRefine(const cv::tripose::support::SyntheticScene& s, double threshold, cv::Mat& R, cv::Mat& t)
{
    const cv::Mat P1 = s.cameraMatrices[0] * cv::Mat::eye(3, 4, CV_64F);
    cv::Mat Rt2;
    cv::hconcat(s.R12, s.t12, Rt2);
    const cv::Mat P2 = s.cameraMatrices[1] * Rt2;
    cv::Mat X4, X;
    cv::triangulatePoints(P1, P2, s.points1.t(), s.points2.t(), X4);
    cv::convertPointsFromHomogeneous(X4.t(), X);
    cv::Mat rvec, tvec, inliers;
    if (!cv::solvePnPRansac(X, s.points3, s.cameraMatrices[2], cv::noArray(), rvec, tvec, false, 10000,
                            (float)(2.0 * threshold), 0.999, inliers, cv::SOLVEPNP_AP3P) ||
        inliers.rows < 4)
        return false;
    cv::Mat Xin(inliers.rows, 1, CV_64FC3), xin(inliers.rows, 1, CV_64FC2);
    for (int i = 0; i < inliers.rows; ++i)
    {
        const int k = inliers.at<int>(i);
        Xin.at<cv::Vec3d>(i) = X.at<cv::Vec3d>(k);
        const double* x = s.points3.ptr<double>(k); // Nx2 CV_64F
        xin.at<cv::Vec2d>(i) = cv::Vec2d(x[0], x[1]);
    }
    cv::solvePnPRefineLM(Xin, xin, s.cameraMatrices[2], cv::noArray(), rvec, tvec);
    cv::Rodrigues(rvec, R);
    t = tvec;
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    Options o;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string arg = argv[i], value = argv[i + 1];
        if (arg == "--scenes") o.scenes = std::stoi(value);
        else if (arg == "--repeats") o.repeats = std::stoi(value);
        else if (arg == "--points") o.points = std::stoi(value);
        else if (arg == "--lines") o.lines = std::stoi(value);
        else if (arg == "--outliers") o.outliers = std::stod(value);
        else if (arg == "--noise") o.noise = std::stod(value);
        else if (arg == "--threshold") o.threshold = std::stod(value);
        else { std::fprintf(stderr, "unknown argument %s\n", arg.c_str()); return 1; }
    }
    if (o.scenes < 1 || o.repeats < 1 || o.points < 4 || o.lines < 0 || !(o.outliers >= 0 && o.outliers < 1) ||
        !(o.threshold > 0))
    {
        std::fprintf(stderr, "--scenes, --repeats >= 1, --points >= 4, --lines >= 0, --outliers in [0, 1), --threshold > 0\n");
        return 1;
    }
    cv::setNumThreads(1);

    typedef std::function<bool(const cv::tripose::support::SyntheticScene&, int, cv::Mat&, cv::Mat&)> Solver;
    const std::vector<std::pair<std::string, Solver>> methods = {
        { "tripose RANSAC+refine", [&o](const cv::tripose::support::SyntheticScene& s, int seed, cv::Mat& R, cv::Mat& t) {
              cv::tripose::RansacParams params;
              params.threshold = o.threshold;
              params.seed = seed;
              params.minInliers = 0; // the estimator's time is measured, whatever its support
              return cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                              s.lines3, s.cameraMatrices, cv::noArray(), s.R12, s.t12,
                                                              R, t, params) > 0;
          } },
        { "tri+PnPRansac+RefineLM", [&o](const cv::tripose::support::SyntheticScene& s, int, cv::Mat& R, cv::Mat& t) {
              return triangulatePnPRansacRefine(s, o.threshold, R, t);
          } },
    };
    const size_t M = methods.size();

    std::vector<std::vector<double>> times(M), rot(M), trans(M);
    std::vector<int> good(M, 0);
    for (int k = 0; k < o.scenes; ++k)
    {
        cv::tripose::support::SyntheticSceneParams params;
        params.numPoints = o.points;
        params.numLines = o.lines;
        params.noiseSigma = o.noise;
        params.outlierRatio = o.outliers;
        params.seed = 2000 + k;
        const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
        std::vector<double> sceneTimes;
        std::vector<cv::tripose::support::PoseError> sceneErrors;
        tripose_benchmark::runInterleaved(s, k, methods, o.repeats, 1e3, sceneTimes, sceneErrors);
        for (size_t m = 0; m < M; ++m)
        {
            times[m].push_back(sceneTimes[m]);
            const double r = sceneErrors[m].rotationDeg, tr = sceneErrors[m].relativeTranslation;
            rot[m].push_back(r);
            trans[m].push_back(tr);
            good[m] += r < 1.0 && tr < 0.05;
        }
    }

    std::printf("%d scenes x %d repeats: %d points + %d lines, %.0f %% outliers in view 3, noise %.2f px, "
                "threshold %.2f px, one thread\n",
                o.scenes, o.repeats, o.points, o.lines, 100.0 * o.outliers, o.noise, o.threshold);
    std::printf("%-24s | %12s | %8s | %14s | %14s | %s\n", "method", "median (ms)", "ratio", "rotation (deg)",
                "translation", "within 1 deg & 5 %");
    const double base = tripose_benchmark::median(times[0]);
    for (size_t m = 0; m < M; ++m)
    {
        const double tm = tripose_benchmark::median(times[m]);
        std::printf("%-24s | %12.2f | x%7.2f | %14.3f | %14.4f | %d/%d\n", methods[m].first.c_str(), tm, tm / base,
                    tripose_benchmark::median(rot[m]), tripose_benchmark::median(trans[m]), good[m], o.scenes);
    }
    std::printf("ratio = method time / tripose time (> 1: tripose is faster); medians of the per-scene medians\n");
    return tripose_benchmark::failureStatus();
}
