// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "candidate_ranking.hpp"

#include <algorithm>
#include <cmath>

namespace tripose {

std::vector<ScoredPose> rankCandidates(const PoseScorer& scorer, const std::vector<CameraPose>& poses)
{
    std::vector<ScoredPose> ranked;
    for (const CameraPose& pose : poses)
    {
        const PoseScore score = scorer.score(pose);
        const double rms = score.rms();
        if (2 * score.behind > score.considered || !std::isfinite(rms))
            continue;
        ScoredPose scored;
        scored.pose = pose;
        scored.rms = rms;
        ranked.push_back(scored);
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const ScoredPose& a, const ScoredPose& b) { return a.rms < b.rms; });
    return ranked;
}

} // namespace tripose
