// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_matching.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>

namespace tripose_samples {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

/** Keeps the mutual best pairs of a candidate list: (a, b) when b is a's best candidate, a is b's best
candidate, and a's best is below @p ratio times a's second best. Candidates arrive grouped by a,
in any order within a group. */
class MutualBest
{
public:
    MutualBest(int rowsA, int rowsB)
        : bestOfA_(rowsA, -1), bestDistanceOfA_(rowsA, kInf), secondOfA_(rowsA, kInf), bestOfB_(rowsB, -1),
          bestDistanceOfB_(rowsB, kInf)
    {
    }

    void add(int a, int b, double distance)
    {
        if (distance < bestDistanceOfA_[a])
        {
            secondOfA_[a] = bestDistanceOfA_[a];
            bestDistanceOfA_[a] = distance;
            bestOfA_[a] = b;
        }
        else if (distance < secondOfA_[a])
            secondOfA_[a] = distance;
        if (distance < bestDistanceOfB_[b])
        {
            bestDistanceOfB_[b] = distance;
            bestOfB_[b] = a;
        }
    }

    Matches result(double ratio) const
    {
        Matches matches;
        for (int a = 0; a < (int)bestOfA_.size(); ++a)
        {
            const int b = bestOfA_[a];
            if (b < 0 || bestOfB_[b] != a)
                continue;
            // A lone candidate passes: the geometry alone singled it out.
            if (std::isfinite(secondOfA_[a]) && !(bestDistanceOfA_[a] < ratio * secondOfA_[a]))
                continue;
            matches.emplace_back(a, b);
        }
        return matches;
    }

private:
    std::vector<int> bestOfA_;
    std::vector<double> bestDistanceOfA_, secondOfA_;
    std::vector<int> bestOfB_;
    std::vector<double> bestDistanceOfB_;
};

double descriptorDistance(const cv::Mat& a, int i, const cv::Mat& b, int j)
{
    return cv::norm(a.row(i), b.row(j), a.depth() == CV_8U ? cv::NORM_HAMMING : cv::NORM_L2);
}

cv::Vec3d homogeneous(const double* x)
{
    return cv::Vec3d(x[0], x[1], 1);
}

//! The line @p l scaled so that l . (x, y, 1) is the distance of (x, y) from it in pixels.
cv::Vec3d distanceNormalised(const cv::Vec3d& l)
{
    return l / std::max(std::hypot(l[0], l[1]), 1e-300);
}

//! Whether @p xa and @p xb each lie within @p distance of the other's epipolar line under @p F.
bool withinEpipolarDistance(const cv::Matx33d& F, const cv::Vec3d& xa, const cv::Vec3d& xb, double distance)
{
    return std::abs(distanceNormalised(F * xa).dot(xb)) <= distance &&
           std::abs(distanceNormalised(F.t() * xb).dot(xa)) <= distance;
}

/** Where segment @p s (x0 y0 x1 y1) crosses the lines @p la and @p lb, as parameters along it (0 at
its first end, 1 at its second): @p atA where it crosses la, @p atB where lb; false when it runs
within @p minSine of either line. */
bool bandOnSegment(const double* s, const cv::Vec3d& la, const cv::Vec3d& lb, double minSine, double& atA, double& atB)
{
    const cv::Point2d p(s[0], s[1]), d(s[2] - s[0], s[3] - s[1]);
    const double length = std::hypot(d.x, d.y);
    double u[2];
    const cv::Vec3d* lines[2] = { &la, &lb };
    for (int k = 0; k < 2; ++k)
    {
        const cv::Vec3d& l = *lines[k];
        const double normal = std::hypot(l[0], l[1]);
        const double across = l[0] * d.x + l[1] * d.y; // = normal * length * sin(angle to the line)
        if (!(std::abs(across) > minSine * normal * length))
            return false;
        u[k] = -(l[0] * p.x + l[1] * p.y + l[2]) / across;
    }
    atA = u[0];
    atB = u[1];
    return true;
}

} // namespace

MatchOptions withPixelScale(MatchOptions options, double pixelScale)
{
    options.epipolarDistance *= pixelScale;
    return options;
}

Matches matchPointsEpipolar(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                            const MatchOptions& options)
{
    const int na = a.points.rows, nb = b.points.rows;
    MutualBest best(na, nb);
    // The epipolar lines of b's points in image a, normalised so that l . x is a distance in pixels.
    std::vector<cv::Vec3d> linesInA(nb);
    for (int j = 0; j < nb; ++j)
        linesInA[j] = distanceNormalised(F.t() * homogeneous(b.points.ptr<double>(j)));
    for (int i = 0; i < na; ++i)
    {
        const cv::Vec3d xa = homogeneous(a.points.ptr<double>(i));
        const cv::Vec3d l = distanceNormalised(F * xa);
        for (int j = 0; j < nb; ++j)
        {
            const double* xb = b.points.ptr<double>(j);
            if (std::abs(l[0] * xb[0] + l[1] * xb[1] + l[2]) > options.epipolarDistance ||
                std::abs(linesInA[j].dot(xa)) > options.epipolarDistance)
                continue;
            best.add(i, j, descriptorDistance(a.pointDescriptors, i, b.pointDescriptors, j));
        }
    }
    return best.result(options.pointRatio);
}

