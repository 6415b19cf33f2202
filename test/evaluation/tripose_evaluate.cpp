// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_evaluate: one experiment of the evaluation suite (doc/studies/evaluation.md) per invocation.
// Every trial is one JSON object on one line of stdout, so that a driver in any language reads
// the results as they come and runs further peers on exactly the same inputs.
//
//   synthetic scenes (Qadir & Neubert, Sec. IV-A):
//     tripose_evaluate synthetic --points N --lines M --noise px [--motion large|small]
//                      [--baseline12-fraction f] [--planar] [--outliers ratio] [--trials T] [--seed S]
//                      [--repeats K] [--threshold px] [--methods list] [--dump-inputs]
//   (--baseline12-fraction: view 2 at that fraction of the 20 m depth from view 1; --planar: all
//   structure on one plane tilted 30 degrees from view 1; SyntheticSceneParams has the details)
//   synthetic stereo-rig scenes (four views: the rig at times A and B; SyntheticStereoParams'
//   defaults: baseline 0.1-0.5 m, depth 5-30 m, motion 0.3-3 m):
//     tripose_evaluate stereo --points N --lines M --noise px [--outliers ratio] [--missing ratio]
//                      [--trials T] [--seed S] [--repeats K] [--threshold px] [--methods list] [--dump-inputs]
//   (--missing: the fraction of the features seen by only one of the two time-B views)
//   random subsets of a VGG multi-view sequence (Sec. IV-B):
//     tripose_evaluate vgg --sequence DIR [--views a,b,c] --points N --lines M
//                      [--trials T] [--seed S] [--repeats K] [--threshold px] [--methods list]
//                      [--dump-inputs]
//   synthetic registration against several known views (SyntheticMultiViewScene: V known views and
//   a new one about 20 m around a 10 m cube, every feature seen by the new view and at least two
//   known views; wrong matches replace observations of the new view):
//     tripose_evaluate multiview --known V --points N --lines M --noise px [--outliers ratio]
//                      [--trials T] [--seed S] [--repeats K] [--threshold px] [--methods list] [--dump-inputs]
//
// Methods (--methods, comma separated; default all that apply):
//   linear         estimatePoseLinePoint (the paper's linear solver)
//   linear+refine  refinePoseLinePoint started from the linear estimate
//   ransac         estimatePoseLinePointRansac (robust + refined), threshold --threshold px
//   ml_from_truth  refinePoseLinePoint started from the ground truth, on the true matches of synthetic
//                  scenes (every feature elsewhere): the accuracy limit
//   tri+sqpnp      points triangulated from views 1-2, then cv::solvePnP(SOLVEPNP_SQPNP), >= 3 points
//   tri+epnp       the same with SOLVEPNP_EPNP, >= 4 points
// Methods of the stereo experiment (views 1-2: the rig at time A, views 3-4: at time B):
//   stereo_linear             estimatePoseLinePointStereo, POSE_LINEAR
//   stereo_multi_start        estimatePoseLinePointStereo, POSE_LINEAR_REFINE (every candidate refined,
//                             further starts where the cost has several basins)
//   stereo_linear+refine      refinePoseLinePointStereo started from the stereo_linear estimate
//   stereo_ransac             estimatePoseLinePointStereoRansac (robust + refined), threshold --threshold px
//   stereo_ml_from_truth      refinePoseLinePointStereo started from the ground truth, on the true
//                             matches: the four-view limit
//   three_view_ransac         ransac on views 1-3 only (the right image at B unused)
//   three_view_linear+refine  linear+refine on views 1-3 only
//   tri+sqpnp                 as above, in view 3 (the left image at B)
//   tri+iterative             the same with SOLVEPNP_ITERATIVE, >= 6 points (its DLT start needs them)
// Methods of the multiview experiment:
//   multiview_ransac          estimatePoseMultiViewRansac (robust + refined), threshold --threshold px
// Per method: rot_deg (angle of R_est R_gt^T), t_rel (|t - t_gt| / |t_gt|), time_us (median of
// --repeats calls, one thread), ok. With --dump-inputs each line also carries the inputs and the
// structure triangulated from views 1-2 (points and lines, with the time that took), which is
// what the PoseLib peers of the Python driver consume (for stereo: view 3, the left image at B, against
// the structure triangulated from the rig at A; the time-B right image is dumped too; "rig_inputs"
// holds the same for every feature of the rig, NaN rows where a time-B view does not see one;
// synthetic scenes add "true_point_matches" and "true_line_matches", 1 for a true match, 0 for a wrong one).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

