// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_FUNDAMENTAL_ESTIMATION_HPP
#define TRIPOSE_CORE_TRACKING_FUNDAMENTAL_ESTIMATION_HPP

#include <vector>

#include <Eigen/Core>

namespace tripose {

/** The fundamental matrix of point pairs (@p xa[i], @p xb[i]) with xb^T F xa = 0, robustly: RANSAC
over samples of eight pairs (the normalised eight-point method, rank two enforced), a pair an inlier
when each point lies within @p threshold px of the other's epipolar line, stopped adaptively at
@p confidence, then re-fitted to the inliers of the best sample. The sampler is seeded alike on
every call, so the same pairs give the same matrix. A caller that wants at least @p minInliers
inliers stops the sampling, short of them, once a matrix they support would have been sampled at
@p confidence: pairs of another scene or of repeated texture do not cost the full count of samples.
Returns the number of inliers (0 with fewer than eight pairs or no sample of rank two); @p inliers
receives one flag per pair.
*/
int estimateFundamentalRansac(const std::vector<Eigen::Vector2d>& xa, const std::vector<Eigen::Vector2d>& xb,
                              double threshold, double confidence, Eigen::Matrix3d& F,
                              std::vector<unsigned char>& inliers, int minInliers = 0);

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_FUNDAMENTAL_ESTIMATION_HPP
