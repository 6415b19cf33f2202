// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_POINT_NORMALIZATION_HPP
#define OPENCV_TRIPOSE_LINEAR_POINT_NORMALIZATION_HPP

#include <vector>

#include <Eigen/Core>

namespace tripose {

/** Hartley normalisation of the points of one view, x̂ = s (x - c): centroid at the origin, mean
distance √2, returned as (s, cx, cy), the form the generated point rows take. Uses the points
selected by @p indices (null: all of them). A single point (or coincident points) keeps unit scale:
only the centring is defined.
*/
Eigen::Vector3d normalizingSimilarity(const std::vector<Eigen::Vector2d>& points, const std::vector<int>* indices);

//! x̂ = s (x - c) for the similarity @p n = (s, cx, cy) of normalizingSimilarity().
inline Eigen::Vector2d applySimilarity(const Eigen::Vector3d& n, const Eigen::Vector2d& x)
{
    return n(0) * (x - n.tail<2>());
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_POINT_NORMALIZATION_HPP