#include "tripose_support/json_writing.hpp"
#include "tripose_support/known_pair_structure.hpp"
#include "tripose_support/pose_error.hpp"
#include "tripose_support/synthetic_multiview_scene.hpp"
#include "tripose_support/synthetic_scene.hpp"
#include "tripose_support/synthetic_stereo_scene.hpp"
#include "tripose_support/vgg_dataset.hpp"

namespace {

const char* kUsage =
    "usage: tripose_evaluate synthetic --points N --lines M --noise px [--motion large|small]\n"
    "                        [--baseline12-fraction f] [--planar]\n"
    "                        [--outliers ratio] [--trials T] [--seed S] [--repeats K]\n"
    "                        [--threshold px] [--methods list] [--dump-inputs]\n"
    "       tripose_evaluate stereo --points N --lines M --noise px [--outliers ratio] [--missing ratio]\n"
    "                        [--trials T] [--seed S] [--repeats K] [--threshold px] [--methods list] [--dump-inputs]\n"
    "       tripose_evaluate vgg --sequence DIR [--views a,b,c] --points N --lines M [--trials T]\n"
    "                        [--seed S] [--repeats K] [--threshold px] [--methods list] [--dump-inputs]\n"
    "       tripose_evaluate multiview --known V --points N --lines M --noise px [--outliers ratio]\n"
    "                        [--trials T] [--seed S] [--repeats K] [--threshold px] [--methods list] [--dump-inputs]\n"
    "methods: linear, linear+refine, ransac, ml_from_truth, tri+sqpnp, tri+epnp (default: all)\n"
    "stereo methods: stereo_linear, stereo_multi_start, stereo_linear+refine, stereo_ransac,\n"
    "                stereo_ml_from_truth, three_view_ransac, three_view_linear+refine, tri+sqpnp,\n"
    "                tri+iterative (default: all)\n"
    "multiview methods: multiview_ransac (default: all)\n";

const std::vector<std::string> kAllMethods = { "linear", "linear+refine", "ransac", "ml_from_truth", "tri+sqpnp",
                                               "tri+epnp" };
const std::vector<std::string> kStereoMethods = { "stereo_linear", "stereo_multi_start", "stereo_linear+refine",
                                                  "stereo_ransac", "stereo_ml_from_truth", "three_view_ransac",
                                                  "three_view_linear+refine", "tri+sqpnp", "tri+iterative" };
const std::vector<std::string> kMultiViewMethods = { "multiview_ransac" };

struct Options
{
    std::string source;  // "synthetic", "stereo", "vgg" or "multiview"
    int points = 4, lines = 4, trials = 20, seed = 0, repeats = 1, known = 4;
    double noise = 0.0, outliers = 0.0, missing = 0.0, threshold = -1.0, baseline12Fraction = 0.0;
    bool planar = false;
    int motion = cv::tripose::support::MOTION_LARGE;
    std::string sequence;
    int views[3] = { 0, 1, 2 };
    std::vector<std::string> methods;  // empty: every method of the source
    bool dumpInputs = false;
};

//! One three-view (or four-view stereo) problem with its ground truth, whatever produced it.
struct Problem
{
    cv::Mat points1, points2, points3, lines1, lines2, lines3;  // Nx2, Mx4, CV_64F
    cv::Mat points4, lines4;                                     // stereo only: the right image at time B
    std::vector<cv::Mat> K;                                      // three 3x3 (four for stereo)
    cv::Mat R12, t12, R, t;                                      // R, t: ground truth of view 3
    cv::Mat pointInliers, lineInliers;                           // synthetic: Nx1 / Mx1 CV_8U, 1 for a true match
    // multiview only: every view's observations (the known views, then the new one; NaN rows where a
    // view does not see a feature) and the known views' world poses; R, t: the new view's. K: one matrix.
    std::vector<cv::Mat> viewPoints, viewLines, knownRs, knownTs;

    bool stereo() const { return K.size() == 4; }
    bool multiView() const { return !knownRs.empty(); }
    //! The cameras of views 1-3, what the three-view functions take.
    std::vector<cv::Mat> threeViewCameras() const { return std::vector<cv::Mat>(K.begin(), K.begin() + 3); }
};

std::vector<std::string> split(const std::string& s, char sep)
{
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, sep))
        if (!item.empty())
            out.push_back(item);
    return out;
}

