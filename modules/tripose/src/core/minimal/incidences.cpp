// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "incidences.hpp"
#include "../geometry/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace tripose {

namespace {

constexpr int kMaxNewtonSteps = 4;
// Residual angles below this are rounding: Newton stops.
constexpr double kConvergedSine = 1e-14;
// An exact pose of a well-posed instance polishes far below this; a spurious root stays far above.
constexpr double kAcceptedSine = 1e-8;

//! Residuals, each divided by the length it scales with (see polishPose), and the Jacobian rows.
double evaluate(const MinimalIncidences& incidences, const CameraPose& pose, Eigen::Matrix<double, 6, 1>& r,
                Eigen::Matrix<double, 6, 6>* J)
{
    double worstSine = 0;
    for (int k = 0; k < 6; ++k)
    {
        const Incidence& c = incidences[k];
        const Eigen::Vector3d rotated = pose.R * c.world;
        const Eigen::Vector3d v = c.isDirection ? rotated : Eigen::Vector3d(rotated + pose.t);
        r(k) = c.normal.dot(v);
        const double length = v.norm();
        worstSine = std::max(worstSine, length > 0 ? std::abs(r(k)) / length : std::abs(r(k)));
        if (J)
        {
            // d/dw n^T (Exp(w) R Y) at w = 0 is n^T (w x R Y) = w . (R Y x n).
            J->block<1, 3>(k, 0) = rotated.cross(c.normal).transpose();
            J->block<1, 3>(k, 3) = c.isDirection ? Eigen::RowVector3d::Zero() : Eigen::RowVector3d(c.normal.transpose());
        }
    }
    return std::isfinite(worstSine) ? worstSine : std::numeric_limits<double>::infinity();
}

} // namespace

Eigen::Vector3d orthogonalUnitVector(const Eigen::Vector3d& a)
{
    // Crossing with the axis least aligned with a keeps the result well conditioned.
    int axis = 0;
    if (std::abs(a.y()) < std::abs(a(axis)))
        axis = 1;
    if (std::abs(a.z()) < std::abs(a(axis)))
        axis = 2;
    return a.cross(Eigen::Vector3d::Unit(axis)).normalized();
}

void pointIncidences(const Eigen::Vector3d& f, const Eigen::Vector3d& X, Incidence* out)
{
    const Eigen::Vector3d u = orthogonalUnitVector(f);
    out[0] = Incidence{ u, X, false };
    out[1] = Incidence{ f.cross(u), X, false };
}

void lineIncidences(const Eigen::Vector3d& n, const WorldLine& line, Incidence* out)
{
    out[0] = Incidence{ n, line.point, false };
    out[1] = Incidence{ n, line.direction.normalized(), true };
}

bool polishPose(const MinimalIncidences& incidences, CameraPose& pose)
{
    Eigen::Matrix<double, 6, 1> r;
    Eigen::Matrix<double, 6, 6> J;
    double sine = evaluate(incidences, pose, r, &J);
    for (int step = 0; step < kMaxNewtonSteps && sine > kConvergedSine; ++step)
    {
        const Eigen::Matrix<double, 6, 1> delta = -J.partialPivLu().solve(r);
        if (!delta.allFinite())
            break;
        CameraPose next = pose;
        next.R = rotateLeft(delta.head<3>(), pose.R);
        next.t += delta.tail<3>();
        Eigen::Matrix<double, 6, 1> nextR;
        Eigen::Matrix<double, 6, 6> nextJ;
        const double nextSine = evaluate(incidences, next, nextR, &nextJ);
        // Far from a root Newton may diverge: keep only steps that improve.
        if (!(nextSine < sine))
            break;
        pose = next;
        sine = nextSine;
        r = nextR;
        J = nextJ;
    }
    return sine < kAcceptedSine && pose.allFinite();
}

} // namespace tripose
