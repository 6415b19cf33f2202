// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "frame_matching.hpp"

#include <algorithm>

#include "fundamental_estimation.hpp"

namespace tripose {

namespace {

const double kConfidence = 0.999;

} // namespace

bool estimateFundamental(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options,
                         Eigen::Matrix3d& F)
{
    const Matches matches = matchByDescriptor(a.pointDescriptors, b.pointDescriptors, options.pointRatio);
    if ((int)matches.size() < options.minFundamentalInliers)
        return false;
    std::vector<Eigen::Vector2d> xa, xb;
    for (const auto& m : matches)
    {
        xa.push_back(a.points[m.first]);
        xb.push_back(b.points[m.second]);
    }
    Eigen::Matrix3d estimate;
    std::vector<unsigned char> inliers;
    if (estimateFundamentalRansac(xa, xb, options.epipolarDistance, kConfidence, estimate, inliers,
                                  options.minFundamentalInliers) < options.minFundamentalInliers)
        return false;
    F = estimate;
    return true;
}

bool matchUnderFundamental(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options,
                           Matches& points, Matches& segments)
{
    points.clear();
    segments.clear();
    Eigen::Matrix3d F;
    if (!estimateFundamental(a, b, options, F))
        return false;
    points = matchPointsEpipolar(a, b, F, options);
    segments = matchSegmentsEpipolar(a, b, F, options);
    return true;
}

bool matchUnknownPose(const FrameFeatures& a, const FrameFeatures& b, const MatchOptions& options, Matches& points,
                      Matches& segments)
{
    if (matchUnderFundamental(a, b, options, points, segments))
        return true;
    points = matchByDescriptor(a.pointDescriptors, b.pointDescriptors, options.pointRatio);
    segments = matchByDescriptor(a.lineDescriptors, b.lineDescriptors, options.lineRatio,
                                 a.lineDescriptors.binary ? options.maxLineDistance
                                                          : std::numeric_limits<double>::infinity());
    return false;
}

EpipolarAgreement epipolarAgreement(const FrameFeatures& a, const FrameFeatures& b, const Eigen::Matrix3d& F,
                                    const MatchOptions& options)
{
    const int n = (int)a.points.size();
    const int step = std::max(1, (n + kAgreementSample - 1) / kAgreementSample);
    std::vector<int> rows;
    for (int i = 0; i < n; i += step)
        rows.push_back(i);
    EpipolarAgreement agreement;
    if (a.pointDescriptors.rows != n)
        return agreement;
    for (const auto& m : matchByDescriptor(a.pointDescriptors.subset(rows), b.pointDescriptors, options.pointRatio))
    {
        ++agreement.matches;
        agreement.agreeing +=
            withinEpipolarDistance(F, a.points[rows[m.first]], b.points[m.second], options.epipolarDistance) ? 1 : 0;
    }
    return agreement;
}

} // namespace tripose
