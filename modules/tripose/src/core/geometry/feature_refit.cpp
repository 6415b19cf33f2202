// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_refit.hpp"

#include "conditioning.hpp"
#include "residuals.hpp"
#include "segment_cheirality.hpp"
#include "triangulation.hpp"

namespace tripose {

bool refitPoint(const ViewSet& set, const CameraPose* poses, int point, double minDepth, Eigen::Vector3d& X,
                std::vector<Eigen::Vector2d>& residuals)
{
    if (!(triangulatePoint(set, poses, point, ViewSelection::All, X, kPointTriangulationConditioning, minDepth) > 0))
        return false;
    residuals.assign(set.views.size(), Eigen::Vector2d::Zero());
    for (size_t v = 0; v < set.views.size(); ++v)
    {
        const View& view = set.views[v];
        if (view.seesPoint(point) &&
            !pointResidual(view.camera, poses[v].toCamera(X), view.points[point], residuals[v], nullptr, minDepth))
            return false;
    }
    return true;
}

bool refitLine(const ViewSet& set, const CameraPose* poses, int line, PluckerLine& L,
               std::vector<Eigen::Vector2d>& residuals)
{
    if (!triangulateLine(set, poses, line, ViewSelection::All, L, 0.0))
        return false;
    residuals.assign(set.views.size(), Eigen::Vector2d::Zero());
    for (size_t v = 0; v < set.views.size(); ++v)
    {
        const View& view = set.views[v];
        if (!view.seesLine(line))
            continue;
        if (segmentBehindCamera(poses[v], L, view.calibratedLineEnd(line, 0), view.calibratedLineEnd(line, 1)) ||
            !lineResidual(view.camera, lineMomentInCamera(poses[v], L), view.lineEnds[2 * line],
                          view.lineEnds[2 * line + 1], residuals[v]))
            return false;
    }
    return true;
}

void lineEndsSeenBy(const View& view, const CameraPose& viewPose, int line, const PluckerLine& L,
                    Eigen::Vector3d& A, Eigen::Vector3d& B)
{
    const Eigen::Matrix3d toWorld = viewPose.R.transpose();
    A = closestPointToRay(L, toWorld * view.calibratedLineEnd(line, 0).homogeneous(), viewPose.centre());
    B = closestPointToRay(L, toWorld * view.calibratedLineEnd(line, 1).homogeneous(), viewPose.centre());
}

} // namespace tripose
