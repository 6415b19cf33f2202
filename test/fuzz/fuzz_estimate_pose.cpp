// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// libFuzzer target over the public API: the fuzz input is decoded into a problem and handed to
// estimatePoseLinePoint, estimatePoseLinePointRansac (few iterations) and refinePoseLinePoint, then,
// as a stereo rig (views 1-2 at time A, view 3's observations seen by views 3 and 4 at time B with
// every third feature missing in one of them: rows of NaN), to their stereo counterparts.
// Rejecting the input with a cv::Exception is fine; anything else escaping, a crash, a sanitizer
// report, or a returned pose that is not finite or whose rotation is not a rotation is a bug.
//
// Input layout (test/fuzz/make_corpus.py writes seeds in it); missing bytes read as zero:
//   byte     number of point triplets (mod 33)
//   byte     number of line triplets (mod 33)
//   byte     options: bit 0 homogeneous lines (Mx3) instead of segments (Mx4); bit 1 observations
//            as CV_32F; bit 2 three intrinsic matrices instead of one; bit 3 distortion (5
//            coefficients per intrinsic matrix); bit 4 R12 as a Rodrigues vector; bit 5 RANSAC
//            local optimisation; bit 6 RANSAC refinement; bit 7 initial pose of the refinement
//            read from the input (else the linear estimate)
//   byte     refinement loss (mod 4; 3 is out of range)
//   byte     RANSAC maxIterations - 1 (mod 32)
//   byte     refinement maxIterations (mod 9; 0 is out of range)
//   doubles  RANSAC threshold, confidence; refinement lossScale, tolerance
//   doubles  intrinsic matrices (9 each, row-major), distortion (5 each), R12 (9 or 3), t12 (3),
//            initial R (Rodrigues, 3) and t (3) when bit 7 is set,
//            points (view 1, 2, 3: 2 per point), lines (view 1, 2, 3: 4 or 3 per line)

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

#include "byte_reader.hpp"

namespace {

using tripose_fuzz::ByteReader;

struct Problem
{
    cv::Mat points[3], lines[3], R12, t12, R0, t0;
    std::vector<cv::Mat> K, dist;
    cv::tripose::RansacParams ransac;
    cv::tripose::RefineParams refine;
    bool initialPoseGiven = false;
};

cv::Mat readMatrix(ByteReader& in, int rows, int cols)
{
    cv::Mat m(rows, cols, CV_64F);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            m.at<double>(r, c) = in.number();
    return m;
}

Problem decode(const uint8_t* data, size_t size)
{
    ByteReader in(data, size);
    Problem p;
    const int numPoints = in.byte() % 33, numLines = in.byte() % 33;
    const uint8_t options = in.byte();
    const bool homogeneous = options & 1, single = options & 2, threeK = options & 4, distortion = options & 8,
               rodrigues = options & 16;
    p.ransac.localOptimization = options & 32;
    p.ransac.refine = options & 64;
    p.initialPoseGiven = options & 128;
    p.refine.loss = in.byte() % 4;
    p.ransac.maxIterations = 1 + in.byte() % 32;
    p.ransac.minInliers = in.byte() % 4; // the fuzzed problems are small: the floor would end most of them early
    p.refine.maxIterations = in.byte() % 9;
    p.ransac.threshold = in.number();
    p.ransac.confidence = in.number();
    p.refine.lossScale = in.number();
    p.refine.tolerance = in.number();

    const int numK = threeK ? 3 : 1;
    for (int v = 0; v < numK; ++v)
        p.K.push_back(readMatrix(in, 3, 3));
    for (int v = 0; v < numK && distortion; ++v)
        p.dist.push_back(readMatrix(in, 1, 5));
    p.R12 = rodrigues ? readMatrix(in, 3, 1) : readMatrix(in, 3, 3);
    p.t12 = readMatrix(in, 3, 1);
    if (p.initialPoseGiven)
    {
        p.R0 = readMatrix(in, 3, 1);
        p.t0 = readMatrix(in, 3, 1);
    }
    for (int v = 0; v < 3; ++v)
        p.points[v] = readMatrix(in, numPoints, 2);
    for (int v = 0; v < 3; ++v)
        p.lines[v] = readMatrix(in, numLines, homogeneous ? 3 : 4);
    if (single)
        for (int v = 0; v < 3; ++v)
        {
            p.points[v].convertTo(p.points[v], CV_32F);
            p.lines[v].convertTo(p.lines[v], CV_32F);
        }
    return p;
}

[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "tripose fuzz: %s\n", what);
    std::abort();
}

//! A returned pose: finite, R a proper rotation (3x3, or a Rodrigues vector from the refinement).
void requireValidPose(const cv::Mat& Rin, const cv::Mat& t, const char* what)
{
    if (Rin.empty() || t.total() != 3 || !cv::checkRange(Rin) || !cv::checkRange(t))
        fail(what);
    cv::Mat R = Rin;
    if (R.total() == 3)
        cv::Rodrigues(Rin, R);
    if (R.rows != 3 || R.cols != 3 || R.type() != CV_64F)
        fail(what);
    const double orthogonality = cv::norm(R.t() * R, cv::Mat::eye(3, 3, CV_64F), cv::NORM_INF);
    if (!(orthogonality < 1e-6) || !(cv::determinant(R) > 0))
        fail(what);
}

