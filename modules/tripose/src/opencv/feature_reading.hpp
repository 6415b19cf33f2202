// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_FEATURE_READING_HPP
#define OPENCV_TRIPOSE_OPENCV_FEATURE_READING_HPP

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "opencv2/core.hpp"

#include "opencv2/tripose/features.hpp"

#include "../core/tracking/tracker_options.hpp"
#include "../core/tracking/frame_features.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! Rows of @p width values (N x width, or N x 1 of width channels, any depth) as CV_64F; cv::Exception
//! naming @p name otherwise.
Mat readRows(InputArray array, int width, const char* name);

//! The rows of @p rows (CV_64F, W columns) as vectors.
template <int W>
std::vector<Eigen::Matrix<double, W, 1>> vectors(const Mat& rows)
{
    std::vector<Eigen::Matrix<double, W, 1>> out(rows.rows);
    for (int i = 0; i < rows.rows; ++i)
        for (int c = 0; c < W; ++c)
            out[i][c] = rows.at<double>(i, c);
    return out;
}

//! @p count feature ids, one integer each (CV_32S, or whole CV_64F values); cv::Exception naming @p name otherwise.
std::vector<int64_t> readIds(InputArray array, int count, const char* name);

//! @p rows descriptor rows, CV_32F (L2) or CV_8U (Hamming); cv::Exception naming @p name otherwise.
::tripose::Descriptors readDescriptors(InputArray array, int rows, const char* name);

//! A 3x3 matrix; cv::Exception naming @p name otherwise.
Eigen::Matrix3d readMatrix3(InputArray array, const char* name);

//! Points, segments and descriptors of one image, read as above.
::tripose::FrameFeatures readFrameFeatures(InputArray points, InputArray pointDescriptors, InputArray segments,
                                           InputArray lineDescriptors);

//! The features of one image, read as above; errors name them "<name>.points", "<name>.pointDescriptors", ...
::tripose::FrameFeatures readFrameFeatures(const ImageFeatures& features, const std::string& name);

//! The core's matching options from the public parameters, checked (core::Error naming "params.<field>").
::tripose::MatchOptions toCoreOptions(const MatchParams& params);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_FEATURE_READING_HPP
