// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <Eigen/Dense>

#include "triangulation.hpp"

namespace tripose {

namespace {

bool selected(const View& view, ViewSelection which)
{
    return which == ViewSelection::All || !view.estimated;
}

} // namespace

std::vector<CameraPose> viewPoses(const ViewSet& set, const CameraPose& estimatedPose)
{
    std::vector<CameraPose> poses(set.views.size());
    for (size_t v = 0; v < set.views.size(); ++v)
        poses[v] = set.views[v].poseFor(estimatedPose);
    return poses;
}

double triangulatePoint(const ViewSet& set, const CameraPose* poses, int point, ViewSelection which,
                        Eigen::Vector3d& X, double minConditioning, double minDepth)
{
    const int numViews = (int)set.views.size();
    // Per-view row weights: the focal length, then divided by the first pass's depth.
    double weightsStorage[8];
    std::vector<double> weightsHeap;
    double* weights = weightsStorage;
    if (numViews > 8)
    {
        weightsHeap.resize(numViews);
        weights = weightsHeap.data();
    }
    int seen = 0;
    for (int v = 0; v < numViews; ++v)
    {
        const View& view = set.views[v];
        const bool use = selected(view, which) && view.seesPoint(point);
        weights[v] = use ? view.camera.fx : 0.0;
        seen += use;
    }
    if (seen < 2)
        return 0;

    double conditioning = 0;
    for (int pass = 0; pass < 2; ++pass)
    {
        Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        for (int v = 0; v < numViews; ++v)
        {
            if (weights[v] == 0)
                continue;
            const CameraPose& p = poses[v];
            const Eigen::Vector2d& x = set.views[v].calibratedPoints[point];
            for (int row = 0; row < 2; ++row)
            {
                // x_row (R_3 X + t_3) - (R_row X + t_row) = 0, weighted.
                const Eigen::Vector3d a = weights[v] * (p.R.row(row) - x(row) * p.R.row(2)).transpose();
                const double rhs = -weights[v] * (p.t(row) - x(row) * p.t(2));
                A.noalias() += a * a.transpose();
                b += rhs * a;
            }
        }
        const double trace = A.trace(), det = A.determinant();
        if (!(trace > 0) || !(det > minConditioning * trace * trace * trace))
            return pass == 0 ? 0 : conditioning;
        const Eigen::Vector3d solution = A.inverse() * b;
        if (!solution.allFinite())
            return pass == 0 ? 0 : conditioning;
        X = solution;
        conditioning = det / (trace * trace * trace);
        if (pass == 1)
            break;
        for (int v = 0; v < numViews; ++v)
        {
            if (weights[v] == 0)
                continue;
            const double z = poses[v].R.row(2).dot(X) + poses[v].t(2);
            if (!(z > minDepth))
                return conditioning; // behind a camera: the caller's depth test rejects it
            weights[v] = set.views[v].camera.fx / z;
        }
    }
    return conditioning;
}

bool triangulateLine(const ViewSet& set, const CameraPose* poses, int line, ViewSelection which, PluckerLine& L,
                     double minRatio)
{
    std::vector<Eigen::Vector4d> planes;
    planes.reserve(set.views.size());
    for (size_t v = 0; v < set.views.size(); ++v)
    {
        const View& view = set.views[v];
        if (selected(view, which) && view.seesLine(line))
            planes.push_back(backProjectLine(poses[v], view.camera.fx, view.calibratedLines[line]));
    }
    if (planes.size() < 2)
        return false;
    return lineFromPlanes(planes.data(), (int)planes.size(), L, minRatio);
}

} // namespace tripose