Matches matchSegmentsEpipolar(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                              const MatchOptions& options)
{
    const int na = a.segments.rows, nb = b.segments.rows;
    MutualBest best(na, nb);
    const double minSine = std::sin(options.minEpipolarAngleDeg * CV_PI / 180);
    for (int i = 0; i < na; ++i)
    {
        const double* s = a.segments.ptr<double>(i);
        const cv::Vec3d la = F * homogeneous(s), lb = F * homogeneous(s + 2);
        for (int j = 0; j < nb; ++j)
        {
            double lo, hi;
            if (!bandOnSegment(b.segments.ptr<double>(j), la, lb, minSine, lo, hi))
                continue;
            // Both segments run with the brighter side on their right (segment_edge_fit.hpp), as every
            // view of an edge sees it, and a view keeps the order of points along a line: the band
            // of a's first end point comes first along b. The other way round, b is another edge.
            if (!(lo < hi))
                continue;
            // The segment spans [0, 1]; the band [lo, hi] along it. Detected segments break up and
            // stop short at different places in the two images: require the overlap to cover a
            // good part of the shorter of the two, not of both.
            const double overlap = std::min(hi, 1.0) - std::max(lo, 0.0);
            if (!(overlap > 0) || overlap < options.minBandOverlap * std::min(1.0, hi - lo))
                continue;
            const double distance = descriptorDistance(a.lineDescriptors, i, b.lineDescriptors, j);
            if (distance <= options.maxLineDistance)
                best.add(i, j, distance);
        }
    }
    return best.result(options.lineRatio);
}

Matches matchByDescriptor(const cv::Mat& descriptorsA, const cv::Mat& descriptorsB, double ratio, double maxDistance)
{
    const int na = descriptorsA.rows, nb = descriptorsB.rows;
    if (na == 0 || nb == 0)
        return {};
    const int norm = descriptorsA.depth() == CV_8U ? cv::NORM_HAMMING : cv::NORM_L2;
    // Hamming distances come as integers.
    cv::Mat distances;
    cv::batchDistance(descriptorsA, descriptorsB, distances, norm == cv::NORM_HAMMING ? CV_32S : CV_32F,
                      cv::noArray(), norm);
    distances.convertTo(distances, CV_32F);
    MutualBest best(na, nb);
    for (int i = 0; i < na; ++i)
    {
        const float* row = distances.ptr<float>(i);
        for (int j = 0; j < nb; ++j)
            if (row[j] <= maxDistance)
                best.add(i, j, row[j]);
    }
    return best.result(ratio);
}

std::string EpipolarAgreement::summary() const
{
    return cv::format("of %d point matches found without the poses, %d (%.0f %%) lie on their epipolar lines "
                      "(73-88 %% where the poses are right)",
                      matches, agreeing, 100 * fraction());
}

EpipolarAgreement epipolarAgreement(const ImageFeatures& a, const ImageFeatures& b, const cv::Matx33d& F,
                                    const MatchOptions& options)
{
    // A subset keeps the descriptor distances to a few milliseconds (4000 points per Merton image).
    const int step = std::max(1, (a.points.rows + kAgreementSample - 1) / kAgreementSample);
    std::vector<int> rows;
    cv::Mat descriptors;
    for (int i = 0; i < a.points.rows; i += step)
    {
        rows.push_back(i);
        descriptors.push_back(a.pointDescriptors.row(i));
    }
    EpipolarAgreement agreement;
    for (const auto& m : matchByDescriptor(descriptors, b.pointDescriptors, options.pointRatio, kInf))
    {
        ++agreement.matches;
        agreement.agreeing += withinEpipolarDistance(F, homogeneous(a.points.ptr<double>(rows[m.first])),
                                                     homogeneous(b.points.ptr<double>(m.second)),
                                                     options.epipolarDistance);
    }
    return agreement;
}

bool estimateFundamental(const ImageFeatures& a, const ImageFeatures& b, const MatchOptions& options, cv::Matx33d& F)
{
    const Matches matches = matchByDescriptor(a.pointDescriptors, b.pointDescriptors, options.pointRatio, kInf);
    if ((int)matches.size() < options.minFundamentalInliers)
        return false;
    std::vector<cv::Point2d> xa, xb;
    for (const auto& m : matches)
    {
        xa.emplace_back(a.points.at<double>(m.first, 0), a.points.at<double>(m.first, 1));
        xb.emplace_back(b.points.at<double>(m.second, 0), b.points.at<double>(m.second, 1));
    }
    cv::Mat inliers;
    // OpenCV's RANSAC seeds its generator alike on every call: the same images give the same matrix.
    const cv::Mat estimate = cv::findFundamentalMat(xa, xb, cv::FM_RANSAC, options.epipolarDistance, 0.999, inliers);
    if (estimate.rows != 3 || cv::countNonZero(inliers) < options.minFundamentalInliers)
        return false;
    F = cv::Matx33d(estimate);
    return true;
}

bool matchUnknownPose(const ImageFeatures& a, const ImageFeatures& b, const MatchOptions& options, Matches& points,
                      Matches& segments)
{
    cv::Matx33d F;
    if (estimateFundamental(a, b, options, F))
    {
        points = matchPointsEpipolar(a, b, F, options);
        segments = matchSegmentsEpipolar(a, b, F, options);
        return true;
    }
    points = matchByDescriptor(a.pointDescriptors, b.pointDescriptors, options.pointRatio, kInf);
    segments = matchByDescriptor(a.lineDescriptors, b.lineDescriptors, options.lineRatio, options.maxLineDistance);
    return false;
}

} // namespace tripose_samples
