// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "fundamental_estimation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "../support/random.hpp"
#include "epipolar_matching.hpp"

namespace tripose {

namespace {

const int kSampleSize = 8;
const int kMaxSamples = 2000;

//! The similarity moving the centroid of @p x to the origin and its mean distance to sqrt(2).
Eigen::Matrix3d normalisingTransform(const std::vector<Eigen::Vector2d>& x, const std::vector<int>& rows)
{
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (int r : rows)
        mean += x[r];
    mean /= (double)rows.size();
    double spread = 0;
    for (int r : rows)
        spread += (x[r] - mean).norm();
    spread /= (double)rows.size();
    const double s = spread > 0 ? std::sqrt(2.0) / spread : 1.0;
    Eigen::Matrix3d T;
    T << s, 0, -s * mean.x(), 0, s, -s * mean.y(), 0, 0, 1;
    return T;
}

//! The eight-point estimate from the pairs @p rows (at least eight); false when degenerate.
bool eightPoint(const std::vector<Eigen::Vector2d>& xa, const std::vector<Eigen::Vector2d>& xb,
                const std::vector<int>& rows, Eigen::Matrix3d& F)
{
    const Eigen::Matrix3d Ta = normalisingTransform(xa, rows), Tb = normalisingTransform(xb, rows);
    Eigen::MatrixXd A((int)rows.size(), 9);
    for (int k = 0; k < (int)rows.size(); ++k)
    {
        const Eigen::Vector3d a = Ta * Eigen::Vector3d(xa[rows[k]].x(), xa[rows[k]].y(), 1);
        const Eigen::Vector3d b = Tb * Eigen::Vector3d(xb[rows[k]].x(), xb[rows[k]].y(), 1);
        A.row(k) << b[0] * a[0], b[0] * a[1], b[0], b[1] * a[0], b[1] * a[1], b[1], a[0], a[1], 1;
    }
    Eigen::Matrix<double, 9, 9> normal = A.transpose() * A;
    Eigen::JacobiSVD<Eigen::Matrix<double, 9, 9>> svdA(normal, Eigen::ComputeFullV);
    const Eigen::Matrix<double, 9, 1> f = svdA.matrixV().col(8);
    Eigen::Matrix3d G;
    G << f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8];
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(G, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Vector3d sigma = svd.singularValues();
    if (!(sigma[1] > 1e-12 * sigma[0]))
        return false;
    sigma[2] = 0;
    F = Tb.transpose() * svd.matrixU() * sigma.asDiagonal() * svd.matrixV().transpose() * Ta;
    F /= F.norm();
    return F.allFinite();
}

int countInliers(const std::vector<Eigen::Vector2d>& xa, const std::vector<Eigen::Vector2d>& xb,
                 const Eigen::Matrix3d& F, double threshold, std::vector<unsigned char>& inliers)
{
    int count = 0;
    inliers.assign(xa.size(), 0);
    for (size_t i = 0; i < xa.size(); ++i)
        if (withinEpipolarDistance(F, xa[i], xb[i], threshold))
        {
            inliers[i] = 1;
            ++count;
        }
    return count;
}

/** The samples that draw, at @p confidence, one of @p inliers among @p n pairs eight times in a row
(at most kMaxSamples). */
int samplesFor(int inliers, int n, double confidence)
{
    const double allInlier = std::pow((double)inliers / n, kSampleSize);
    if (allInlier >= 1)
        return 1;
    // Bounded in floating point: a low inlier ratio asks for more samples than an int holds.
    if (!(allInlier > 0))
        return kMaxSamples;
    return (int)std::min((double)kMaxSamples, std::ceil(std::log(1 - confidence) / std::log1p(-allInlier)));
}

} // namespace

int estimateFundamentalRansac(const std::vector<Eigen::Vector2d>& xa, const std::vector<Eigen::Vector2d>& xb,
                              double threshold, double confidence, Eigen::Matrix3d& F,
                              std::vector<unsigned char>& inliers, int minInliers)
{
    const int n = (int)xa.size();
    inliers.assign(n, 0);
    if (n < kSampleSize || (int)xb.size() != n)
        return 0;
    Random random(1);
    // A wanted count of every pair (or none) leaves the sampling to the count it finds.
    int best = 0, samples = minInliers > 0 && minInliers < n ? samplesFor(minInliers, n, confidence) : kMaxSamples;
    std::vector<unsigned char> mask;
    std::vector<int> sample(kSampleSize);
    for (int iteration = 0; iteration < samples; ++iteration)
    {
        for (int k = 0; k < kSampleSize; ++k)
        {
            int r;
            do
                r = random.uniform(0, n);
            while (std::find(sample.begin(), sample.begin() + k, r) != sample.begin() + k);
            sample[k] = r;
        }
        Eigen::Matrix3d candidate;
        if (!eightPoint(xa, xb, sample, candidate))
            continue;
        const int count = countInliers(xa, xb, candidate, threshold, mask);
        if (count > best)
        {
            best = count;
            F = candidate;
            inliers = mask;
            if (count == n)
                break;
            samples = std::min(samples, samplesFor(count, n, confidence));
        }
    }
    if (best < kSampleSize)
        return 0;
    // Re-fitted to the inliers while that keeps or adds inliers.
    for (int round = 0; round < 3; ++round)
    {
        std::vector<int> rows;
        for (int i = 0; i < n; ++i)
            if (inliers[i])
                rows.push_back(i);
        Eigen::Matrix3d refit;
        if (!eightPoint(xa, xb, rows, refit))
            break;
        const int count = countInliers(xa, xb, refit, threshold, mask);
        if (count < best)
            break;
        const bool grew = count > best;
        best = count;
        F = refit;
        inliers = mask;
        if (!grew)
            break;
    }
    return best;
}

} // namespace tripose
