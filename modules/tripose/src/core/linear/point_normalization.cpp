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

namespace {

//! Hartley's mean distance from the centroid: an average point lands near (1, 1), so that the
//! coordinates and the ones of homogeneous points, which the rows multiply together, are of one size.
constexpr double kNormalizedMeanDistance = 1.4142135623730951; // sqrt(2)
//! Mean distance (calibrated units) below which the points coincide and have no scale to normalise.
constexpr double kCoincidentSpread = 1e-12;

} // namespace

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
    const double scale = meanDistance > kCoincidentSpread ? kNormalizedMeanDistance / meanDistance : 1.0;
    return Eigen::Vector3d(scale, centroid.x(), centroid.y());
}

} // namespace tripose
