// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "triplet_matching.hpp"

namespace tripose {

namespace {

/** The features of @p view in the rows @p pairs (their second member): what a feature of a pair of
views 1-2 looks like in view 2. */
FrameFeatures pairsInView2(const FrameFeatures& view, const Matches& pointPairs, const Matches& segmentPairs)
{
    FrameFeatures out;
    std::vector<int> pointRows, segmentRows;
    for (const auto& m : pointPairs)
    {
        out.points.push_back(view.points[m.second]);
        pointRows.push_back(m.second);
    }
    for (const auto& m : segmentPairs)
    {
        out.segments.push_back(view.segments[m.second]);
        segmentRows.push_back(m.second);
    }
    out.pointDescriptors = view.pointDescriptors.subset(pointRows);
    out.lineDescriptors = view.lineDescriptors.subset(segmentRows);
    return out;
}

//! The rows in the three views of each pair of views 1-2 (@p pairs12) that @p toView3 matches
//! (row of @p pairs12, row in view 3).
void tripletRows(const Matches& pairs12, const Matches& toView3, std::vector<int> (&rows)[3])
{
    for (const auto& m : toView3)
    {
        rows[0].push_back(pairs12[m.first].first);
        rows[1].push_back(pairs12[m.first].second);
        rows[2].push_back(m.second);
    }
}

} // namespace

FeatureTriplets matchTriplets(const FrameFeatures views[3], const Eigen::Matrix3d K[3], const CameraPose& pose12,
                              const MatchOptions& options)
{
    const Eigen::Matrix3d F = fundamentalFromPose(K[0], K[1], pose12);
    FeatureTriplets out;
    out.pairAgreement = epipolarAgreement(views[0], views[1], F, options);
    const Matches points12 = matchPointsEpipolar(views[0], views[1], F, options);
    const Matches segments12 = matchSegmentsEpipolar(views[0], views[1], F, options);
    out.pointPairs = (int)points12.size();
    out.segmentPairs = (int)segments12.size();
    // View 3's pose is what is sought, but the geometry of views 2-3 shows in their descriptor
    // matches: under the fundamental matrix estimated from them, matching takes the form it has for
    // views 1-2 and rejects descriptor matches that no rigid motion explains.
    Matches points23, segments23;
    matchUnknownPose(pairsInView2(views[1], points12, segments12), views[2], options, points23, segments23);
    tripletRows(points12, points23, out.pointRows);
    tripletRows(segments12, segments23, out.segmentRows);
    return out;
}

} // namespace tripose
