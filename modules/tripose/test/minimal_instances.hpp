// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Random noise-free instances of the minimal point and line solvers, for their tests and perf tests:
// a random pose, points and line segments in a 90 degree field of view at depths 2..10, and adaptors
// that call each solver on an instance.

#ifndef OPENCV_TRIPOSE_TEST_MINIMAL_INSTANCES_HPP
#define OPENCV_TRIPOSE_TEST_MINIMAL_INSTANCES_HPP

#include <vector>

#include <Eigen/Geometry>

#include "opencv2/core.hpp"

#include "../src/core/minimal/p1p2l.hpp"
#include "../src/core/minimal/p3p.hpp"
#include "../src/core/minimal/p2p1l.hpp"
#include "../src/core/minimal/p3l.hpp"

namespace opencv_test {
namespace minimal_instances {

using cv::RNG;
using ::tripose::CameraPose;
using ::tripose::solveP1P2L;
using ::tripose::solveP2P1L;
using ::tripose::solveP3L;
using ::tripose::solveP3P;
using ::tripose::WorldLine;

inline CameraPose randomPose(RNG& rng)
{
    // One draw per statement, as C++ leaves the order of arguments and operands unspecified: the last
    // coordinate first (z before y before x, here and below) is the order the seeded instances were
    // drawn in so far (GCC's, right to left).
    const double qz = rng.gaussian(1.0);
    const double qy = rng.gaussian(1.0);
    const double qx = rng.gaussian(1.0);
    const double qw = rng.gaussian(1.0);
    const double tz = rng.uniform(-2.0, 2.0);
    const double ty = rng.uniform(-2.0, 2.0);
    const double tx = rng.uniform(-2.0, 2.0);
    CameraPose pose;
    pose.R = Eigen::Quaterniond(qw, qx, qy, qz).normalized().toRotationMatrix();
    pose.t = Eigen::Vector3d(tx, ty, tz);
    return pose;
}

//! A point in the camera frame in a 90 degree field of view, at depth 2..10.
inline Eigen::Vector3d randomPointInView(RNG& rng)
{
    const double y = rng.uniform(-1.0, 1.0);
    const double x = rng.uniform(-1.0, 1.0);
    const double depth = rng.uniform(2.0, 10.0);
    return depth * Eigen::Vector3d(x, y, 1.0);
}

inline Eigen::Vector3d toWorld(const CameraPose& pose, const Eigen::Vector3d& Xc)
{
    return pose.R.transpose() * (Xc - pose.t);
}

//! The calibrated image line through the projections of two camera-frame points, (a, b) unit.
inline Eigen::Vector3d imageLineThrough(const Eigen::Vector3d& Ac, const Eigen::Vector3d& Bc)
{
    const Eigen::Vector3d l = (Ac / Ac.z()).cross(Bc / Bc.z());
    return l / l.head<2>().norm();
}

struct PointObservation
{
    Eigen::Vector3d bearing; // [x; 1]
    Eigen::Vector3d world;
};

struct LineObservation
{
    Eigen::Vector3d imageLine;
    WorldLine world;
    Eigen::Vector3d ends[2]; // world end points, both in front of the camera
};

inline PointObservation observePoint(const CameraPose& pose, const Eigen::Vector3d& Xc)
{
    return PointObservation{ Xc / Xc.z(), toWorld(pose, Xc) };
}

inline LineObservation observeLine(const CameraPose& pose, const Eigen::Vector3d& Ac, const Eigen::Vector3d& Bc)
{
    LineObservation o;
    o.imageLine = imageLineThrough(Ac, Bc);
    o.ends[0] = toWorld(pose, Ac);
    o.ends[1] = toWorld(pose, Bc);
    o.world = WorldLine::throughPoints(o.ends[0], o.ends[1]);
    return o;
}

//! A line of @p pose's view through two random points in view, the second end drawn first.
inline LineObservation randomLine(RNG& rng, const CameraPose& pose)
{
    const Eigen::Vector3d Bc = randomPointInView(rng);
    const Eigen::Vector3d Ac = randomPointInView(rng);
    return observeLine(pose, Ac, Bc);
}

//! A camera-frame segment through @p Zc along @p dc, both end points at positive depth.
inline void segmentThrough(RNG& rng, const Eigen::Vector3d& Zc, const Eigen::Vector3d& dc, Eigen::Vector3d& Ac,
                    Eigen::Vector3d& Bc)
{
    // Depths are at least 2 and |dc| is 1: steps below 1 keep both ends in front.
    const Eigen::Vector3d d = dc.normalized();
    Ac = Zc + rng.uniform(0.2, 0.9) * d;
    Bc = Zc - rng.uniform(0.2, 0.9) * d;
}

inline Eigen::Vector3d randomDirection(RNG& rng)
{
    const double z = rng.gaussian(1.0);
    const double y = rng.gaussian(1.0);
    const double x = rng.gaussian(1.0);
    return Eigen::Vector3d(x, y, z).normalized();
}

//! A line of @p pose's view through the camera-frame point @p Zc along @p dc.
inline LineObservation lineThrough(RNG& rng, const CameraPose& pose, const Eigen::Vector3d& Zc, const Eigen::Vector3d& dc)
{
    Eigen::Vector3d Ac, Bc;
    segmentThrough(rng, Zc, dc, Ac, Bc);
    return observeLine(pose, Ac, Bc);
}

inline CameraPose makeP2P1L(RNG& rng, std::vector<PointObservation>& points, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    for (int i = 0; i < 2; ++i)
        points.push_back(observePoint(truth, randomPointInView(rng)));
    lines.push_back(randomLine(rng, truth));
    return truth;
}

inline int solveP2P1LObservations(const std::vector<PointObservation>& points, const std::vector<LineObservation>& lines,
                           std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d bearings[2] = { points[0].bearing, points[1].bearing };
    const Eigen::Vector3d worlds[2] = { points[0].world, points[1].world };
    return solveP2P1L(bearings, worlds, lines[0].imageLine, lines[0].world, poses);
}

inline CameraPose makeP1P2L(RNG& rng, std::vector<PointObservation>& points, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    points.push_back(observePoint(truth, randomPointInView(rng)));
    for (int j = 0; j < 2; ++j)
        lines.push_back(randomLine(rng, truth));
    return truth;
}

inline int solveP1P2LObservations(const std::vector<PointObservation>& points, const std::vector<LineObservation>& lines,
                           std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d imageLines[2] = { lines[0].imageLine, lines[1].imageLine };
    const WorldLine worlds[2] = { lines[0].world, lines[1].world };
    return solveP1P2L(points[0].bearing, points[0].world, imageLines, worlds, poses);
}

inline CameraPose makeP3L(RNG& rng, std::vector<PointObservation>&, std::vector<LineObservation>& lines)
{
    const CameraPose truth = randomPose(rng);
    for (int j = 0; j < 3; ++j)
        lines.push_back(randomLine(rng, truth));
    return truth;
}

inline int solveP3LObservations(const std::vector<PointObservation>&, const std::vector<LineObservation>& lines,
                         std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d imageLines[3] = { lines[0].imageLine, lines[1].imageLine, lines[2].imageLine };
    const WorldLine worlds[3] = { lines[0].world, lines[1].world, lines[2].world };
    return solveP3L(imageLines, worlds, poses);
}

inline CameraPose makeP3P(RNG& rng, std::vector<PointObservation>& points, std::vector<LineObservation>&)
{
    const CameraPose truth = randomPose(rng);
    for (int i = 0; i < 3; ++i)
        points.push_back(observePoint(truth, randomPointInView(rng)));
    return truth;
}

inline int solveP3PObservations(const std::vector<PointObservation>& points, const std::vector<LineObservation>&,
                                std::vector<CameraPose>& poses)
{
    const Eigen::Vector3d bearings[3] = { points[0].bearing, points[1].bearing, points[2].bearing };
    const Eigen::Vector3d worlds[3] = { points[0].world, points[1].world, points[2].world };
    return solveP3P(bearings, worlds, poses);
}

} // namespace minimal_instances
} // namespace opencv_test

#endif // OPENCV_TRIPOSE_TEST_MINIMAL_INSTANCES_HPP
