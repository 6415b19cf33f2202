// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include "point_normalization.hpp"

namespace tripose {

Eigen::Vector3d normalizingSimilarity(const std::vector<Eigen::Vector2d>& points, const std::vector<int>* indices)
{
    const int n = indices ? (int)indices->size() : (int)points.size();
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (int k = 0; k < n; ++k)
        centroid += points[indices ? (*indices)[k] : k];
    centroid /= std::max(n, 1);
    double meanDistance = 0;
    for (int k = 0; k < n; ++k)
        meanDistance += (points[indices ? (*indices)[k] : k] - centroid).norm();
    meanDistance /= std::max(n, 1);
    const double scale = meanDistance > 1e-12 ? std::sqrt(2.0) / meanDistance : 1.0;
    return Eigen::Vector3d(scale, centroid.x(), centroid.y());
}

} // namespace tripose
