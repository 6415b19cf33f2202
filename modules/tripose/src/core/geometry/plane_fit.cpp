// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../support/error.hpp"

#include <algorithm>

#include <Eigen/Dense>

#include "plane_fit.hpp"

namespace tripose {

void PlaneAccumulator::add(const Eigen::Vector3d& X)
{
    if (count_ == 0)
        origin_ = X;
    const Eigen::Vector3d d = X - origin_;
    sum_ += d;
    second_.noalias() += d * d.transpose();
    ++count_;
}

bool PlaneAccumulator::fit(Plane& plane) const
{
    if (count_ < 4)
        return false;
    const Eigen::Vector3d mean = sum_ / count_;
    const Eigen::Matrix3d covariance = second_ / count_ - mean * mean.transpose();
    if (!covariance.allFinite())
        return false;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    if (eigen.info() != Eigen::Success)
        return false;
    plane.extents = eigen.eigenvalues();
    plane.normal = eigen.eigenvectors().col(0);
    plane.centre = origin_ + mean;
    return plane.extents.allFinite() && plane.normal.allFinite() && plane.centre.allFinite();
}

bool trimPlaneFit(const std::vector<Eigen::Vector3d>& X, int rounds, Plane& plane)
{
    std::vector<double> distances(X.size()), sorted;
    for (int round = 0; round < rounds; ++round)
    {
        for (size_t k = 0; k < X.size(); ++k)
            distances[k] = std::abs(plane.normal.dot(X[k] - plane.centre));
        sorted = distances;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double limit = 3 * sorted[sorted.size() / 2];
        PlaneAccumulator kept;
        for (size_t k = 0; k < X.size(); ++k)
            if (distances[k] <= limit)
                kept.add(X[k]);
        if (!kept.fit(plane))
            return false;
    }
    return true;
}

} // namespace tripose
