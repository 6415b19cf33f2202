// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/tracking/triplet_matching.hpp"
#include "opencv/core_calls.hpp"
#include "opencv/feature_reading.hpp"
#include "opencv/opencv_compat.hpp"

namespace cv {
namespace tripose {

MatchParams::MatchParams()
{
    const detail::core::MatchOptions defaults;
    epipolarDistance = defaults.epipolarDistance;
    minBandOverlap = defaults.minBandOverlap;
    minEpipolarAngleDeg = defaults.minEpipolarAngleDeg;
    pointRatio = defaults.pointRatio;
    lineRatio = defaults.lineRatio;
    maxLineDistance = defaults.maxLineDistance;
    minFundamentalInliers = defaults.minFundamentalInliers;
}

namespace {

namespace core = detail::core;

Mat rowsOf(const std::vector<int>& rows, const Mat& positions)
{
    Mat out((int)rows.size(), positions.cols, CV_64F);
    for (size_t k = 0; k < rows.size(); ++k)
        positions.row(rows[k]).copyTo(out.row((int)k));
    return out;
}

} // namespace

FeatureTriplets matchFeatureTriplets(const ImageFeatures& view1, const ImageFeatures& view2, const ImageFeatures& view3,
                                     InputArrayOfArrays cameraMatrix, InputArray R12, InputArray t12,
                                     const MatchParams& params)
{
    CV_INSTRUMENT_REGION();
    const ImageFeatures* views[3] = { &view1, &view2, &view3 };
    core::FrameFeatures features[3];
    Mat points[3], segments[3];
    for (int v = 0; v < 3; ++v)
    {
        points[v] = detail::readRows(views[v]->points, 2, "points");
        segments[v] = detail::readRows(views[v]->segments, 4, "segments");
        features[v].points = detail::vectors<2>(points[v]);
        features[v].segments = detail::vectors<4>(segments[v]);
        features[v].pointDescriptors =
            detail::readDescriptors(views[v]->pointDescriptors, points[v].rows, "pointDescriptors");
        features[v].lineDescriptors =
            detail::readDescriptors(views[v]->lineDescriptors, segments[v].rows, "lineDescriptors");
    }
    Eigen::Matrix3d K[3];
    if (cameraMatrix.kind() == _InputArray::STD_VECTOR_MAT || cameraMatrix.kind() == _InputArray::STD_VECTOR_VECTOR)
    {
        if (cameraMatrix.total() != 3)
            CV_Error(Error::StsBadSize, "cameraMatrix must be one 3x3 matrix or three, one per view");
        for (int v = 0; v < 3; ++v)
            K[v] = detail::readMatrix3(cameraMatrix.getMat(v), "cameraMatrix");
    }
    else
        K[0] = K[1] = K[2] = detail::readMatrix3(cameraMatrix, "cameraMatrix");
    Mat r, t;
    R12.getMat().convertTo(r, CV_64F);
    if (r.total() == 3)
        Rodrigues(r.reshape(1, 3), r);
    t12.getMat().convertTo(t, CV_64F);
    if (r.total() != 9 || t.total() != 3)
        CV_Error(Error::StsBadSize, "R12 must be 3x3 or a Rodrigues vector, t12 must hold 3 elements");
    core::CameraPose pose12;
    for (int i = 0; i < 9; ++i)
        pose12.R(i / 3, i % 3) = r.reshape(1, 3).at<double>(i / 3, i % 3);
    for (int i = 0; i < 3; ++i)
        pose12.t[i] = t.reshape(1, 3).at<double>(i);
    const core::MatchOptions options = TRIPOSE_CALL_CORE([&] { return detail::toCoreOptions(params); });
    const core::FeatureTriplets triplets =
        TRIPOSE_CALL_CORE([&] { return core::matchTriplets(features, K, pose12, options); });
    FeatureTriplets out;
    for (int v = 0; v < 3; ++v)
    {
        out.points[v] = rowsOf(triplets.pointRows[v], points[v]);
        out.lines[v] = rowsOf(triplets.segmentRows[v], segments[v]);
        Mat(triplets.pointRows[v], true).copyTo(out.pointRows[v]);
        Mat(triplets.segmentRows[v], true).copyTo(out.segmentRows[v]);
    }
    out.pointPairs = triplets.pointPairs;
    out.segmentPairs = triplets.segmentPairs;
    out.pairAgreement = Vec2i(triplets.pairAgreement.matches, triplets.pairAgreement.agreeing);
    return out;
}

} // namespace tripose
} // namespace cv