Options parse(int argc, char** argv)
{
    if (argc < 2)
        throw std::runtime_error("missing experiment kind (synthetic, stereo, vgg or multiview)");
    Options o;
    o.source = argv[1];
    if (o.source != "synthetic" && o.source != "stereo" && o.source != "vgg" && o.source != "multiview")
        throw std::runtime_error("experiment kind must be synthetic, stereo, vgg or multiview, got " + o.source);
    const std::vector<std::string>& known = o.source == "stereo"      ? kStereoMethods
                                            : o.source == "multiview" ? kMultiViewMethods
                                                                      : kAllMethods;
    o.methods = known;
    for (int i = 2; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--dump-inputs") { o.dumpInputs = true; continue; }
        if (arg == "--planar") { o.planar = true; continue; }
        if (i + 1 >= argc)
            throw std::runtime_error("argument " + arg + ": missing value");
        const std::string v = argv[++i];
        if (arg == "--points") o.points = std::stoi(v);
        else if (arg == "--lines") o.lines = std::stoi(v);
        else if (arg == "--known") o.known = std::stoi(v);
        else if (arg == "--trials") o.trials = std::stoi(v);
        else if (arg == "--seed") o.seed = std::stoi(v);
        else if (arg == "--repeats") o.repeats = std::stoi(v);
        else if (arg == "--noise") o.noise = std::stod(v);
        else if (arg == "--outliers") o.outliers = std::stod(v);
        else if (arg == "--missing") o.missing = std::stod(v);
        else if (arg == "--baseline12-fraction") o.baseline12Fraction = std::stod(v);
        else if (arg == "--threshold") o.threshold = std::stod(v);
        else if (arg == "--sequence") o.sequence = v;
        else if (arg == "--motion")
        {
            if (v != "large" && v != "small")
                throw std::runtime_error("argument --motion: expected large or small, got " + v);
            o.motion = v == "small" ? cv::tripose::support::MOTION_SMALL : cv::tripose::support::MOTION_LARGE;
        }
        else if (arg == "--views")
        {
            const std::vector<std::string> parts = split(v, ',');
            if (parts.size() != 3)
                throw std::runtime_error("argument --views: expected three indices a,b,c, got " + v);
            for (int k = 0; k < 3; ++k)
                o.views[k] = std::stoi(parts[k]);
        }
        else if (arg == "--methods")
        {
            o.methods = split(v, ',');
            for (const std::string& m : o.methods)
                if (std::find(known.begin(), known.end(), m) == known.end())
                    throw std::runtime_error("argument --methods: unknown method " + m + " for " + o.source);
        }
        else
            throw std::runtime_error("unknown argument " + arg);
    }
    if (o.points < 0 || o.lines < 0 || o.points + o.lines < 4)
        throw std::runtime_error("arguments --points/--lines: need at least four features in all");
    if (o.trials < 1 || o.repeats < 1)
        throw std::runtime_error("arguments --trials/--repeats: expected >= 1");
    if (o.source == "stereo" && (o.planar || o.baseline12Fraction != 0.0 || !o.sequence.empty()))
        throw std::runtime_error("arguments --planar, --baseline12-fraction, --sequence: not for stereo");
    if (o.source != "stereo" && o.missing != 0.0)
        throw std::runtime_error("argument --missing: stereo only");
    if (o.source == "multiview" && (o.planar || o.baseline12Fraction != 0.0 || !o.sequence.empty()))
        throw std::runtime_error("arguments --planar, --baseline12-fraction, --sequence: not for multiview");
    if (o.source == "multiview" && o.known < 2)
        throw std::runtime_error("argument --known: expected >= 2");
    if (o.source == "multiview" && !(o.outliers >= 0 && o.outliers < 1))
        throw std::runtime_error("argument --outliers: expected a ratio in [0, 1)");
    if (o.source == "vgg" && o.sequence.empty())
        throw std::runtime_error("argument --sequence: required for vgg");
    if (o.threshold <= 0)  // A fixed 2 px would drop inliers at high noise; 3 sigma keeps ~99% of them.
        o.threshold = std::max(2.0, 3.0 * o.noise);
    return o;
}

// ---------------------------------------------------------------------------------------------
// Statistics

