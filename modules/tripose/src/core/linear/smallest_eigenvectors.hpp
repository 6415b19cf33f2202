// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_SMALLEST_EIGENVECTORS_HPP
#define OPENCV_TRIPOSE_SMALLEST_EIGENVECTORS_HPP

#include <Eigen/Core>

namespace tripose {

/** Orthonormal eigenvectors of the symmetric 9x9 matrix @p S for its two smallest eigenvalues
(column 0: the smallest). The over-determined linear solve needs only these two of nine: the
matrix is reduced to tridiagonal form, its eigenvalues found without accumulating the rotations,
and the two vectors obtained by inverse iteration on the tridiagonal matrix shifted by their
eigenvalues, then mapped back; about two thirds of the cost of the full decomposition. When a
vector fails its residual check (e.g. the tridiagonal matrix splits into blocks that the start
vector misses), the full decomposition is used instead. Returns false if that fails too.
*/
bool smallestEigenvectors(const Eigen::Matrix<double, 9, 9>& S, Eigen::Matrix<double, 9, 2>& vectors);

} // namespace tripose

#endif // OPENCV_TRIPOSE_SMALLEST_EIGENVECTORS_HPP
