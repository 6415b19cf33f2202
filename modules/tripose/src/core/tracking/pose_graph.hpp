// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_POSE_GRAPH_HPP
#define TRIPOSE_CORE_TRACKING_POSE_GRAPH_HPP

#include <vector>

#include "../geometry/camera.hpp"

namespace tripose {

//! A measured relative pose between two camera poses: pose[to] = composePose(relative, pose[from]).
struct PoseGraphEdge
{
    int from = 0;
    int to = 0;
    CameraPose relative;
    double weight = 1; //!< The edge's share of the cost (its inverse variance, the same on all six axes).
};

/** Moves the poses not held so that the edges' relative poses hold as nearly as possible, in the least
squares of each edge's error exp(e) = relative^-1 * pose[to] * pose[from]^-1, read as its rotation
vector (radians) and its translation divided by @p translationScale (the length that weighs as much as
a radian of rotation, typically the distance between consecutive frames). Levenberg-Marquardt over a
left update of each free pose, at most @p maxIterations steps. Returns the final cost (the sum of
the weighted squared errors); the poses are changed only when the cost fell.

Error(BadSize) naming @p held when its size is not that of @p poses; Error(BadArgument) naming the argument when an edge names a pose out of range or
joins a pose to itself, a weight or @p translationScale is not positive and finite, or a free pose is
linked by no chain of edges to a held one (its place would be arbitrary).
*/
double optimizePoseGraph(std::vector<CameraPose>& poses, const std::vector<bool>& held,
                         const std::vector<PoseGraphEdge>& edges, double translationScale, int maxIterations = 30);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_POSE_GRAPH_HPP
