// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_stereo_benchmark: median time per call of the stereo-rig estimators beside what a user
// without them would run on the same scenes, in one process, one thread: triangulate the points
// from the rig at time A (views 1-2), then cv::solvePnP (SQPnP) in view 3 on the points it sees,
// or, with outliers, cv::solvePnPRansac + cv::solvePnPRefineLM. Rows: the linear solver at 4+4 and
// 10+10 features (alone and followed by refinePoseLinePointStereo), the robust estimator at 100
// points + 40 lines with half of them wrong matches at time B. Scenes: the support library's rig
// (baseline 0.1-0.5 m, depths 5-30 m), 1 px noise, a fifth of the features seen by one time-B view.
// Printed: median time, ratio to the first method of the row, median rotation and translation
// errors (failures count as infinite).
//
//   tripose_stereo_benchmark [--scenes 100] [--repeats 10] [--ransac-scenes 20] [--noise 1.0]

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
#include "tripose_support/synthetic_stereo_scene.hpp"

namespace {

using Scene = cv::tripose::support::SyntheticStereoScene;
typedef std::function<bool(const Scene&, int, cv::Mat&, cv::Mat&)> Solver;

//! The points seen by view 3 (rows without NaN), triangulated from views 1-2, and their view-3 pixels.
void pointsSeenInView3(const Scene& s, cv::Mat& X, cv::Mat& x3)
{
    const cv::Mat P1 = s.cameraMatrices[0] * cv::Mat::eye(3, 4, CV_64F);
    cv::Mat Rt2;
    cv::hconcat(s.R12, s.t12, Rt2);
    const cv::Mat P2 = s.cameraMatrices[1] * Rt2;
    cv::Mat X4, all;
    cv::triangulatePoints(P1, P2, s.points1.t(), s.points2.t(), X4);
    cv::convertPointsFromHomogeneous(X4.t(), all);
    X.release();
    x3.release();
    for (int i = 0; i < s.points3.rows; ++i)
        if (!std::isnan(s.points3.at<double>(i, 0)))
        {
            X.push_back(all.row(i));
            x3.push_back(s.points3.row(i).reshape(2));
        }
}

bool triangulateThenSQPnP(const Scene& s, cv::Mat& R, cv::Mat& t)
{
    cv::Mat X, x3, rvec, tvec;
    pointsSeenInView3(s, X, x3);
    if (X.rows < 3 || !cv::solvePnP(X, x3, s.cameraMatrices[2], cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_SQPNP))
        return false;
    cv::Rodrigues(rvec, R);
    t = tvec;
    return true;
}

bool triangulatePnPRansacRefine(const Scene& s, cv::Mat& R, cv::Mat& t)
{
    cv::Mat X, x3, rvec, tvec, inliers;
    pointsSeenInView3(s, X, x3);
    // Threshold 4 px: the triangulated points carry the error of two views (tripose samples at 2 x 2 px).
    if (X.rows < 4 || !cv::solvePnPRansac(X, x3, s.cameraMatrices[2], cv::noArray(), rvec, tvec, false, 10000, 4.0f,
                                          0.999, inliers, cv::SOLVEPNP_AP3P) || inliers.rows < 4)
        return false;
    cv::Mat Xin, xin;
    for (int i = 0; i < inliers.rows; ++i)
    {
        Xin.push_back(X.row(inliers.at<int>(i)));
        xin.push_back(x3.row(inliers.at<int>(i)));
    }
    cv::solvePnPRefineLM(Xin, xin, s.cameraMatrices[2], cv::noArray(), rvec, tvec);
    cv::Rodrigues(rvec, R);
    t = tvec;
    return true;
}

void runRow(const char* label, int points, int lines, double outliers, double noise, int scenes, int repeats,
            const std::vector<std::pair<std::string, Solver>>& methods)
{
    const size_t M = methods.size();
    std::vector<std::vector<double>> times(M), rot(M), trans(M);
    for (int k = 0; k < scenes; ++k)
    {
        cv::tripose::support::SyntheticStereoParams params;
        params.numPoints = points;
        params.numLines = lines;
        params.noiseSigma = noise;
        params.outlierRatio = outliers;
        params.missingRatio = 0.2;
        params.seed = 3000 + k;
        const Scene s = cv::tripose::support::generateSyntheticStereoScene(params);
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
    const double base = tripose_benchmark::median(times[0]);
    for (size_t m = 0; m < M; ++m)
    {
        const double tm = tripose_benchmark::median(times[m]);
        std::printf("%-14s | %-24s | %10.1f | x%6.2f | %14.3f | %11.4f\n", m == 0 ? label : "",
                    methods[m].first.c_str(), tm, tm / base, tripose_benchmark::median(rot[m]),
                    tripose_benchmark::median(trans[m]));
    }
}

} // namespace

int main(int argc, char** argv)
{
    int scenes = 100, repeats = 10, ransacScenes = 20;
    double noise = 1.0;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string arg = argv[i], value = argv[i + 1];
        if (arg == "--scenes") scenes = std::stoi(value);
        else if (arg == "--repeats") repeats = std::stoi(value);
        else if (arg == "--ransac-scenes") ransacScenes = std::stoi(value);
        else if (arg == "--noise") noise = std::stod(value);
        else { std::fprintf(stderr, "unknown argument %s\n", arg.c_str()); return 1; }
    }
    if (scenes < 1 || repeats < 1 || ransacScenes < 1 || !(noise >= 0))
    {
        std::fprintf(stderr, "--scenes, --repeats, --ransac-scenes must be >= 1 and --noise >= 0\n");
        return 1;
    }
    cv::setNumThreads(1);

