// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_HYPOTHESIS_STARTS_HPP
#define OPENCV_TRIPOSE_REFINE_HYPOTHESIS_STARTS_HPP

#include <vector>

#include "../estimator/feature_subset.hpp"
#include "../estimator/pose_solver.hpp"
#include "../geometry/view_set.hpp"

namespace tripose {

/** Starts of different rotations for the search where the cost has several basins. With a narrow
known pair the estimate over all features (and the starts that keep its rotation) can lie 40 to 150
degrees from the rotation of the lowest minimum (doc/studies/accuracy.md, "Narrow known baselines: the
lowest minimum"); the solver's minimal samples of @p features, each fitting a different few
features, spread their rotations over those basins. Every distinct sample is solved (up to
kMaxHypothesisSamples, else that many drawn with a fixed seed), each pose scored by the RMS of all
of @p features' residuals over every view with the structure triangulated at it (no iteration);
the best-scored poses whose rotations differ from each other and from the poses already in
@p starts are appended, at most kMaxHypothesisStarts. Nothing for solvers of mixed samples.
*/
void appendHypothesisStarts(const ViewSet& set, const PoseSolver& solver, const FeatureSubset& features,
                            std::vector<CameraPose>& starts);

constexpr int kMaxHypothesisSamples = 128;
constexpr int kMaxHypothesisStarts = 6;

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_HYPOTHESIS_STARTS_HPP
