// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_PIPELINE_POSE_PIPELINES_HPP
#define TRIPOSE_CORE_PIPELINE_POSE_PIPELINES_HPP

#include <vector>

#include "../estimator/pose_solver.hpp"
#include "../estimator/scored_pose.hpp"
#include "../geometry/view_set.hpp"
#include "../refine/ml_refinement.hpp"
#include "../robust/robust_estimator.hpp"
#include "../scoring/pose_scorer.hpp"
#include "../support/options.hpp"

namespace tripose {

/** What every entry point does once its arguments are a ViewSet and it has chosen the PoseSolver of
its arrangement of views (three-view, stereo rig, several known views). The adapters (the OpenCV
module, the Python package) read their arguments into a ViewSet (problem/), call one of these and
write the result in their own types.
*/

/** The solver's candidates from all features, ranked by their reprojection error (best first,
rankCandidates()); with @p refine, each refined over every view (and, where the cost may have
several basins, from starts around the best one), the distinct minima ranked by their RMS.
*/
std::vector<ScoredPose> estimateCandidates(const ViewSet& views, const PoseSolver& solver, bool refine);

/** Where the final refinement looks for the minimum: from further starts where the structure's
regime allows several basins (a single estimate), or from the estimate alone (a tracked frame,
whose pose its neighbours already place in the right basin).
*/
enum class BasinSearch
{
    WhereSeveral,
    EstimateOnly
};

/** The robust estimate: RANSAC over @p solver's samples scored by @p scorer, then the refinement
that @p options asks for. @p options must be valid (checkRansacOptions()). Returns false (and @p estimate's masks all zero) when no pose was found
or the pose has fewer than RansacOptions::minInliers inliers.
*/
bool estimateRobust(const ViewSet& views, const PoseScorer& scorer, const PoseSolver& solver,
                    const RansacOptions& options, RobustEstimate& estimate,
                    BasinSearch basins = BasinSearch::WhereSeveral);

/** The robust estimate of one estimated view on the structure of known views (three views, several
known views): the hybrid sample solver (robust/hybrid_pose_solver.hpp) over @p linear, its minimal
samples solved on the structure that the scorer triangulates from the known views.
*/
bool estimateRobustOnKnownStructure(const ViewSet& views, const PoseSolver& linear, const RansacOptions& options,
                                    RobustEstimate& estimate, BasinSearch basins = BasinSearch::WhereSeveral);

/** The robust estimate of a stereo rig's pose at time B (linear/rig_system.hpp's layout): the hybrid
sample solver over the rig's linear solver, its minimal samples drawn from the features of one
time-B camera at a time and solved on the structure of the rig at time A, every hypothesis scored
with that structure free to slide along the rays of view 1 (PoseScorer::KnownDepth::Slides): the
rig's short baseline places it poorly in depth.
*/
bool estimateRobustRig(const ViewSet& views, const RansacOptions& options, RobustEstimate& estimate);

/** Refines @p pose (in place) and the structure over every view of @p views; @p options must be
valid (checkRefineOptions()). @p covariance, when given, receives the uncertainty of the refined
pose. Returns the final RMS reprojection error (px).
*/
double refineInitialPose(const ViewSet& views, CameraPose& pose, const RefineOptions& options,
                         RefinedStructure* structure = nullptr, PoseCovariance* covariance = nullptr);

/** The uncertainty of @p pose, a maximum-likelihood estimate that estimateCandidates() or
estimateRobust() returned, over the features of the masks (null: every feature): the refinement
with @p options run once more from @p pose (where it only re-converges the structure) reports it.
@p pose itself is not changed.
*/
PoseCovariance covarianceOfEstimate(const ViewSet& views, const CameraPose& pose, const RefineOptions& options,
                                    const std::vector<unsigned char>* pointMask = nullptr,
                                    const std::vector<unsigned char>* lineMask = nullptr);

/** Refines several poses (@p poseOfView, @p poses as in refinePosesAndStructure()) and the
structure; @p options must be valid. Returns the final RMS reprojection error (px).
*/
double refineSeveralPoses(const ViewSet& views, const std::vector<int>& poseOfView, std::vector<CameraPose>& poses,
                          const RefineOptions& options, RefinedStructure* structure = nullptr);

//! Every view's pose after refineSeveralPoses(): the refined ones from @p poses, the fixed ones as given.
std::vector<CameraPose> allViewPoses(const ViewSet& views, const std::vector<int>& poseOfView,
                                     const std::vector<CameraPose>& poses);

} // namespace tripose

#endif // TRIPOSE_CORE_PIPELINE_POSE_PIPELINES_HPP
