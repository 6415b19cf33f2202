// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_triplets.hpp"

#include <limits>

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

/** Extends the pairs (view 1 row, view 2 row) of one kind to view 3 by descriptor: rows of the
three views' @p positions for every pair whose view-2 descriptor finds a mutual match in view 3. */
void extendToView3(const Matches& pairs12, const cv::Mat positions[3], const cv::Mat& descriptors2,
                   const cv::Mat& descriptors3, double ratio, double maxDistance, cv::Mat out[3])
{
    const cv::Mat pairDescriptors = matchedRows(descriptors2, pairs12, false);
    const Matches toView3 = matchByDescriptor(pairDescriptors, descriptors3, ratio, maxDistance);
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
                              const cv::Vec3d& t12, const MatchOptions& options, StageTimes& times)
{
    const int64 start = cv::getTickCount();
    const cv::Matx33d F = fundamentalMatrix(K[0], K[1], R12, t12);
    FeatureTriplets out;

    const Matches points12 = matchPointsEpipolar(views[0], views[1], F, options);
    const cv::Mat pointPositions[3] = { views[0].points, views[1].points, views[2].points };
    extendToView3(points12, pointPositions, views[1].pointDescriptors, views[2].pointDescriptors, options.pointRatio,
                  std::numeric_limits<double>::infinity(), out.points);
    out.pointPairs = (int)points12.size();

    const Matches segments12 = matchSegmentsEpipolar(views[0], views[1], F, options);
    const cv::Mat segmentPositions[3] = { views[0].segments, views[1].segments, views[2].segments };
    extendToView3(segments12, segmentPositions, views[1].lineDescriptors, views[2].lineDescriptors, options.lineRatio,
                  options.maxLineDistance, out.lines);
    out.segmentPairs = (int)segments12.size();

    times.matching += 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    return out;
}

} // namespace tripose_samples
