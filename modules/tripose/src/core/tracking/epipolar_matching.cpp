// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "epipolar_matching.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace tripose {

namespace {

Eigen::Vector3d homogeneous(const Eigen::Vector2d& x)
{
    return Eigen::Vector3d(x.x(), x.y(), 1);
}

//! The line @p l scaled so that l . (x, y, 1) is the distance of (x, y) from it in pixels.
Eigen::Vector3d distanceNormalised(const Eigen::Vector3d& l)
{
    return l / std::max(std::hypot(l[0], l[1]), 1e-300);
}

/** Where segment @p s crosses the lines @p la and @p lb, as parameters along it (0 at its first end,
1 at its second); false when it runs within @p minSine of either line. */
bool bandOnSegment(const Eigen::Vector4d& s, const Eigen::Vector3d& la, const Eigen::Vector3d& lb, double minSine,
                   double& atA, double& atB)
{
    const Eigen::Vector2d p(s[0], s[1]), d(s[2] - s[0], s[3] - s[1]);
    const double length = d.norm();
    double u[2];
    const Eigen::Vector3d* lines[2] = { &la, &lb };
    for (int k = 0; k < 2; ++k)
    {
        const Eigen::Vector3d& l = *lines[k];
        const double normal = std::hypot(l[0], l[1]);
        const double across = l[0] * d.x() + l[1] * d.y(); // normal * length * sin(angle to the line)
        if (!(std::abs(across) > minSine * normal * length))
            return false;
        u[k] = -(l[0] * p.x() + l[1] * p.y() + l[2]) / across;
    }
    atA = u[0];
    atB = u[1];
    return true;
}

} // namespace

Eigen::Matrix3d fundamentalFromPose(const Eigen::Matrix3d& Ka, const Eigen::Matrix3d& Kb, const CameraPose& relative)
{
    const Eigen::Vector3d& t = relative.t;
    Eigen::Matrix3d tx;
    tx << 0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0;
    return Kb.inverse().transpose() * (tx * relative.R) * Ka.inverse();
}

bool withinEpipolarDistance(const Eigen::Matrix3d& F, const Eigen::Vector2d& xa, const Eigen::Vector2d& xb,
                            double distance)
{
    const Eigen::Vector3d ha = homogeneous(xa), hb = homogeneous(xb);
    return std::abs(distanceNormalised(F * ha).dot(hb)) <= distance &&
           std::abs(distanceNormalised(F.transpose() * hb).dot(ha)) <= distance;
}

Matches matchPointsEpipolar(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                            const MatchOptions& options)
{
    const int na = (int)a.points.size(), nb = (int)b.points.size();
    if (a.pointDescriptors.rows != na || b.pointDescriptors.rows != nb)
        return {};
    MutualBest best(na, nb);
    std::vector<Eigen::Vector3d> linesInA(nb);
    for (int j = 0; j < nb; ++j)
        linesInA[j] = distanceNormalised(F.transpose() * homogeneous(b.points[j]));
    for (int i = 0; i < na; ++i)
    {
        const Eigen::Vector3d xa = homogeneous(a.points[i]);
        const Eigen::Vector3d l = distanceNormalised(F * xa);
        for (int j = 0; j < nb; ++j)
        {
            const Eigen::Vector2d& xb = b.points[j];
            if (std::abs(l[0] * xb.x() + l[1] * xb.y() + l[2]) > options.epipolarDistance ||
                std::abs(linesInA[j].dot(xa)) > options.epipolarDistance)
                continue;
            best.add(i, j, a.pointDescriptors.distance(i, b.pointDescriptors, j));
        }
    }
    return best.result(options.pointRatio);
}

Matches matchSegmentsEpipolar(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                              const MatchOptions& options)
{
    const int na = (int)a.segments.size(), nb = (int)b.segments.size();
    if (a.lineDescriptors.rows != na || b.lineDescriptors.rows != nb)
        return {};
    MutualBest best(na, nb);
    const double minSine = std::sin(options.minEpipolarAngleDeg * M_PI / 180);
    for (int i = 0; i < na; ++i)
    {
        const Eigen::Vector4d& s = a.segments[i];
        const Eigen::Vector3d la = F * Eigen::Vector3d(s[0], s[1], 1), lb = F * Eigen::Vector3d(s[2], s[3], 1);
        for (int j = 0; j < nb; ++j)
        {
            double lo, hi;
            if (!bandOnSegment(b.segments[j], la, lb, minSine, lo, hi))
                continue;
            // Views keep the order of points along a line and the side of an edge's brighter half:
            // the band of a's first end point comes first along b, or b is another edge.
            if (!(lo < hi))
                continue;
            // Detected segments break up and stop short at different places in two images: the
            // overlap must cover a good part of the shorter of the two, not of both.
            const double overlap = std::min(hi, 1.0) - std::max(lo, 0.0);
            if (!(overlap > 0) || overlap < options.minBandOverlap * std::min(1.0, hi - lo))
                continue;
            const double distance = a.lineDescriptors.distance(i, b.lineDescriptors, j);
            if (!a.lineDescriptors.binary || distance <= options.maxLineDistance)
                best.add(i, j, distance);
        }
    }
    return best.result(options.lineRatio);
}

} // namespace tripose
