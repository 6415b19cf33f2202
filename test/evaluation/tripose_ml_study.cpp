// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_ml_study: does the estimator reach the three-view maximum-likelihood optimum? For each
// synthetic regime (large, small, narrow known pair, planar structure) and feature mix it runs
// RANSAC + refinement and the linear solver + refinement, and compares them with refinement started
// from the true pose (the accuracy limit): median rotation errors, and the fraction of scenes whose
// final estimate is that optimum.
//
//   tripose_ml_study [--trials T] [--seed S] [--noise px] [--threshold px] [--regimes list]
//                    [--mixes list] [--csv] [--time]
//
// Regimes (--regimes, comma separated; default all): large, small, narrow1 (view 2 at 1 % of the
// depth from view 1, view 3 by small motion), narrow05 (0.5 %), planar_large, planar_small (one
// plane tilted 30 degrees). Mixes (--mixes): 4+4, 10+10 (points+lines; default both).
//
// The RMS of a final estimate is the one that refinePoseLinePoint reaches when started from it;
// the estimate is at the optimum when that RMS is within 1e-3 px of the RMS reached from the truth
// and its rotation within 1e-3 degrees of the optimum's (the same minimum, not just an equally good
// one).
//
// --time adds the estimators' median time per scene (microseconds, the call alone, one thread): run
// two builds side by side in one session to compare them (doc/studies/speed.md).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

#include "tripose_support/pose_error.hpp"
#include "tripose_support/synthetic_scene.hpp"

