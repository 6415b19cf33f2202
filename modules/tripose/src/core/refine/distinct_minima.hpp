// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_DISTINCT_MINIMA_HPP
#define OPENCV_TRIPOSE_REFINE_DISTINCT_MINIMA_HPP

#include <vector>

#include "multi_start_refinement.hpp"

namespace tripose {

/** Where a multi-start refinement ends in several minima: which of them are distinct, and which the
data cannot tell apart from the best (doc/conventions.md, "Several minima").
*/

/** The 0.95 quantile of chi-square with 6 degrees of freedom. With Gaussian noise of variance
sigma^2 the poses whose profile cost (structure refined) exceeds the lowest by less than
sigma^2 times this form the 95 % likelihood-ratio confidence region of the 6-parameter pose: a
minimum inside it is a pose the data do not reject. */
constexpr double kChiSquare6Quantile95 = 12.5916;

/** The tolerance of sameMinimum() for minima refined with the default iterations: refined to
convergence, one minimum reached from several starts ends far closer than this (the narrow scenes
of test_narrow_minima.cpp), but in flat valleys the default iterations leave two refinements of it
further apart than a tighter tolerance would merge. */
constexpr double kSameMinimum = 1e-3;

//! True when @p a and @p b are one local minimum reached twice: rotation (Frobenius norm of the
//! difference) and translation (relative to its norm) closer than @p tolerance.
bool sameMinimum(const CameraPose& a, const CameraPose& b, double tolerance = kSameMinimum);

/** The distinct minima of @p minima (several starts may reach one minimum, at @p tolerance as in
sameMinimum(); the lowest of a repeated one is kept), best first (LocalMinimum::betterThan()),
and only those that use as many features as the best: an RMS over fewer residuals is not comparable.
*/
std::vector<LocalMinimum> distinctMinima(std::vector<LocalMinimum> minima, double tolerance);

/** True when @p other, a minimum over the same features as @p best (which is at least as good), is
within the noise of it: its cost (sum of squared residuals) exceeds best's by less than
kChiSquare6Quantile95 times the noise variance estimated at @p best. False when best's noise
variance is not determined (no more residuals than parameters): then no bound is known. */
bool withinNoise(const LocalMinimum& best, const LocalMinimum& other);

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_DISTINCT_MINIMA_HPP
