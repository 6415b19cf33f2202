// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_benchmark: median time per call of estimatePoseLinePoint beside "triangulate the points
// from views 1-2, then cv::solvePnP(SOLVEPNP_SQPNP) in view 3" on the same scenes, in the same
// process, one thread; with the median rotation and translation errors of both so that speed is
// read together with accuracy.
//
//   tripose_benchmark [--scenes 200] [--repeats 20] [--noise 1.0] [--motion large|small]

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

namespace {

double median(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

double rotationErrorDeg(const cv::Mat& A, const cv::Mat& B)
{
    return 2.0 * std::asin(std::min(1.0, cv::norm(A, B) / (2.0 * std::sqrt(2.0)))) * 180.0 / CV_PI;
}

double translationError(const cv::Mat& a, const cv::Mat& b)
{
    return cv::norm(a, b) / cv::norm(b);
}

//! Triangulates the points from views 1-2 and solves PnP in view 3 (the baseline a user would write).
bool triangulateThenPnP(const cv::tripose::SyntheticScene& s, int flags, cv::Mat& R, cv::Mat& t)
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
    int motion = cv::tripose::MOTION_LARGE;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string arg = argv[i], value = argv[i + 1];
        if (arg == "--scenes") scenes = std::stoi(value);
        else if (arg == "--repeats") repeats = std::stoi(value);
        else if (arg == "--noise") noise = std::stod(value);
        else if (arg == "--motion") motion = value == "small" ? cv::tripose::MOTION_SMALL : cv::tripose::MOTION_LARGE;
        else { std::fprintf(stderr, "unknown argument %s\n", arg.c_str()); return 1; }
    }
    cv::setNumThreads(1);
    const int configs[][2] = { { 4, 4 }, { 5, 5 }, { 10, 10 }, { 20, 20 }, { 45, 45 } };
    std::printf("%d scenes x %d repeats, noise %.2f px, %s motion, one thread\n", scenes, repeats, noise,
                motion == cv::tripose::MOTION_LARGE ? "large" : "small");
    std::printf("%-8s | %12s %12s %8s | %10s %10s | %10s %10s\n", "features", "tripose us", "SQPnP us",
                "ratio", "rot tri", "rot SQPnP", "t tri", "t SQPnP");
    for (const auto& c : configs)
    {
        std::vector<double> ours, peer, rotOurs, rotPeer, tOurs, tPeer;
        for (int k = 0; k < scenes; ++k)
        {
            cv::tripose::SyntheticSceneParams params;
            params.numPoints = c[0];
            params.numLines = c[1];
            params.noiseSigma = noise;
            params.motion = motion;
            params.seed = 1000 + k;
            const cv::tripose::SyntheticScene s = cv::tripose::generateSyntheticScene(params);
            cv::Mat R, t, Rp, tp;
            // Interleave the two methods so that frequency changes hit both alike.
            std::vector<double> a, b;
            for (int r = 0; r < repeats; ++r)
            {
                int64 t0 = cv::getTickCount();
                cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                   s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t);
                int64 t1 = cv::getTickCount();
                triangulateThenPnP(s, cv::SOLVEPNP_SQPNP, Rp, tp);
                int64 t2 = cv::getTickCount();
                a.push_back(1e6 * double(t1 - t0) / cv::getTickFrequency());
                b.push_back(1e6 * double(t2 - t1) / cv::getTickFrequency());
            }
            ours.push_back(median(a));
            peer.push_back(median(b));
            if (!R.empty())
            {
                rotOurs.push_back(rotationErrorDeg(R, s.R));
                tOurs.push_back(translationError(t, s.t));
            }
            if (!Rp.empty())
            {
                rotPeer.push_back(rotationErrorDeg(Rp, s.R));
                tPeer.push_back(translationError(tp, s.t));
            }
        }
        const double mo = median(ours), mp = median(peer);
        std::printf("%2dP+%-2dL  | %12.2f %12.2f %8.2f | %10.4f %10.4f | %10.4f %10.4f\n", c[0], c[1], mo, mp,
                    mp / mo, median(rotOurs), median(rotPeer), median(tOurs), median(tPeer));
    }
    std::printf("ratio = SQPnP time / tripose time (> 1: tripose is faster); rot in degrees, t relative\n");
    return 0;
}