double medianOf(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// ---------------------------------------------------------------------------------------------
// Triangulation from views 1-2: the structure the PnP peers work with.

//! Nx3 points triangulated (DLT) from views 1 and 2.
cv::Mat triangulatePoints12(const Problem& p)
{
    return cv::tripose::support::triangulateKnownPair(cv::Matx33d(p.K[0]), cv::Matx33d(p.K[1]), cv::Matx33d(p.R12),
                                                      cv::Vec3d(p.t12), p.points1, p.points2);
}

//! Mx6 3D segments from views 1 and 2 (NaN end points where the view-1 ray runs parallel to the
//! plane of the view-2 line: the line is not determined by views 1-2).
cv::Mat triangulateLines12(const Problem& p)
{
    return cv::tripose::support::liftSegmentsKnownPair(cv::Matx33d(p.K[0]), cv::Matx33d(p.K[1]), cv::Matx33d(p.R12),
                                                       cv::Vec3d(p.t12), p.lines1, p.lines2, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Problem sources

//! The three-view part of a problem from anything with the support library's field names (a
//! synthetic scene, a stereo scene, a VGG triplet).
template <typename Source>
Problem threeViewProblem(const Source& s)
{
    Problem p;
    p.points1 = s.points1; p.points2 = s.points2; p.points3 = s.points3;
    p.lines1 = s.lines1; p.lines2 = s.lines2; p.lines3 = s.lines3;
    p.K = s.cameraMatrices;
    p.R12 = s.R12; p.t12 = s.t12; p.R = s.R; p.t = s.t;
    return p;
}

Problem syntheticProblem(const Options& o, int trial)
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = o.points;
    params.numLines = o.lines;
    params.motion = o.motion;
    params.noiseSigma = o.noise;
    params.outlierRatio = o.outliers;
    params.baseline12Fraction = o.baseline12Fraction;
    params.planar = o.planar;
    params.seed = o.seed + trial;
    const cv::tripose::support::SyntheticScene s = cv::tripose::support::generateSyntheticScene(params);
    Problem p = threeViewProblem(s);
    p.pointInliers = s.pointInliers;
    p.lineInliers = s.lineInliers;
    return p;
}

Problem syntheticStereoProblem(const Options& o, int trial)
{
    cv::tripose::support::SyntheticStereoParams params;  // the rig, depths and motion of its defaults
    params.numPoints = o.points;
    params.numLines = o.lines;
    params.noiseSigma = o.noise;
    params.outlierRatio = o.outliers;
    params.missingRatio = o.missing;
    params.seed = o.seed + trial;
    const cv::tripose::support::SyntheticStereoScene s = cv::tripose::support::generateSyntheticStereoScene(params);
    Problem p = threeViewProblem(s);
    p.points4 = s.points4;
    p.lines4 = s.lines4;
    p.pointInliers = s.pointInliers;
    p.lineInliers = s.lineInliers;
    return p;
}

//! k distinct row indices out of n, drawn by a partial Fisher-Yates shuffle (same seed, same rows).
std::vector<int> drawRows(int n, int k, cv::RNG& rng)
{
    std::vector<int> idx(n);
    for (int i = 0; i < n; ++i)
        idx[i] = i;
    for (int i = 0; i < k; ++i)
        std::swap(idx[i], idx[i + (int)rng.uniform(0, n - i)]);
    idx.resize(k);
    return idx;
}

cv::Mat selectRows(const cv::Mat& m, const std::vector<int>& rows)
{
    if (m.empty())
        return m;  // a view a problem does not have (points4, lines4 of a three-view problem)
    cv::Mat out(0, m.cols, m.type());
    for (int r : rows)
        out.push_back(m.row(r));
    return out.empty() ? cv::Mat(0, m.cols, CV_64F) : out;
}

//! The rows of @p m that are finite (a NaN row: a feature the view does not see).
std::vector<int> finiteRows(const cv::Mat& m)
{
    std::vector<int> rows;
    for (int r = 0; r < m.rows; ++r)
        if (cv::checkRange(m.row(r)))
            rows.push_back(r);
    return rows;
}

//! The points @p pr and lines @p lr of @p p, in every view.
Problem selectFeatures(const Problem& p, const std::vector<int>& pr, const std::vector<int>& lr)
{
    Problem q = p;
    q.points1 = selectRows(p.points1, pr); q.points2 = selectRows(p.points2, pr); q.points3 = selectRows(p.points3, pr);
    q.points4 = selectRows(p.points4, pr);
    q.lines1 = selectRows(p.lines1, lr); q.lines2 = selectRows(p.lines2, lr); q.lines3 = selectRows(p.lines3, lr);
    q.lines4 = selectRows(p.lines4, lr);
    q.pointInliers = selectRows(p.pointInliers, pr);
    q.lineInliers = selectRows(p.lineInliers, lr);
    return q;
}

//! The rows of @p mask that are non-zero; every row of @p all where there is no mask.
std::vector<int> trueRows(const cv::Mat& mask, const cv::Mat& all)
{
    std::vector<int> rows;
    for (int r = 0; r < all.rows; ++r)
        if (mask.empty() || mask.at<uchar>(r) != 0)
            rows.push_back(r);
    return rows;
}

//! The true matches of @p p (all of its features where it has no inlier masks).
Problem trueMatches(const Problem& p)
{
    return selectFeatures(p, trueRows(p.pointInliers, p.points1), trueRows(p.lineInliers, p.lines1));
}

/** The features of a stereo problem that view 3 (the left image at B) sees: what the three-view
methods and the PnP peers, which use views 1-3 only, are given. */
Problem seenInView3(const Problem& p)
{
    return selectFeatures(p, finiteRows(p.points3), finiteRows(p.lines3));
}

/** A SyntheticMultiViewScene of --known views with 1 px (--noise) of noise, and round(ratio x count) of
the new view's point and line observations each replaced by a random wrong match: a random point of
the 640 x 480 image at least 20 px from the true one, a random segment with an end point at least
20 px from the true line (as the three-view synthetic scenes make them). */
Problem multiViewProblem(const Options& o, int trial)
{
    const uint64 seed = (uint64)(o.seed + trial);
    cv::tripose::support::SyntheticMultiViewScene s(o.known, o.points, o.lines, seed);
    s.addNoise(o.noise, 0x9E3779B97F4A7C15ull ^ seed);
    Problem p;
    p.viewPoints = s.points;
    p.viewLines = s.lines;
    p.knownRs = s.Rs;
    p.knownTs = s.ts;
    p.K = { cv::Mat(s.K, true) };
    p.R = cv::Mat(s.R, true);
    p.t = cv::Mat(s.t, true);
    p.pointInliers = cv::Mat(o.points, 1, CV_8U, cv::Scalar(1));
    p.lineInliers = cv::Mat(o.lines, 1, CV_8U, cv::Scalar(1));
    cv::RNG rng(0xC2B2AE3D27D4EB4Full ^ seed);
    // One draw per statement, as C++ leaves the order of arguments unspecified: y before x is the order
    // the documented seeded trials were drawn in (GCC's, right to left).
    const auto randomPixel = [&rng]() {
        const double y = rng.uniform(0.0, 480.0);
        const double x = rng.uniform(0.0, 640.0);
        return cv::Point2d(x, y);
    };
    const auto lineDistance = [](const cv::Point2d& x, const cv::Point2d& a, const cv::Point2d& b) {
        const cv::Point2d d = b - a;
        return std::abs(d.cross(x - a)) / std::max(cv::norm(d), 1e-12);
    };
    std::vector<int> order = drawRows(o.points, (int)std::lround(o.outliers * o.points), rng);
    for (int i : order)
    {
        double* x = p.viewPoints.back().ptr<double>(i);
        const cv::Point2d truth(x[0], x[1]);
        cv::Point2d wrong;
        do
            wrong = randomPixel();
        while (cv::norm(wrong - truth) < 20.0);
        x[0] = wrong.x;
        x[1] = wrong.y;
        p.pointInliers.at<uchar>(i) = 0;
    }
    order = drawRows(o.lines, (int)std::lround(o.outliers * o.lines), rng);
    for (int i : order)
    {
        double* l = p.viewLines.back().ptr<double>(i);
        const cv::Point2d ta(l[0], l[1]), tb(l[2], l[3]);
        cv::Point2d a, b;
        do
        {
            a = randomPixel();
            b = randomPixel();
        } while (cv::norm(b - a) < 20.0 || std::max(lineDistance(a, ta, tb), lineDistance(b, ta, tb)) < 20.0);
        l[0] = a.x; l[1] = a.y; l[2] = b.x; l[3] = b.y;
        p.lineInliers.at<uchar>(i) = 0;
    }
    return p;
}

Problem vggProblem(const cv::tripose::support::VggTriplet& v, const Options& o, int trial)
{
    if (v.points1.rows < o.points || v.lines1.rows < o.lines)
        throw std::runtime_error(cv::format("the sequence has %d points and %d lines in the three views, %d and %d requested",
                                            v.points1.rows, v.lines1.rows, o.points, o.lines));
    cv::RNG rng((uint64)(0x9E3779B97F4A7C15ull ^ (uint64)(o.seed * 100003 + trial)));
    const std::vector<int> pr = drawRows(v.points1.rows, o.points, rng);
    const std::vector<int> lr = drawRows(v.lines1.rows, o.lines, rng);
    return selectFeatures(threeViewProblem(v), pr, lr);
}

// ---------------------------------------------------------------------------------------------
// Methods

struct Result
{
    bool ok = false;
    double rot = 0, trans = 0, timeUs = 0;
    std::string error;  // the exception message when the method threw
};

//! Runs solve() `repeats` times; the median wall time, the errors of the last run.
Result timed(const Problem& p, int repeats, const std::function<bool(cv::Mat&, cv::Mat&)>& solve)
{
    std::vector<double> times;
    Result res;
    cv::Mat R, t;
    for (int r = 0; r < repeats; ++r)
    {
        R.release(); t.release();
        const int64 t0 = cv::getTickCount();
        res.ok = solve(R, t);
        const int64 t1 = cv::getTickCount();
        times.push_back(1e6 * double(t1 - t0) / cv::getTickFrequency());
    }
    res.timeUs = medianOf(times);
    res.ok = res.ok && !R.empty() && cv::checkRange(R) && cv::checkRange(t);
    if (res.ok)
    {
        const cv::tripose::support::PoseError e = cv::tripose::support::poseError(R, t, p.R, p.t);
        res.rot = e.rotationDeg;
        res.trans = e.relativeTranslation;
    }
    return res;
}

cv::tripose::RansacParams ransacParams(const Options& o)
{
    cv::tripose::RansacParams params;
    params.threshold = o.threshold;
    params.seed = o.seed;
    params.minInliers = 0; // the estimator itself is measured, on mixes of 2-10 features as well
    return params;
}

// The three-view functions on views 1-3 (of a stereo problem too: its right image at B unused).

bool linearSolve(const Problem& p, cv::Mat& R, cv::Mat& t)
{
    return cv::tripose::estimatePoseLinePoint(p.points1, p.points2, p.points3, p.lines1, p.lines2, p.lines3,
                                              p.threeViewCameras(), cv::noArray(), p.R12, p.t12, R, t) > 0;
}

bool refineFrom(const Problem& p, cv::Mat& R, cv::Mat& t)
{
    const double rms = cv::tripose::refinePoseLinePoint(p.points1, p.points2, p.points3, p.lines1, p.lines2,
                                                        p.lines3, p.threeViewCameras(), cv::noArray(), p.R12, p.t12,
                                                        R, t);
    return std::isfinite(rms);
}

bool ransacSolve(const Problem& p, const Options& o, cv::Mat& R, cv::Mat& t)
{
    return cv::tripose::estimatePoseLinePointRansac(p.points1, p.points2, p.points3, p.lines1, p.lines2, p.lines3,
                                                    p.threeViewCameras(), cv::noArray(), p.R12, p.t12, R, t,
                                                    ransacParams(o)) > 0;
}

bool multiViewRansacSolve(const Problem& p, const Options& o, cv::Mat& R, cv::Mat& t)
{
    std::vector<cv::Mat> K(p.viewPoints.size(), p.K[0]);
    return cv::tripose::estimatePoseMultiViewRansac(p.viewPoints, p.viewLines, K, cv::noArray(), p.knownRs,
                                                    p.knownTs, R, t, ransacParams(o)) > 0;
}

// The stereo functions on the four views.

bool stereoSolve(const Problem& p, int method, cv::Mat& R, cv::Mat& t)
{
    return cv::tripose::estimatePoseLinePointStereo(p.points1, p.points2, p.points3, p.points4, p.lines1, p.lines2,
                                                    p.lines3, p.lines4, p.K, cv::noArray(), p.R12, p.t12, R, t,
                                                    method) > 0;
}

bool stereoRefineFrom(const Problem& p, cv::Mat& R, cv::Mat& t)
{
    const double rms = cv::tripose::refinePoseLinePointStereo(p.points1, p.points2, p.points3, p.points4, p.lines1,
                                                              p.lines2, p.lines3, p.lines4, p.K, cv::noArray(), p.R12,
                                                              p.t12, R, t);
    return std::isfinite(rms);
}

bool stereoRansacSolve(const Problem& p, const Options& o, cv::Mat& R, cv::Mat& t)
{
    return cv::tripose::estimatePoseLinePointStereoRansac(p.points1, p.points2, p.points3, p.points4, p.lines1,
                                                          p.lines2, p.lines3, p.lines4, p.K, cv::noArray(), p.R12,
                                                          p.t12, R, t, ransacParams(o)) > 0;
}

//! Starts from the ground truth and refines with @p refine on the true matches: the accuracy limit of
//! the cost (wrong matches would pull a non-robust refinement off it).
bool fromTruth(const Problem& p, cv::Mat& R, cv::Mat& t, bool (*refine)(const Problem&, cv::Mat&, cv::Mat&))
{
    R = p.R.clone();
    t = p.t.clone();
    return refine(trueMatches(p), R, t);
}

bool triangulateThenPnP(const Problem& p, int flags, cv::Mat& R, cv::Mat& t)
{
    const cv::Mat X = triangulatePoints12(p);
    cv::Mat rvec, tvec;
    if (!cv::solvePnP(X, p.points3, p.K[2], cv::noArray(), rvec, tvec, false, flags))
        return false;
    cv::Rodrigues(rvec, R);
    t = tvec;
    return true;
}

bool applies(const std::string& method, const Problem& p)
{
    if (method == "tri+sqpnp") return p.points1.rows >= 3;
    if (method == "tri+epnp") return p.points1.rows >= 4;
    if (method == "tri+iterative") return p.points1.rows >= 6;
    return true;
}

Result runMethod(const std::string& method, const Problem& p, const Options& o)
{
    try
    {
        if (method == "linear")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return linearSolve(p, R, t); });
        if (method == "linear+refine" || method == "three_view_linear+refine")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return linearSolve(p, R, t) && refineFrom(p, R, t); });
        if (method == "ml_from_truth")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return fromTruth(p, R, t, refineFrom); });
        if (method == "ransac" || method == "three_view_ransac")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return ransacSolve(p, o, R, t); });
        if (method == "multiview_ransac")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return multiViewRansacSolve(p, o, R, t); });
        if (method == "stereo_linear")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return stereoSolve(p, cv::tripose::POSE_LINEAR, R, t); });
        if (method == "stereo_multi_start")
            return timed(p, o.repeats,
                         [&](cv::Mat& R, cv::Mat& t) { return stereoSolve(p, cv::tripose::POSE_LINEAR_REFINE, R, t); });
        if (method == "stereo_linear+refine")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) {
                return stereoSolve(p, cv::tripose::POSE_LINEAR, R, t) && stereoRefineFrom(p, R, t);
            });
        if (method == "stereo_ransac")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return stereoRansacSolve(p, o, R, t); });
        if (method == "stereo_ml_from_truth")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return fromTruth(p, R, t, stereoRefineFrom); });
        if (method == "tri+sqpnp")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return triangulateThenPnP(p, cv::SOLVEPNP_SQPNP, R, t); });
        if (method == "tri+epnp")
            return timed(p, o.repeats, [&](cv::Mat& R, cv::Mat& t) { return triangulateThenPnP(p, cv::SOLVEPNP_EPNP, R, t); });
        if (method == "tri+iterative")
            return timed(p, o.repeats,
                         [&](cv::Mat& R, cv::Mat& t) { return triangulateThenPnP(p, cv::SOLVEPNP_ITERATIVE, R, t); });
    }
    catch (const cv::Exception& e)
    {
        // A degenerate draw (e.g. collinear points for PnP) is a failure of that method, not of the run.
        Result failed;
        failed.error = e.err;
        return failed;
    }
    return Result();
}

