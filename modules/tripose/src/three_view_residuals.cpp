// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>

#include "three_view_residuals.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

typedef Eigen::Matrix<double, 3, 4> Matrix34d;

double pointResidual(const TripletData& data, const Matrix34d P[3], const Matrix34d KP[3], int i)
{
    const std::vector<Eigen::Vector2d>* calibrated[3] = { &data.points1, &data.points2, &data.points3 };
    // x (P3 X) - P1 X = 0 and y (P3 X) - P2 X = 0 per view, inhomogeneous X: 6x3 least squares.
    Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Atb = Eigen::Vector3d::Zero();
    for (int v = 0; v < 3; ++v)
    {
        const Eigen::Vector2d& x = (*calibrated[v])[i];
        for (int c = 0; c < 2; ++c)
        {
            const Eigen::Matrix<double, 1, 4> row = x(c) * P[v].row(2) - P[v].row(c);
            AtA += row.head<3>().transpose() * row.head<3>();
            Atb -= row.head<3>().transpose() * row(3);
        }
    }
    Eigen::LDLT<Eigen::Matrix3d> ldlt(AtA);
    const Eigen::Vector3d X = ldlt.solve(Atb);
    if (ldlt.info() != Eigen::Success || !X.allFinite())
        return std::numeric_limits<double>::infinity();
    double sum = 0;
    for (int v = 0; v < 3; ++v)
    {
        const Eigen::Vector3d x = KP[v] * X.homogeneous();
        if (!(x.z() > 0))
            return std::numeric_limits<double>::infinity();
        sum += (x.hnormalized() - data.pixels[v].points[i]).squaredNorm();
    }
    return std::sqrt(sum / 6.0);
}

double lineResidual(const TripletData& data, const Matrix34d KP[3], int i)
{
    // The 3D line is the (approximate) 2D null space of the three back-projected planes (K P)^T l,
    // l the observed line in pixels with unit normal, so that a plane's value at a point is its
    // depth times the pixel distance of its projection to l: a near-geometric fit.
    Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
    for (int v = 0; v < 3; ++v)
    {
        const Eigen::Vector3d a = data.pixels[v].lineEnds[2 * i].homogeneous();
        const Eigen::Vector3d b = data.pixels[v].lineEnds[2 * i + 1].homogeneous();
        Eigen::Vector3d l = a.cross(b);
        l /= l.head<2>().norm();
        const Eigen::Vector4d plane = KP[v].transpose() * l;
        M += plane * plane.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(M);
    if (eigen.info() != Eigen::Success)
        return std::numeric_limits<double>::infinity();
    const Eigen::Vector4d A = eigen.eigenvectors().col(0), B = eigen.eigenvectors().col(1);
    double sum = 0;
    for (int v = 0; v < 3; ++v)
    {
        Eigen::Vector3d line = (KP[v] * A).cross(KP[v] * B);
        const double n = line.head<2>().norm();
        if (!(n > 0))
            return std::numeric_limits<double>::infinity();
        line /= n;
        for (int end = 0; end < 2; ++end)
        {
            const double d = line.dot(data.pixels[v].lineEnds[2 * i + end].homogeneous());
            sum += d * d;
        }
    }
    return std::sqrt(sum / 6.0);
}

} // namespace

void threeViewResiduals(const TripletData& data, const CameraPose& pose,
                        std::vector<double>& pointResiduals, std::vector<double>& lineResiduals)
{
    Matrix34d P[3], KP[3];
    P[0] << Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero();
    P[1] << data.view2.R, data.view2.t;
    P[2] << pose.R, pose.t;
    for (int v = 0; v < 3; ++v)
        KP[v] = data.pixels[v].K * P[v];
    pointResiduals.resize(data.numPoints());
    for (int i = 0; i < data.numPoints(); ++i)
        pointResiduals[i] = pointResidual(data, P, KP, i);
    lineResiduals.resize(data.numLines());
    for (int i = 0; i < data.numLines(); ++i)
        lineResiduals[i] = lineResidual(data, KP, i);
}

} // namespace detail
} // namespace tripose
} // namespace cv
