// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP
#define OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP

#include <vector>

#include "opencv2/tripose/robust.hpp"
#include "triplet_data.hpp"

namespace cv {
namespace tripose {
namespace detail {

struct RobustEstimate
{
    CameraPose pose;
    std::vector<unsigned char> pointInliers, lineInliers;
    int numInliers = 0;
    int iterations = 0; //!< Samples drawn.
};

/** LO-MSAC over four-feature samples solved by the linear method; see estimatePoseLinePointRansac().
Returns false when no sample gave a pose.
*/
bool estimatePoseRobust(const TripletData& data, const RansacParams& params, RobustEstimate& estimate);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_ROBUST_ESTIMATOR_HPP
