// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_CANDIDATE_SCORING_HPP
#define OPENCV_TRIPOSE_CANDIDATE_SCORING_HPP

#include <vector>

#include <Eigen/Core>

#include "triplet_data.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! 3D structure seen by the known views 1 and 2, used to judge candidate poses of view 3.
struct TwoViewStructure
{
    std::vector<Eigen::Vector3d> points;    //!< Triangulated points (midpoint of the two rays).
    std::vector<unsigned char> pointValid;  //!< 0 where the rays are (nearly) parallel or meet behind view 1 or 2.
    std::vector<Eigen::Vector3d> lineEnds;  //!< Two 3D points per line: view-1 end rays cut by the plane of view 2.
    std::vector<unsigned char> lineValid;   //!< 0 where a ray is (nearly) parallel to that plane or an end lies behind view 1 or 2.
};

TwoViewStructure triangulateTwoViewStructure(const TripletData& data);

//! Residuals of one candidate pose in view 3, in pixels.
struct ReprojectionScore
{
    double rms = 0;         //!< RMS over point distances and line end-point distances.
    int behind = 0;         //!< Structure points (point features and line ends) behind view 3.
    int considered = 0;     //!< Structure points that could be checked.
};

/** Reprojection error of view 3 under @p pose: a point contributes its pixel distance, a line the
distances of its two observed end points to the projected 3D line (@cite QadirNeubert2017, Sec. III-G).
Point residuals go to @p pointResiduals and line residuals (RMS of the two end distances) to
@p lineResiduals when given; features whose structure is invalid or behind the camera get +inf.
*/
ReprojectionScore scorePose(const TripletData& data, const TwoViewStructure& structure, const CameraPose& pose,
                            std::vector<double>* pointResiduals = nullptr,
                            std::vector<double>* lineResiduals = nullptr);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_CANDIDATE_SCORING_HPP
