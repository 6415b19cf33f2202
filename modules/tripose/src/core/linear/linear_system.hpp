// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_SYSTEM_HPP
#define OPENCV_TRIPOSE_LINEAR_SYSTEM_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/view_set.hpp"

namespace tripose {

typedef Eigen::Matrix<double, 12, 12> Matrix12d;
typedef Eigen::Matrix<double, Eigen::Dynamic, 12, Eigen::RowMajor> ConstraintMatrix;

/** The matrix A of the linear system A v = 0 in v = [r1; r2; r3; t] (@cite QadirNeubert2017,
Sec. III-A to III-C): four rows per point triplet (the trilinear equations 9-12 in Hartley-normalised
coordinates) and two rows per line triplet (the planes of views 1 and 2 eliminated by a Householder
QR, leaving "two points of the 3D line project onto l3"). Each point's block of rows is scaled
to Frobenius norm sqrt 2, so that points and lines weigh alike whatever the normalising scales,
which keeps A well conditioned. A line's two rows use, as the two points of its 3D line, the
view-1 end points lifted onto the plane of view 2, which makes them near-geometric residuals;
with six or more features they are weighted by the inverse of their predicted noise (see
linear_system.cpp).

@p translationScale divides t12 before the rows are formed, so that the unknown t is expressed in
units of |t12| and the columns of A are balanced whatever the user's units; multiply the solved t by
it. The feature subsets @p pointIndices / @p lineIndices select features (empty pointers: all).
*/
ConstraintMatrix buildConstraintMatrix(const ViewSet& set, double translationScale,
                                       const std::vector<int>* pointIndices = nullptr,
                                       const std::vector<int>* lineIndices = nullptr);

/** Two homogeneous points spanning the 3D line seen as l1 in view 1 and l2 in view 2 (an
orthonormal basis of the null space of [pi1 pi2]^T, pi1 = [l1; 0], pi2 = [R12^T l2; t12^T l2], by the
generated closed form). Returns false when the two planes are parallel (the line lies in an epipolar
plane of views 1-2 and has no 3D position).
*/
bool lineNullSpace(const Eigen::Vector3d& l1, const Eigen::Vector3d& l2, const CameraPose& pose12,
                   Eigen::Vector4d& qa, Eigen::Vector4d& qb);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_SYSTEM_HPP
