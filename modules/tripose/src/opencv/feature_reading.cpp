// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "feature_reading.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! Rows of @p width values (N x width, or N x 1 of width channels, any depth), as CV_64F.
Mat readRows(InputArray array, int width, const char* name)
{
    if (array.empty())
        return Mat(0, width, CV_64F);
    Mat m = array.getMat();
    if (m.channels() == width && (m.cols == 1 || m.rows == 1))
        m = m.reshape(1, (int)m.total());
    if (m.dims != 2 || m.channels() != 1 || m.cols != width)
        CV_Error_(Error::StsBadSize, ("%s must be N x %d (or N x 1 with %d channels)", name, width, width));
    Mat out;
    m.convertTo(out, CV_64F);
    return out;
}

std::vector<int64_t> readIds(InputArray array, int count, const char* name)
{
    std::vector<int64_t> ids;
    if (array.empty())
    {
        if (count > 0)
            CV_Error_(Error::StsBadSize, ("%s is empty: one id per feature is needed", name));
        return ids;
    }
    Mat m = array.getMat();
    if (m.channels() != 1 || (int)m.total() != count || !(m.depth() == CV_32S || m.depth() == CV_64F))
        CV_Error_(Error::StsBadSize, ("%s must hold one integer (CV_32S) per feature (%d)", name, count));
    Mat d;
    m.reshape(1, 1).convertTo(d, CV_64F);
    for (int i = 0; i < count; ++i)
        ids.push_back((int64_t)d.at<double>(i));
    return ids;
}

::tripose::Descriptors readDescriptors(InputArray array, int rows, const char* name)
{
    ::tripose::Descriptors d;
    if (array.empty())
    {
        if (rows > 0)
            CV_Error_(Error::StsBadSize, ("%s is empty: one descriptor row per feature is needed", name));
        return d;
    }
    Mat m = array.getMat();
    if (m.dims != 2 || m.channels() != 1 || m.rows != rows || !(m.depth() == CV_32F || m.depth() == CV_8U))
        CV_Error_(Error::StsBadSize, ("%s must have one row per feature (%d), CV_32F or CV_8U, single channel",
                                      name, rows));
    m = m.isContinuous() ? m : m.clone();
    d.rows = m.rows;
    d.cols = m.cols;
    d.binary = m.depth() == CV_8U;
    if (d.binary)
        d.bits.assign(m.ptr<uchar>(), m.ptr<uchar>() + m.total());
    else
        d.real.assign(m.ptr<float>(), m.ptr<float>() + m.total());
    return d;
}

Eigen::Matrix3d readMatrix3(InputArray array, const char* name)
{
    Mat m = array.getMat();
    if (m.total() != 9 || m.channels() != 1)
        CV_Error_(Error::StsBadSize, ("%s must be 3x3", name));
    Mat d;
    m.reshape(1, 3).convertTo(d, CV_64F);
    Eigen::Matrix3d out;
    for (int i = 0; i < 9; ++i)
        out(i / 3, i % 3) = d.at<double>(i / 3, i % 3);
    return out;
}

::tripose::FrameFeatures readFrameFeatures(InputArray points, InputArray pointDescriptors, InputArray segments,
                                           InputArray lineDescriptors)
{
    ::tripose::FrameFeatures f;
    f.points = vectors<2>(readRows(points, 2, "points"));
    f.segments = vectors<4>(readRows(segments, 4, "segments"));
    f.pointDescriptors = readDescriptors(pointDescriptors, (int)f.points.size(), "pointDescriptors");
    f.lineDescriptors = readDescriptors(lineDescriptors, (int)f.segments.size(), "lineDescriptors");
    return f;
}

::tripose::FrameFeatures readFrameFeatures(const ImageFeatures& features, const std::string& name)
{
    const std::string points = name + ".points", segments = name + ".segments";
    const std::string pointDescriptors = name + ".pointDescriptors", lineDescriptors = name + ".lineDescriptors";
    ::tripose::FrameFeatures f;
    f.points = vectors<2>(readRows(features.points, 2, points.c_str()));
    f.segments = vectors<4>(readRows(features.segments, 4, segments.c_str()));
    f.pointDescriptors = readDescriptors(features.pointDescriptors, (int)f.points.size(), pointDescriptors.c_str());
    f.lineDescriptors = readDescriptors(features.lineDescriptors, (int)f.segments.size(), lineDescriptors.c_str());
    return f;
}

::tripose::MatchOptions toCoreOptions(const MatchParams& params)
{
    ::tripose::MatchOptions o;
    o.epipolarDistance = params.epipolarDistance;
    o.minBandOverlap = params.minBandOverlap;
    o.minEpipolarAngleDeg = params.minEpipolarAngleDeg;
    o.pointRatio = params.pointRatio;
    o.lineRatio = params.lineRatio;
    o.maxLineDistance = params.maxLineDistance;
    o.minFundamentalInliers = params.minFundamentalInliers;
    ::tripose::checkMatchOptions(o, "params");
    return o;
}

} // namespace detail
} // namespace tripose
} // namespace cv
