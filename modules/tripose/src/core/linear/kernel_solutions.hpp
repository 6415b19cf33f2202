// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_KERNEL_SOLUTIONS_HPP
#define OPENCV_TRIPOSE_KERNEL_SOLUTIONS_HPP

#include <vector>

#include <Eigen/Core>

namespace tripose {

typedef Eigen::Matrix<double, 12, 1> Vector12d;

/** Solution vectors v = sum_k beta_k v_k of the linear system, for a kernel basis v_1..v_N
(the columns of @p basis, N = 1..4), with the coefficients fixed by the orthonormality of R
(@cite QadirNeubert2017, Sec. III-D). v = [r1; r2; r3; t] with r_i the columns of R; the scale and
sign of each candidate are arbitrary (fixed later by det(R) = 1).

- N = 1: v_1.
- N = 2: the five homogeneous constraints (three orthogonalities, two equal norms) are linear in
  [b1^2, b2^2, b1 b2]: their null vector gives b1, b2.
- N = 3: the three orthogonalities and three unit norms are linear in the six quadratic monomials.
- N = 4: b4 = 1 and b3 hidden: the 5x6 system in [b1^2, b2^2, b1 b2, b1, b2, 1] has a null vector of
  signed 5x5 minors, polynomial in b3; its consistency polynomials f_i give the degree-11
  sum f_i f_i' whose real roots are the candidates for b3.
Appends the candidates to @p solutions and returns how many were appended.
*/
int solveKernelCombinations(const Eigen::Matrix<double, 12, Eigen::Dynamic, 0, 12, 4>& basis,
                            std::vector<Vector12d>& solutions);

} // namespace tripose

#endif // OPENCV_TRIPOSE_KERNEL_SOLUTIONS_HPP
