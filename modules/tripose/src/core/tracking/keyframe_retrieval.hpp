// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_KEYFRAME_RETRIEVAL_HPP
#define TRIPOSE_CORE_TRACKING_KEYFRAME_RETRIEVAL_HPP

#include <functional>
#include <utility>
#include <vector>

#include "epipolar_matching.hpp"
#include "frame_features.hpp"

namespace tripose {

/** The keyframes that look most like a frame, judged by descriptors alone: an evenly spread sample
of each keyframe's point and segment descriptors is kept, and a query's sample is matched to each
(mutual best with the ratio test); the keyframes with the most matches are the candidates of a place
seen before, for closing a loop and for finding a lost camera again. Their geometry is checked by
the caller.
*/
class KeyframeRetrieval
{
public:
    explicit KeyframeRetrieval(const MatchOptions& options) : options_(options) {}

    void add(int frame, const FrameFeatures& features);

    /** Up to @p maxResults keyframes for which @p eligible holds, as (frame, matches), most matches
    first, each with at least @p minMatches. */
    std::vector<std::pair<int, int>> rank(const FrameFeatures& query, const std::function<bool(int)>& eligible,
                                          int minMatches, int maxResults) const;

private:
    struct Sample
    {
        int frame;
        Descriptors points, lines;
    };
    MatchOptions options_;
    std::vector<Sample> samples_;
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_KEYFRAME_RETRIEVAL_HPP