// ---------------------------------------------------------------------------------------------
// JSON output

//! Ten significant digits: far below any error the experiments measure, and lines a driver reads fast.
const int kJsonDigits = 10;

std::string num(double x)
{
    return cv::tripose::support::jsonNumber(x, kJsonDigits);
}

std::string matrix(const cv::Mat& m)
{
    return cv::tripose::support::jsonMatrix(m, kJsonDigits);
}

//! A multiview problem as it is: the observations of every view, the known poses, the ground truth.
std::string multiViewInputsJson(const Problem& p)
{
    const auto list = [](const std::vector<cv::Mat>& ms) {
        std::string s = "[";
        for (size_t k = 0; k < ms.size(); ++k)
            s += (k ? "," : "") + matrix(ms[k]);
        return s + "]";
    };
    std::vector<cv::Mat> ts;
    for (const cv::Mat& t : p.knownTs)
        ts.push_back(t.reshape(1, 3));
    return "{\"K\":" + matrix(p.K[0]) + ",\"Rs\":" + list(p.knownRs) + ",\"ts\":" + list(ts) +
           ",\"R_gt\":" + matrix(p.R) + ",\"t_gt\":" + matrix(p.t.reshape(1, 3)) + ",\"points\":" +
           list(p.viewPoints) + ",\"lines\":" + list(p.viewLines) + "}";
}

