// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "image_sequence.hpp"

#include <algorithm>
#include <limits>

#include "two_view_geometry.hpp"

namespace tripose_samples {

namespace {

//! How many frames back a frame is matched when the nearer ones share too few matches with it.
constexpr int kMaxFrameGap = 3;

/** Tracks of one kind of feature: per track, its row in each frame's features (-1: not seen). */
class TrackBuilder
{
public:
    explicit TrackBuilder(const std::vector<int>& featuresPerFrame)
    {
        for (int n : featuresPerFrame)
            trackOf_.emplace_back(n, -1);
    }

    //! Matches (row in frame @p from, row in frame @p to), @p from < @p to: each extends its track in
    //! frame @p from, or starts one.
    void add(int from, int to, const Matches& matches)
    {
        for (const auto& m : matches)
        {
            int& track = trackOf_[from][m.first];
            if (track < 0)
            {
                track = (int)rows_.size();
                rows_.emplace_back(trackOf_.size(), -1);
                rows_.back()[from] = m.first;
            }
            rows_[track][to] = m.second;
            trackOf_[to][m.second] = track;
        }
    }

    //! Per frame, a row per track (width columns of @p positions[frame]), NaN where unseen.
    std::vector<cv::Mat> observations(const std::vector<cv::Mat>& positions, int width) const
    {
        std::vector<cv::Mat> out;
        for (size_t f = 0; f < trackOf_.size(); ++f)
        {
            cv::Mat m((int)rows_.size(), width, CV_64F, cv::Scalar::all(std::numeric_limits<double>::quiet_NaN()));
            for (size_t t = 0; t < rows_.size(); ++t)
                if (rows_[t][f] >= 0)
                    positions[f].row(rows_[t][f]).copyTo(m.row((int)t));
            out.push_back(rows_.empty() ? cv::Mat() : m);
        }
        return out;
    }

private:
    std::vector<std::vector<int>> trackOf_; //!< Per frame, per feature row: its track, or -1.
    std::vector<std::vector<int>> rows_;    //!< Per track, per frame: the feature row, or -1.
};

} // namespace

SequenceObservations observationsFromImages(const std::vector<cv::Mat>& images,
                                            const std::vector<cv::Mat>& cameraMatrices, const cv::Mat& R0,
                                            const cv::Mat& t0, const cv::Mat& R1, const cv::Mat& t1,
                                            const FeatureOptions& featureOptions, const MatchOptions& matchOptions,
                                            StageTimes& times, EpipolarAgreement* givenPairAgreement)
{
    const int F = (int)images.size();
    CV_Assert(F >= 2 && (int)cameraMatrices.size() == F);
    std::vector<cv::Matx33d> K;
    for (const cv::Mat& m : cameraMatrices)
        K.emplace_back(m);
    const std::vector<ImageFeatures> features = extractFeaturesOfImages(images, K, {}, featureOptions, times);
    std::vector<int> points(F), segments(F);
    std::vector<cv::Mat> pointPositions(F), segmentPositions(F);
    for (int k = 0; k < F; ++k)
    {
        points[k] = features[k].points.rows;
        segments[k] = features[k].segments.rows;
        pointPositions[k] = features[k].points;
        segmentPositions[k] = features[k].segments;
    }

    const int64 start = cv::getTickCount();
    TrackBuilder pointTracks(points), segmentTracks(segments);
    // Frame 1 relative to frame 0.
    const cv::Mat R01 = R1 * R0.t(), t01 = t1 - R01 * t0;
    const cv::Matx33d F01 = fundamentalMatrix(cv::Matx33d(cameraMatrices[0]), cv::Matx33d(cameraMatrices[1]),
                                              cv::Matx33d(R01), cv::Vec3d(t01));
    if (givenPairAgreement)
        *givenPairAgreement = epipolarAgreement(features[0], features[1], F01, matchOptions);
    pointTracks.add(0, 1, matchPointsEpipolar(features[0], features[1], F01, matchOptions));
    segmentTracks.add(0, 1, matchSegmentsEpipolar(features[0], features[1], F01, matchOptions));
    // Later frames have no pose yet: matched under the fundamental matrix of their descriptor matches
    // (as view 3 of a triplet, feature_triplets.cpp). A frame that shares too few matches with the one
    // before for that geometry (blurred, covered, of another scene) would end every track there: the
    // next frame is then matched to the nearest of the frames before that does share enough, at most
    // kMaxFrameGap back, and only without any to the one before by descriptor alone.
    for (int k = 2; k < F; ++k)
    {
        Matches points, segments;
        int from = k - 1;
        bool underGeometry = matchUnknownPose(features[from], features[k], matchOptions, points, segments);
        for (int j = k - 2; !underGeometry && j >= std::max(0, k - kMaxFrameGap); --j)
        {
            Matches earlierPoints, earlierSegments;
            if (matchUnknownPose(features[j], features[k], matchOptions, earlierPoints, earlierSegments))
            {
                points.swap(earlierPoints);
                segments.swap(earlierSegments);
                from = j;
                underGeometry = true;
            }
        }
        pointTracks.add(from, k, points);
        segmentTracks.add(from, k, segments);
    }
    times.matching += 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();

    SequenceObservations out;
    out.cameraMatrices = cameraMatrices;
    out.points = pointTracks.observations(pointPositions, 2);
    out.lines = segmentTracks.observations(segmentPositions, 4);
    out.R0 = R0;
    out.t0 = t0;
    out.R1 = R1;
    out.t1 = t1;
    return out;
}

} // namespace tripose_samples
