// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_RIG_SOLVER_HPP
#define OPENCV_TRIPOSE_LINEAR_RIG_SOLVER_HPP

#include <vector>

#include "../geometry/view_set.hpp"

namespace tripose {

/** Candidate poses of view 3 (the left camera at time B) of a stereo rig seen at two times, from
the rig system A v = b (rig_system.hpp; the ViewSet layout is described there), before any scoring.

The kernel dimension d and the number of poses that fit exact data come from the feature counts
(rigKernelDimension(), rigSolutionCount()); none fit (e.g. two points seen in both time-B views,
or fewer than six constraints): no candidate. v = v0 + sum_k c_k e_k with v0 the least-squares
solution over the leading 12 - d singular directions of A and e_k the last d right singular
vectors; d = 0 takes v0, d = 1..6 solveAffineKernel(). Each solution's R part is projected onto
the nearest rotation, polished by Gauss-Newton on |A v - b| over SO(3) with t eliminated, and t
re-estimated by least squares with R fixed. Candidates are ordered by
their algebraic residual |A v - b|, smallest first; one where exactly one pose fits, up to 2, 4 or 8
where several do (only reprojection with cheirality can choose among those).

Uses the selected features only (null pointers: all of them). Degenerate geometry (features that do
not fix the pose, e.g. collinear points) gives no candidate, never a non-finite one. Appends to
@p poses and returns how many were appended.
*/
int rigPoseCandidates(const ViewSet& set, std::vector<CameraPose>& poses,
                      const std::vector<int>* pointIndices = nullptr,
                      const std::vector<int>* lineIndices = nullptr);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_RIG_SOLVER_HPP