void run(const Problem& p)
{
    cv::Mat R, t;
    std::vector<cv::Mat> Rs, ts;
    int n = 0;
    try
    {
        n = cv::tripose::estimatePoseLinePoint(p.points[0], p.points[1], p.points[2], p.lines[0], p.lines[1],
                                               p.lines[2], p.K, p.dist, p.R12, p.t12, R, t,
                                               cv::tripose::POSE_LINEAR, Rs, ts);
        if (n < 0 || (int)Rs.size() != n || (int)ts.size() != n || (n == 0) != R.empty())
            fail("estimatePoseLinePoint: inconsistent outputs");
        for (int i = 0; i < n; ++i)
            requireValidPose(Rs[i], ts[i], "estimatePoseLinePoint: a candidate is not a finite rotation and translation");
    }
    catch (const cv::Exception&)
    {
    }

    try
    {
        cv::Mat Rr, tr;
        const int inliers = cv::tripose::estimatePoseLinePointRansac(
            p.points[0], p.points[1], p.points[2], p.lines[0], p.lines[1], p.lines[2], p.K, p.dist, p.R12, p.t12,
            Rr, tr, p.ransac);
        if (inliers > 0)
            requireValidPose(Rr, tr, "estimatePoseLinePointRansac: the pose is not a finite rotation and translation");
        else if (!Rr.empty())
            fail("estimatePoseLinePointRansac: a pose without inliers");
    }
    catch (const cv::Exception&)
    {
    }

    cv::Mat R0 = p.initialPoseGiven ? p.R0.clone() : R.clone(), t0 = p.initialPoseGiven ? p.t0.clone() : t.clone();
    if (R0.empty())
        return;
    try
    {
        const double rms = cv::tripose::refinePoseLinePoint(p.points[0], p.points[1], p.points[2], p.lines[0],
                                                            p.lines[1], p.lines[2], p.K, p.dist, p.R12, p.t12, R0,
                                                            t0, p.refine);
        if (std::isnan(rms) || rms < 0)
            fail("refinePoseLinePoint: RMS is NaN or negative");
        requireValidPose(R0, t0, "refinePoseLinePoint: the pose is not a finite rotation and translation");
    }
    catch (const cv::Exception&)
    {
    }
}

//! The problem as a stereo rig: view 4 sees what view 3 sees, but feature i is missing (NaN) in
//! view 4 when i % 3 == 1 and in view 3 when i % 3 == 2; the intrinsics of view 4 are view 2's.
void runStereo(const Problem& p)
{
    cv::Mat points[4], lines[4];
    for (int v = 0; v < 3; ++v)
    {
        points[v] = p.points[v];
        lines[v] = p.lines[v];
    }
    points[3] = p.points[2].clone();
    lines[3] = p.lines[2].clone();
    points[2] = p.points[2].clone();
    lines[2] = p.lines[2].clone();
    for (cv::Mat* pair : { points + 2, lines + 2 })
        for (int i = 0; i < pair[0].rows; ++i)
            if (i % 3 != 0)
                pair[i % 3 == 1 ? 1 : 0].row(i).setTo(std::numeric_limits<double>::quiet_NaN());
    std::vector<cv::Mat> K = p.K, dist = p.dist;
    if (K.size() == 3)
        K.push_back(K[1]);
    if (dist.size() == 3)
        dist.push_back(dist[1]);

    cv::Mat R, t;
    std::vector<cv::Mat> Rs, ts;
    try
    {
        const int n = cv::tripose::estimatePoseLinePointStereo(points[0], points[1], points[2], points[3], lines[0],
                                                               lines[1], lines[2], lines[3], K, dist, p.R12, p.t12,
                                                               R, t, cv::tripose::POSE_LINEAR, Rs, ts);
        if (n < 0 || (int)Rs.size() != n || (int)ts.size() != n || (n == 0) != R.empty())
            fail("estimatePoseLinePointStereo: inconsistent outputs");
        for (int i = 0; i < n; ++i)
            requireValidPose(Rs[i], ts[i], "estimatePoseLinePointStereo: a candidate is not a finite rotation and translation");
    }
    catch (const cv::Exception&)
    {
    }

    try
    {
        cv::Mat Rr, tr;
        const int inliers = cv::tripose::estimatePoseLinePointStereoRansac(
            points[0], points[1], points[2], points[3], lines[0], lines[1], lines[2], lines[3], K, dist, p.R12, p.t12,
            Rr, tr, p.ransac);
        if (inliers > 0)
            requireValidPose(Rr, tr, "estimatePoseLinePointStereoRansac: the pose is not a finite rotation and translation");
        else if (!Rr.empty())
            fail("estimatePoseLinePointStereoRansac: a pose without inliers");
    }
    catch (const cv::Exception&)
    {
    }

    cv::Mat R0 = p.initialPoseGiven ? p.R0.clone() : R.clone(), t0 = p.initialPoseGiven ? p.t0.clone() : t.clone();
    if (R0.empty())
        return;
    try
    {
        const double rms = cv::tripose::refinePoseLinePointStereo(points[0], points[1], points[2], points[3],
                                                                  lines[0], lines[1], lines[2], lines[3], K, dist,
                                                                  p.R12, p.t12, R0, t0, p.refine);
        if (std::isnan(rms) || rms < 0)
            fail("refinePoseLinePointStereo: RMS is NaN or negative");
        requireValidPose(R0, t0, "refinePoseLinePointStereo: the pose is not a finite rotation and translation");
    }
    catch (const cv::Exception&)
    {
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const Problem problem = decode(data, size);
    run(problem);
    runStereo(problem);
    return 0;
}