    const Solver linear = [](const Scene& s, int, cv::Mat& R, cv::Mat& t) {
        return cv::tripose::estimatePoseLinePointStereo(s.points1, s.points2, s.points3, s.points4, s.lines1, s.lines2,
                                                        s.lines3, s.lines4, s.cameraMatrices, cv::noArray(), s.R12,
                                                        s.t12, R, t) > 0;
    };
    const Solver linearRefine = [&linear](const Scene& s, int k, cv::Mat& R, cv::Mat& t) {
        return linear(s, k, R, t) &&
               std::isfinite(cv::tripose::refinePoseLinePointStereo(s.points1, s.points2, s.points3, s.points4,
                                                                    s.lines1, s.lines2, s.lines3, s.lines4,
                                                                    s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t));
    };
    const Solver sqpnp = [](const Scene& s, int, cv::Mat& R, cv::Mat& t) { return triangulateThenSQPnP(s, R, t); };
    const Solver ransac = [](const Scene& s, int seed, cv::Mat& R, cv::Mat& t) {
        cv::tripose::RansacParams params;
        params.seed = seed;
        params.minInliers = 0; // the estimator's time is measured, whatever its support
        return cv::tripose::estimatePoseLinePointStereoRansac(s.points1, s.points2, s.points3, s.points4, s.lines1,
                                                              s.lines2, s.lines3, s.lines4, s.cameraMatrices,
                                                              cv::noArray(), s.R12, s.t12, R, t, params) > 0;
    };
    const Solver pnpRansac = [](const Scene& s, int, cv::Mat& R, cv::Mat& t) {
        return triangulatePnPRansacRefine(s, R, t);
    };

    std::printf("stereo rig, noise %.2f px, 20 %% of the features seen by one time-B view, one thread; "
                "linear rows %d scenes x %d repeats, RANSAC row %d scenes x %d repeats\n",
                noise, scenes, repeats, ransacScenes, repeats);
    std::printf("%-14s | %-24s | %10s | %7s | %14s | %11s\n", "features", "method", "median (us)", "ratio",
                "rotation (deg)", "translation");
    runRow("4P+4L", 4, 4, 0.0, noise, scenes, repeats,
           { { "stereo linear", linear }, { "stereo linear+refine", linearRefine }, { "tri(1-2)+SQPnP(3)", sqpnp } });
    runRow("10P+10L", 10, 10, 0.0, noise, scenes, repeats,
           { { "stereo linear", linear }, { "stereo linear+refine", linearRefine }, { "tri(1-2)+SQPnP(3)", sqpnp } });
    runRow("100P+40L 50%", 100, 40, 0.5, noise, ransacScenes, repeats,
           { { "stereo RANSAC+refine", ransac }, { "tri+PnPRansac+RefineLM", pnpRansac } });
    std::printf("ratio = method time / the row's first method's time; medians of the per-scene medians\n");
    return tripose_benchmark::failureStatus();
}
