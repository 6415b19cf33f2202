// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_TEST_POSE_COMMON_HPP
#define OPENCV_TRIPOSE_TEST_POSE_COMMON_HPP

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "test_precomp.hpp"
#include "../src/opencv/opencv_compat.hpp" // Rodrigues: calib3d in OpenCV 4, geometry in 5
#include "../src/core/geometry/camera.hpp"

namespace opencv_test {

//! Expects @p call to throw a cv::Exception whose message names @p name (an argument, a key).
inline void expectNamed(const std::function<void()>& call, const std::string& name)
{
    try
    {
        call();
        ADD_FAILURE() << "no exception; expected one naming " << name;
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(name)) << "expected " << name << ": " << e.err;
    }
}

//! A true pose (@p Rtrue, @p ttrue) turned by @p degrees about a random axis, its translation moved
//! by @p fraction of its norm in a random direction: a start for refinement tests.
inline void perturbPose(const Mat& Rtrue, const Mat& ttrue, double degrees, double fraction, RNG& rng, Mat& R, Mat& t)
{
    // One draw per statement, as C++ leaves the order of arguments unspecified: z before y before x is
    // the order the seeded starts were drawn in so far (GCC's, right to left).
    const double axisZ = rng.gaussian(1);
    const double axisY = rng.gaussian(1);
    const double axisX = rng.gaussian(1);
    Vec3d axis(axisX, axisY, axisZ);
    axis *= (degrees * CV_PI / 180.0) / cv::norm(axis);
    Mat dR;
    Rodrigues(Mat(axis), dR);
    R = dR * Rtrue;
    const double dtZ = rng.gaussian(1);
    const double dtY = rng.gaussian(1);
    const double dtX = rng.gaussian(1);
    Vec3d dt(dtX, dtY, dtZ);
    dt *= fraction * cv::norm(ttrue) / cv::norm(dt);
    t = ttrue + Mat(dt);
}

//! A 3x3 CV_64F Mat as a Matx33d (checks the type and size).
inline Matx33d toMatx33(const Mat& m)
{
    EXPECT_EQ(m.type(), CV_64F);
    EXPECT_EQ(m.size(), Size(3, 3));
    return Matx33d(m.ptr<double>());
}

//! A 3-element CV_64F Mat as a Vec3d (checks the type and size).
inline Vec3d toVec3(const Mat& m)
{
    EXPECT_EQ(m.type(), CV_64F);
    EXPECT_EQ(m.total(), 3u);
    return Vec3d(m.ptr<double>());
}

//! Nx3 points triangulated (DLT, cv::triangulatePoints) from the first two views, view 1 at [I|0]
//! and view 2 at [R12|t12]: the structure a user without this module would start from.
inline Mat triangulateFromKnownPair(const std::vector<Mat>& K, const Mat& R12, const Mat& t12, const Mat& points1,
                                    const Mat& points2)
{
    return cv::tripose::support::triangulateKnownPair(Matx33d(K[0]), Matx33d(K[1]), Matx33d(R12), Vec3d(t12), points1,
                                                      points2);
}

using cv::tripose::support::PoseError;
using cv::tripose::support::poseError;

//! An angle in radians in degrees, the unit of PoseError: noise-free bounds are stated in radians,
//! as in the Python tests.
//! The core's pose of a 3x3 rotation and 3-vector translation (CV_64F).
inline ::tripose::CameraPose corePose(const Mat& R, const Mat& t)
{
    ::tripose::CameraPose p;
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
            p.R(r, c) = R.at<double>(r, c);
        p.t(r) = t.at<double>(r);
    }
    return p;
}

inline double degrees(double radians)
{
    return radians * 180.0 / CV_PI;
}

//! A feature mix: numbers of point and line triplets.
struct FeatureMix
{
    int points;
    int lines;
};

inline std::string mixName(const FeatureMix& m)
{
    return cv::format("%dP%dL", m.points, m.lines);
}

inline cv::tripose::support::SyntheticSceneParams sceneParams(const FeatureMix& mix, int motion, double noise, int seed,
                                                          double outlierRatio = 0)
{
    cv::tripose::support::SyntheticSceneParams params;
    params.numPoints = mix.points;
    params.numLines = mix.lines;
    params.motion = motion;
    params.noiseSigma = noise;
    params.outlierRatio = outlierRatio;
    params.seed = seed;
    return params;
}

inline cv::tripose::support::SyntheticScene makeScene(const FeatureMix& mix, int motion, double noise, int seed,
                                                  double outlierRatio = 0)
{
    return cv::tripose::support::generateSyntheticScene(sceneParams(mix, motion, noise, seed, outlierRatio));
}

//! A stereo-rig scene's parameters: the generator's rig, depths and motion with these features, noise
//! (px), share of wrong matches at time B and share of features seen by one time-B view only.
inline cv::tripose::support::SyntheticStereoParams stereoParams(int points, int lines, int seed, double noise = 0,
                                                            double outliers = 0, double missing = 0)
{
    cv::tripose::support::SyntheticStereoParams p;
    p.numPoints = points;
    p.numLines = lines;
    p.seed = seed;
    p.noiseSigma = noise;
    p.outlierRatio = outliers;
    p.missingRatio = missing;
    return p;
}

//! Solves a scene with the linear method; all candidates best first.
inline int solveScene(const cv::tripose::support::SyntheticScene& s, std::vector<Mat>& Rs, std::vector<Mat>& ts, Mat& R, Mat& t)
{
    return cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                          s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                          cv::tripose::POSE_LINEAR, Rs, ts);
}

//! Whether @p a and @p b have the same size, type and elements (a NaN element makes them differ).
inline bool identical(const Mat& a, const Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && (a.empty() || cv::norm(a, b, NORM_INF) == 0);
}

//! The upper median of @p values (the middle element of an odd count), which must not be empty.
template <typename T>
T median(std::vector<T> values)
{
    CV_Assert(!values.empty());
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

//! How many of a statistical test's @p full scenes to run: all of them, or the first
//! TRIPOSE_TEST_SCENE_LIMIT when that is set (scripts/test_sanitizers.sh sets it: under the
//! sanitizers a few scenes take the code paths the many repeat, at a 25th of the speed). Assertions
//! made per scene hold on any prefix; a test whose aggregate bound does not says so where it uses this.
inline int scenesToRun(int full)
{
    const char* limit = std::getenv("TRIPOSE_TEST_SCENE_LIMIT");
    int n = 0;
    if (!limit || !*limit || std::sscanf(limit, "%d", &n) != 1 || n <= 0)
        return full;
    return std::min(full, n);
}

} // namespace opencv_test

#endif // OPENCV_TRIPOSE_TEST_POSE_COMMON_HPP