namespace {

namespace ts = cv::tripose::support;

const char* kUsage =
    "usage: tripose_ml_study [--trials T] [--seed S] [--noise px] [--threshold px] [--regimes list]\n"
    "                        [--mixes list] [--csv] [--time]\n"
    "regimes: large, small, narrow1, narrow05, planar_large, planar_small (default: all)\n"
    "mixes: 4+4, 10+10 (default: both)\n";

struct Regime
{
    std::string name;
    int motion;
    double baselineFraction;
    bool planar;
};

const std::vector<Regime> kRegimes = {
    { "large", ts::MOTION_LARGE, 0.0, false },        { "small", ts::MOTION_SMALL, 0.0, false },
    { "narrow1", ts::MOTION_SMALL, 0.01, false },     { "narrow05", ts::MOTION_SMALL, 0.005, false },
    { "planar_large", ts::MOTION_LARGE, 0.0, true },  { "planar_small", ts::MOTION_SMALL, 0.0, true },
};

struct Options
{
    int trials = 200, seed = 0;
    double noise = 1.0, threshold = 4.0;
    std::vector<std::string> regimes, mixes = { "4+4", "10+10" };
    bool csv = false, time = false;
};

std::vector<std::string> splitList(const std::string& s)
{
    std::vector<std::string> out;
    size_t start = 0;
    while (start <= s.size())
    {
        const size_t comma = s.find(',', start);
        const size_t end = comma == std::string::npos ? s.size() : comma;
        if (end > start)
            out.push_back(s.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

Options parse(int argc, char** argv)
{
    Options o;
    for (const Regime& r : kRegimes)
        o.regimes.push_back(r.name);
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::fputs(kUsage, stdout);
            std::exit(0);
        }
        if (arg == "--csv" || arg == "--time")
        {
            (arg == "--csv" ? o.csv : o.time) = true;
            continue;
        }
        if (i + 1 >= argc)
            throw std::runtime_error("argument " + arg + " needs a value\n" + kUsage);
        const std::string v = argv[++i];
        if (arg == "--trials")
            o.trials = std::stoi(v);
        else if (arg == "--seed")
            o.seed = std::stoi(v);
        else if (arg == "--noise")
            o.noise = std::stod(v);
        else if (arg == "--threshold")
            o.threshold = std::stod(v);
        else if (arg == "--regimes")
            o.regimes = splitList(v);
        else if (arg == "--mixes")
            o.mixes = splitList(v);
        else
            throw std::runtime_error("unknown argument " + arg + "\n" + kUsage);
    }
    if (o.trials <= 0)
        throw std::runtime_error("--trials must be positive");
    return o;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return std::nan("");
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

//! Refines (R, t) in place and returns the RMS reached.
double refineFrom(const ts::SyntheticScene& s, cv::Mat& R, cv::Mat& t)
{
    return cv::tripose::refinePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                            s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t);
}

struct Outcome
{
    std::vector<double> rot; //!< rotation error (deg) per scene; 180 where no pose was returned
    std::vector<double> micros; //!< time of the estimator's call per scene (us)
    int atOptimum = 0; //!< the same minimum as refinement from the truth
    int atOrBelow = 0; //!< a minimum whose RMS is at most 1e-3 px above that one's (possibly another, lower one)
    long inliers = 0;
};

//! Scores a final estimate against the optimum reached from the truth.
void score(const ts::SyntheticScene& s, bool ok, const cv::Mat& R, const cv::Mat& t, const cv::Mat& Rml,
           const cv::Mat& tml, double mlRms, Outcome& out)
{
    if (!ok || R.empty())
    {
        out.rot.push_back(180.0);
        return;
    }
    out.rot.push_back(ts::poseError(R, t, s.R, s.t).rotationDeg);
    cv::Mat Rr = R.clone(), tr = t.clone();
    const double rms = refineFrom(s, Rr, tr);
    const double apart = ts::poseError(R, t, Rml, tml).rotationDeg;
    if (std::abs(rms - mlRms) <= 1e-3 && apart <= 1e-3)
        ++out.atOptimum;
    if (rms <= mlRms + 1e-3)
        ++out.atOrBelow;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        const Options o = parse(argc, argv);
        if (o.csv)
            std::printf("regime,mix,trials,ransac_med,linref_med,ml_med,ransac_ratio,linref_ratio,"
                        "ransac_at_opt,linref_at_opt,ransac_at_or_below,linref_at_or_below,linear_med,"
                        "ransac_inliers%s\n", o.time ? ",ransac_us,linref_us" : "");
        else
            std::printf("| regime | mix | RANSAC + refine (deg) | linear + refine (deg) | ML limit (deg) | ratios | "
                        "same minimum (RANSAC, linear) | RMS at or below (RANSAC, linear) | linear alone (deg) |%s\n"
                        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |%s\n",
                        o.time ? " time (us: RANSAC, linear + refine) |" : "", o.time ? " --- |" : "");
        for (const std::string& regimeName : o.regimes)
        {
            const auto regime = std::find_if(kRegimes.begin(), kRegimes.end(),
                                              [&](const Regime& r) { return r.name == regimeName; });
            if (regime == kRegimes.end())
                throw std::runtime_error("unknown regime " + regimeName + "\n" + kUsage);
            for (const std::string& mix : o.mixes)
            {
                const size_t plus = mix.find('+');
                if (plus == std::string::npos)
                    throw std::runtime_error("mix " + mix + ": expected points+lines, e.g. 4+4");
                ts::SyntheticSceneParams params;
                params.numPoints = std::stoi(mix.substr(0, plus));
                params.numLines = std::stoi(mix.substr(plus + 1));
                params.motion = regime->motion;
                params.baseline12Fraction = regime->baselineFraction;
                params.planar = regime->planar;
                params.noiseSigma = o.noise;

                Outcome ransac, linref;
                std::vector<double> mlRot, linRot;
                for (int trial = 0; trial < o.trials; ++trial)
                {
                    params.seed = o.seed + trial;
                    const ts::SyntheticScene s = ts::generateSyntheticScene(params);
                    cv::Mat Rml = s.R.clone(), tml = s.t.clone();
                    const double mlRms = refineFrom(s, Rml, tml);
                    mlRot.push_back(ts::poseError(Rml, tml, s.R, s.t).rotationDeg);

                    cv::tripose::RansacParams rp;
                    rp.threshold = o.threshold;
                    cv::Mat R, t;
                    int64 start = cv::getTickCount();
                    const int inliers = cv::tripose::estimatePoseLinePointRansac(
                        s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3, s.cameraMatrices,
                        cv::noArray(), s.R12, s.t12, R, t, rp);
                    ransac.micros.push_back(1e6 * double(cv::getTickCount() - start) / cv::getTickFrequency());
                    score(s, inliers > 0, R, t, Rml, tml, mlRms, ransac);
                    ransac.inliers += inliers;

                    R.release();
                    t.release();
                    int n = cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                               s.lines3, s.cameraMatrices, cv::noArray(), s.R12,
                                                               s.t12, R, t, cv::tripose::POSE_LINEAR);
                    linRot.push_back(n > 0 ? ts::poseError(R, t, s.R, s.t).rotationDeg : 180.0);
                    R.release();
                    t.release();
                    start = cv::getTickCount();
                    n = cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2,
                                                           s.lines3, s.cameraMatrices, cv::noArray(), s.R12, s.t12,
                                                           R, t, cv::tripose::POSE_LINEAR_REFINE);
                    linref.micros.push_back(1e6 * double(cv::getTickCount() - start) / cv::getTickFrequency());
                    score(s, n > 0, R, t, Rml, tml, mlRms, linref);
                }
                const double ml = median(mlRot), ra = median(ransac.rot), li = median(linref.rot);
                if (o.csv)
                    std::printf("%s,%s,%d,%.4f,%.4f,%.4f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f",
                                regime->name.c_str(), mix.c_str(), o.trials, ra, li, ml, ra / ml, li / ml,
                                double(ransac.atOptimum) / o.trials, double(linref.atOptimum) / o.trials,
                                double(ransac.atOrBelow) / o.trials, double(linref.atOrBelow) / o.trials,
                                median(linRot), double(ransac.inliers) / o.trials);
                else
                    std::printf("| %s | %s | %.3f | %.3f | %.3f | %.3fx, %.3fx | %.1f %%, %.1f %% | %.1f %%, %.1f %% | %.3f |",
                                regime->name.c_str(), mix.c_str(), ra, li, ml, ra / ml, li / ml,
                                100.0 * ransac.atOptimum / o.trials, 100.0 * linref.atOptimum / o.trials,
                                100.0 * ransac.atOrBelow / o.trials, 100.0 * linref.atOrBelow / o.trials,
                                median(linRot));
                if (o.time)
                    std::printf(o.csv ? ",%.1f,%.1f" : " %.1f, %.1f |", median(ransac.micros), median(linref.micros));
                std::printf("\n");
                std::fflush(stdout);
            }
        }
        return 0;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "tripose_ml_study: %s\n", e.what());
        return 1;
    }
}
