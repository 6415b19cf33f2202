// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_triplets.hpp"


#include "two_view_geometry.hpp"

namespace tripose_samples {

cv::Mat matchedRows(const cv::Mat& rows, const Matches& pairs, bool first)
{
    cv::Mat out((int)pairs.size(), rows.cols, rows.type());
    for (size_t k = 0; k < pairs.size(); ++k)
        rows.row(first ? pairs[k].first : pairs[k].second).copyTo(out.row((int)k));
    return out;
}

namespace {

/** The features of @p view in the rows of @p pairs (their second member): what a feature of a pair of
views 1-2 looks like in view 2. */
ImageFeatures pairsInView2(const ImageFeatures& view, const Matches& pointPairs, const Matches& segmentPairs)
{
    ImageFeatures out;
    out.points = matchedRows(view.points, pointPairs, false);
    out.pointDescriptors = matchedRows(view.pointDescriptors, pointPairs, false);
    out.segments = matchedRows(view.segments, segmentPairs, false);
    out.lineDescriptors = matchedRows(view.lineDescriptors, segmentPairs, false);
    return out;
}

/** Rows of the three views' @p positions for each pair of views 1-2 (@p pairs12) that @p toView3
matches (row of @p pairs12, row in view 3). */
void tracks(const Matches& pairs12, const Matches& toView3, const cv::Mat positions[3], cv::Mat out[3])
{
    Matches track1, track2;
    for (const auto& m : toView3)
    {
        track1.emplace_back(pairs12[m.first].first, m.second);
        track2.emplace_back(pairs12[m.first].second, m.second);
    }
    out[0] = matchedRows(positions[0], track1, true);
    out[1] = matchedRows(positions[1], track2, true);
    out[2] = matchedRows(positions[2], toView3, false);
}

} // namespace

FeatureTriplets matchTriplets(const ImageFeatures views[3], const cv::Matx33d K[3], const cv::Matx33d& R12,
                              const cv::Vec3d& t12, const MatchOptions& options, StageTimes& times,
                              EpipolarAgreement* pairAgreement)
{
    const int64 start = cv::getTickCount();
    const cv::Matx33d F = fundamentalMatrix(K[0], K[1], R12, t12);
    FeatureTriplets out;
    if (pairAgreement)
        *pairAgreement = epipolarAgreement(views[0], views[1], F, options);

    const Matches points12 = matchPointsEpipolar(views[0], views[1], F, options);
    const Matches segments12 = matchSegmentsEpipolar(views[0], views[1], F, options);
    out.pointPairs = (int)points12.size();
    out.segmentPairs = (int)segments12.size();

    // View 3 against the pairs' features in view 2. Its pose is what is sought, but the geometry of
    // views 2-3 shows in their descriptor matches: under the fundamental matrix estimated from them,
    // matching takes the same form as for views 1-2 (candidates near the epipolar lines, then
    // descriptors), which rejects descriptor matches that no rigid motion explains and lets segments
    // be matched by the band of their end points. Without enough matches for that geometry, the
    // descriptors alone decide.
    const ImageFeatures pairs = pairsInView2(views[1], points12, segments12);
    Matches points23, segments23;
    matchUnknownPose(pairs, views[2], options, points23, segments23);
    const cv::Mat pointPositions[3] = { views[0].points, views[1].points, views[2].points };
    const cv::Mat segmentPositions[3] = { views[0].segments, views[1].segments, views[2].segments };
    tracks(points12, points23, pointPositions, out.points);
    tracks(segments12, segments23, segmentPositions, out.lines);

    times.matching += 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    return out;
}

} // namespace tripose_samples