std::string inputsJson(const Problem& p)
{
    const int64 t0 = cv::getTickCount();
    const cv::Mat X = triangulatePoints12(p);
    const cv::Mat L = triangulateLines12(p);
    const double triUs = 1e6 * double(cv::getTickCount() - t0) / cv::getTickFrequency();
    std::string s = "{\"K\":[";
    for (size_t v = 0; v < p.K.size(); ++v)
        s += (v ? "," : "") + matrix(p.K[v]);
    s += "]";
    s += ",\"R12\":" + matrix(p.R12) + ",\"t12\":" + matrix(p.t12.reshape(1, 3));
    s += ",\"R_gt\":" + matrix(p.R) + ",\"t_gt\":" + matrix(p.t.reshape(1, 3));
    s += ",\"points1\":" + matrix(p.points1) + ",\"points2\":" + matrix(p.points2) + ",\"points3\":" + matrix(p.points3);
    s += ",\"lines1\":" + matrix(p.lines1) + ",\"lines2\":" + matrix(p.lines2) + ",\"lines3\":" + matrix(p.lines3);
    if (p.stereo())
        s += ",\"points4\":" + matrix(p.points4) + ",\"lines4\":" + matrix(p.lines4);
    s += ",\"points3d_12\":" + matrix(X) + ",\"lines3d_12\":" + matrix(L) + ",\"triangulation_us\":" + num(triUs);
    // Synthetic scenes: which rows are true matches (1) and which wrong ones (0).
    const auto mask = [](const cv::Mat& m) {
        cv::Mat row;
        m.reshape(1, 1).convertTo(row, CV_64F);
        return matrix(row);
    };
    if (!p.pointInliers.empty())
        s += ",\"true_point_matches\":" + mask(p.pointInliers);
    if (!p.lineInliers.empty())
        s += ",\"true_line_matches\":" + mask(p.lineInliers);
    return s + "}";
}

} // namespace

