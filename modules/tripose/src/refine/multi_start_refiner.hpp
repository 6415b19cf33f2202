// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
#define OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP

#include "../robust/pose_solver.hpp"
#include "multi_start_refinement.hpp"

namespace cv {
namespace tripose {
namespace detail {

/** The robust estimator's final stage: maximum-likelihood refinement
over every view from the estimator's pose, from the solver's estimates on the inliers (when it has
one and they are enough) and from the 26 starts of centreDirectionStarts() around the estimator's
pose, each re-triangulated until it settles, the lowest cost kept (refine/multi_start_refinement.hpp).
Only where the problem has several basins (a narrow known baseline, planar structure); there too,
sets larger than kMaxMultiStartFeatures are refined once from the estimator's pose: the samples and
local optimisation already put it in the right basin, and 27 starts would cost more than the rest
of the estimator. Elsewhere one refinement from the estimator's pose reaches the optimum.

A stereo rig asks for no centre-direction starts (@p centreDirections false): the second camera
at the estimated time fixes the translation's direction and scale, and the basins that remain are
those of the hypotheses themselves; the estimator settles from its runners-up instead
(runnersUp()), which reaches the same minima as the 26 starts at a small part of their cost.
*/
class MultiStartRefiner : public PoseRefiner
{
public:
    static constexpr int kMaxMultiStartFeatures = 60;
    //! Runner-up hypotheses settled from when the centre-direction starts are left out.
    static constexpr int kRunnersUp = 4;

    /** @p severalBasins: whether the problem has several basins (scoring/known_structure.hpp);
    without, one refinement from the estimator's pose reaches the optimum and the starts would only
    cost time. @p centreDirections: whether to add the 26 centre-direction starts (see above). */
    MultiStartRefiner(const ViewSet& set, const RefineParams& params, const PoseSolver* solver, bool severalBasins,
                      bool centreDirections = true)
        : set_(set), params_(params), solver_(solver), severalBasins_(severalBasins),
          centreDirections_(centreDirections)
    {}

    bool searchesSeveralBasins() const CV_OVERRIDE { return severalBasins_; }
    int runnersUp() const CV_OVERRIDE { return severalBasins_ && !centreDirections_ ? kRunnersUp : 0; }

    bool refine(const FeatureSubset& inliers, CameraPose& pose) const CV_OVERRIDE
    {
        // Fewer than three features leave the pose and structure under-determined.
        if (inliers.size() < 3)
            return false;
        if (!severalBasins_ || inliers.size() > kMaxMultiStartFeatures)
        {
            refinePoseAndStructure(set_, pose, params_, &inliers.points, &inliers.lines);
            return true;
        }
        std::vector<CameraPose> starts(1, pose);
        if (solver_ && inliers.size() >= solver_->nonMinimalSize())
            solver_->estimateNonMinimal(inliers, starts);
        if (centreDirections_)
            centreDirectionStarts(set_, pose, starts);
        const LocalMinimum best = refineFromStarts(set_, starts, params_, &inliers.points, &inliers.lines);
        if (!best.finite())
            return false;
        pose = best.pose;
        return true;
    }

private:
    const ViewSet& set_;
    const RefineParams& params_;
    const PoseSolver* solver_;
    bool severalBasins_;
    bool centreDirections_;
};

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
