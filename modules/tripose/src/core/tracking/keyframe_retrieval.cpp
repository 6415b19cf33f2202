// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "keyframe_retrieval.hpp"

#include <algorithm>
#include <limits>

#include "descriptor_matching.hpp"

namespace tripose {

namespace {

// Rows kept per keyframe and kind: enough for a place seen again to stand out from the others by
// tens of matches, few enough that ranking every keyframe stays cheap.
const int kSampleRows = 300;

Descriptors evenSample(const Descriptors& d)
{
    if (d.rows <= kSampleRows)
        return d;
    std::vector<int> rows;
    for (int k = 0; k < kSampleRows; ++k)
        rows.push_back((int)((long long)k * d.rows / kSampleRows));
    return d.subset(rows);
}

int countMatches(const Descriptors& a, const Descriptors& b, double ratio, double maxDistance)
{
    if (a.empty() || b.empty() || a.binary != b.binary || a.cols != b.cols)
        return 0;
    return (int)matchByDescriptor(a, b, ratio, maxDistance).size();
}

} // namespace

void KeyframeRetrieval::add(int frame, const FrameFeatures& features)
{
    samples_.push_back({ frame, evenSample(features.pointDescriptors), evenSample(features.lineDescriptors) });
}

std::vector<std::pair<int, int>> KeyframeRetrieval::rank(const FrameFeatures& query,
                                                         const std::function<bool(int)>& eligible, int minMatches,
                                                         int maxResults) const
{
    const Descriptors points = evenSample(query.pointDescriptors), lines = evenSample(query.lineDescriptors);
    std::vector<std::pair<int, int>> ranked;
    for (const Sample& s : samples_)
    {
        if (!eligible(s.frame))
            continue;
        const int matches = countMatches(points, s.points, options_.pointRatio, std::numeric_limits<double>::infinity()) +
                            countMatches(lines, s.lines, options_.lineRatio, options_.maxLineDistance);
        if (matches >= minMatches)
            ranked.emplace_back(s.frame, matches);
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.second > b.second; });
    if ((int)ranked.size() > maxResults)
        ranked.resize(maxResults);
    return ranked;
}

} // namespace tripose