int main(int argc, char** argv)
{
    Options o;
    try
    {
        o = parse(argc, argv);
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_evaluate: " << e.what() << "\n" << kUsage;
        return 1;
    }
    cv::setNumThreads(1);  // times are single-thread, as in the paper and the perf tests

    try
    {
        cv::tripose::support::VggTriplet vgg;
        if (o.source == "vgg")
            vgg = cv::tripose::support::loadVggTriplet(o.sequence, o.views[0], o.views[1], o.views[2]);
        for (int trial = 0; trial < o.trials; ++trial)
        {
            const Problem p = o.source == "vgg"         ? vggProblem(vgg, o, trial)
                              : o.source == "stereo"    ? syntheticStereoProblem(o, trial)
                              : o.source == "multiview" ? multiViewProblem(o, trial)
                                                        : syntheticProblem(o, trial);
            // Stereo: the methods on views 1-3 get the features the left image at B sees.
            const Problem left = p.stereo() ? seenInView3(p) : p;
            std::string line = "{\"source\":\"" + o.source + "\",\"trial\":" + std::to_string(trial) +
                               ",\"seed\":" + std::to_string(o.seed) + ",\"points\":" + std::to_string(o.points) +
                               ",\"lines\":" + std::to_string(o.lines) + ",\"repeats\":" + std::to_string(o.repeats) +
                               ",\"threshold\":" + num(o.threshold);
            if (o.source == "synthetic")
                line += ",\"noise\":" + num(o.noise) + ",\"outliers\":" + num(o.outliers) + ",\"motion\":\"" +
                        (o.motion == cv::tripose::support::MOTION_SMALL ? "small" : "large") + "\",\"baseline12_fraction\":" +
                        num(o.baseline12Fraction) + ",\"planar\":" + (o.planar ? "true" : "false");
            else if (o.source == "stereo")
                line += ",\"noise\":" + num(o.noise) + ",\"outliers\":" + num(o.outliers) + ",\"missing\":" +
                        num(o.missing);
            else if (o.source == "multiview")
                line += ",\"noise\":" + num(o.noise) + ",\"outliers\":" + num(o.outliers) + ",\"known\":" +
                        std::to_string(o.known);
            else
                line += ",\"sequence\":\"" + o.sequence.substr(o.sequence.find_last_of('/') + 1) + "\",\"views\":[" +
                        std::to_string(o.views[0]) + "," + std::to_string(o.views[1]) + "," +
                        std::to_string(o.views[2]) + "]";
            line += ",\"methods\":{";
            bool first = true;
            for (const std::string& m : o.methods)
            {
                const Problem& input = m.compare(0, 7, "stereo_") == 0 ? p : left;
                if (!applies(m, input))
                    continue;
                const Result r = runMethod(m, input, o);
                line += std::string(first ? "" : ",") + "\"" + m + "\":{\"ok\":" + (r.ok ? "true" : "false") +
                        ",\"rot_deg\":" + (r.ok ? num(r.rot) : "null") + ",\"t_rel\":" + (r.ok ? num(r.trans) : "null") +
                        ",\"time_us\":" + num(r.timeUs) + (r.error.empty() ? "" : ",\"error\":\"" + cv::tripose::support::jsonEscape(r.error) + "\"") + "}";
                first = false;
            }
            line += "}";
            if (o.dumpInputs)
                line += ",\"inputs\":" + (p.multiView() ? multiViewInputsJson(p) : inputsJson(left));
            // The rig's peers that use both time-B views (generalized absolute pose) need every feature.
            if (o.dumpInputs && p.stereo())
                line += ",\"rig_inputs\":" + inputsJson(p);
            std::cout << line << "}\n" << std::flush;
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_evaluate: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
