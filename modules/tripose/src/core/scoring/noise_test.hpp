// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_SCORING_NOISE_TEST_HPP
#define TRIPOSE_CORE_SCORING_NOISE_TEST_HPP

#include <vector>

#include "../geometry/view_set.hpp"

namespace tripose {

/** The final inlier test of lines where a wrong line match can look right: their re-triangulated
residuals (PoseScorer::refitResiduals(), per feature the RMS over every view that sees it) judged
against the image noise that the inlier points show, not only against the threshold.

The threshold bounds each residual, about 3 sigma. A point seen in four views is held by its
epipolar geometry, and a wrong match is tens of pixels off; a line has no such constraint, and on a
stereo rig a wrong line match that is consistent between the two images at the new time is a few
pixels off at most: each pair's planes nearly coincide (a short baseline), and two planes always
meet in a line. Such lines, a little above the noise of true ones, pass the threshold, and a handful
of them pulls the least-squares settle off (doc/studies/evaluation.md, Stereo rig). Here a line
stays an inlier only if its sum of squared residuals (RMS^2 times their number n) is below the
99.9 % quantile of chi-square with n - 4 degrees of freedom (its four parameters fitted) times the noise
variance, so one true line in a thousand is lost. The variance is estimated from the inlier points
(sum of their squared residuals over their n - 3 degrees of freedom) when they have at least
kMinNoiseDegrees, else it is (threshold / 3)^2. Lines seen in two views (no degree of freedom left)
keep the threshold's verdict.

@p lineMask (the threshold's verdict) loses the lines that fail; returns how many. */
int rejectLinesAbovePointNoise(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                               const std::vector<unsigned char>& pointMask, const std::vector<double>& lineResiduals,
                               std::vector<unsigned char>& lineMask);

/** The same test of the inlier points themselves, for the settled pose only: each point of
@p pointMask stays an inlier if its sum of squared residuals is below the 99.9 % quantile of
chi-square with n - 3 degrees of freedom times the variance that the inlier points show (as above).
A point is held by its epipolar geometry, but among many wrong matches of a rig (consistent between
the two images at the new time) a few still land within the threshold, and even two of them pull
the pose off (doc/studies/evaluation.md, Stereo rig). Judged only once the inliers have
settled: at the poses of unconverged settle rounds true points fail it too, and the rounds then
end elsewhere. Only where the variance is estimated from the points (kMinNoiseDegrees): with a
handful of points the threshold's variance would judge true points by a noise that is not theirs,
and a rig scene with few true points would lose one it cannot spare. @p pointMask loses the points that fail;
returns how many. */
int rejectPointsAboveNoise(const ViewSet& set, double threshold, const std::vector<double>& pointResiduals,
                           std::vector<unsigned char>& pointMask);

} // namespace tripose

#endif // TRIPOSE_CORE_SCORING_NOISE_TEST_HPP
