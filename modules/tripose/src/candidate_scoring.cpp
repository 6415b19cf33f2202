// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>

#include "candidate_scoring.hpp"

namespace cv {
namespace tripose {
namespace detail {

TwoViewStructure triangulateTwoViewStructure(const TripletData& data)
{
    TwoViewStructure s;
    const Eigen::Matrix3d& R0 = data.view2.R;
    const Eigen::Vector3d& t0 = data.view2.t;
    const Eigen::Vector3d centre2 = -R0.transpose() * t0;

    s.points.resize(data.numPoints());
    s.pointValid.assign(data.numPoints(), 0);
    for (int i = 0; i < data.numPoints(); ++i)
    {
        // Midpoint of the closest points of the rays lambda1 d1 and centre2 + lambda2 d2.
        const Eigen::Vector3d d1 = data.points1[i].homogeneous().normalized();
        const Eigen::Vector3d d2 = (R0.transpose() * data.points2[i].homogeneous()).normalized();
        const double b = d1.dot(d2);
        const double denominator = 1.0 - b * b;
        if (!(denominator > 1e-12))
            continue;
        const double e = d1.dot(centre2), f = d2.dot(centre2);
        const double lambda1 = (e - b * f) / denominator;
        const double lambda2 = (b * e - f) / denominator;
        s.points[i] = 0.5 * (lambda1 * d1 + centre2 + lambda2 * d2);
        // A point triangulated behind view 1 or 2 is noise, not structure: it must not vote.
        s.pointValid[i] = s.points[i].allFinite() && lambda1 > 0 && lambda2 > 0;
    }

    s.lineEnds.resize(2 * data.numLines());
    s.lineValid.assign(data.numLines(), 0);
    for (int i = 0; i < data.numLines(); ++i)
    {
        const Eigen::Vector3d normal2 = R0.transpose() * data.lines2[i];
        const double offset2 = t0.dot(data.lines2[i]);
        bool valid = true;
        for (int end = 0; end < 2; ++end)
        {
            const Eigen::Vector3d ray = data.calibratedLineEnd(0, i, end).homogeneous();
            const double denominator = normal2.dot(ray);
            // The ray must cut the plane of view 2 at a well-defined depth.
            if (!(std::abs(denominator) > 1e-9 * normal2.norm() * ray.norm()))
            {
                valid = false;
                break;
            }
            const double depth1 = -offset2 / denominator;
            s.lineEnds[2 * i + end] = depth1 * ray;
            // Ends lifted behind view 1 or 2 (grazing rays under noise) are not structure.
            if (!(depth1 > 0) || !((R0 * s.lineEnds[2 * i + end] + t0).z() > 0))
            {
                valid = false;
                break;
            }
        }
        s.lineValid[i] = valid && s.lineEnds[2 * i].allFinite() && s.lineEnds[2 * i + 1].allFinite();
    }
    return s;
}

ReprojectionScore scorePose(const TripletData& data, const TwoViewStructure& structure, const CameraPose& pose,
                            std::vector<double>* pointResiduals, std::vector<double>* lineResiduals)
{
    const double inf = std::numeric_limits<double>::infinity();
    const Eigen::Matrix3d& K3 = data.pixels[2].K;
    const Eigen::Matrix3d KR = K3 * pose.R;
    const Eigen::Vector3d Kt = K3 * pose.t;
    ReprojectionScore score;
    double sum = 0;
    int count = 0;

    if (pointResiduals)
        pointResiduals->assign(data.numPoints(), inf);
    for (int i = 0; i < data.numPoints(); ++i)
    {
        if (!structure.pointValid[i])
            continue;
        const Eigen::Vector3d x = KR * structure.points[i] + Kt;
        ++score.considered;
        if (!(x.z() > 0))
        {
            ++score.behind;
            continue;
        }
        const double e2 = (x.hnormalized() - data.pixels[2].points[i]).squaredNorm();
        sum += e2;
        ++count;
        if (pointResiduals)
            (*pointResiduals)[i] = std::sqrt(e2);
    }

    if (lineResiduals)
        lineResiduals->assign(data.numLines(), inf);
    for (int i = 0; i < data.numLines(); ++i)
    {
        if (!structure.lineValid[i])
            continue;
        const Eigen::Vector3d a = KR * structure.lineEnds[2 * i] + Kt;
        const Eigen::Vector3d b = KR * structure.lineEnds[2 * i + 1] + Kt;
        score.considered += 2;
        const int behind = (a.z() > 0 ? 0 : 1) + (b.z() > 0 ? 0 : 1);
        score.behind += behind;
        if (behind > 0)
            continue;
        Eigen::Vector3d line = a.cross(b);
        const double n = line.head<2>().norm();
        if (!(n > 0))
            continue;
        line /= n;
        const double d0 = line.dot(data.pixels[2].lineEnds[2 * i].homogeneous());
        const double d1 = line.dot(data.pixels[2].lineEnds[2 * i + 1].homogeneous());
        sum += d0 * d0 + d1 * d1;
        count += 2;
        if (lineResiduals)
            (*lineResiduals)[i] = std::sqrt(0.5 * (d0 * d0 + d1 * d1));
    }
    score.rms = count > 0 ? std::sqrt(sum / count) : inf;
    return score;
}

} // namespace detail
} // namespace tripose
} // namespace cv
