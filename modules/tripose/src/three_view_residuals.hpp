// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_THREE_VIEW_RESIDUALS_HPP
#define OPENCV_TRIPOSE_THREE_VIEW_RESIDUALS_HPP

#include <vector>

#include "triplet_data.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** How well each feature fits all three views once the pose of view 3 is known: the feature is
triangulated from the three views (a point by linear least squares; a line as the best fit to the
three back-projected planes) and the RMS of its reprojection residuals over the views is returned,
in pixels (a point: 2 coordinates per view; a line: distances of the 2 observed end points per
view). Unlike residuals against structure from views 1-2 alone, these do not carry the
triangulation error of two views into view 3, so they separate inliers from outliers at a
threshold of a few sigma. Non-triangulable features get +inf.
*/
void threeViewResiduals(const TripletData& data, const CameraPose& pose,
                        std::vector<double>& pointResiduals, std::vector<double>& lineResiduals);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_THREE_VIEW_RESIDUALS_HPP
