// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_SCORING_CANDIDATE_RANKING_HPP
#define TRIPOSE_CORE_SCORING_CANDIDATE_RANKING_HPP

#include <vector>

#include "../estimator/scored_pose.hpp"
#include "pose_scorer.hpp"

namespace tripose {

/** The paper's selection (Sec. III-G): drops candidates that put most of the structure (from the
known views) behind the estimated view and sorts the rest by their reprojection error there
(PoseScorer::score(), untruncated), best first.
*/
std::vector<ScoredPose> rankCandidates(const PoseScorer& scorer, const std::vector<CameraPose>& poses);

} // namespace tripose

#endif // TRIPOSE_CORE_SCORING_CANDIDATE_RANKING_HPP
