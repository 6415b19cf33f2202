// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
#define OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP

#include "../estimator/pose_solver.hpp"
#include "multi_start_refinement.hpp"

namespace tripose {

/** The robust estimator's final stage: maximum-likelihood refinement
over every view from the estimator's pose, from the solver's estimates on the inliers (when it has
one and they are enough) and from the 26 starts of centreDirectionStarts() around the estimator's
pose, each re-triangulated until it settles, the lowest cost kept (refine/multi_start_refinement.hpp).
Only where the problem has several basins (a narrow known baseline, planar structure); there too,
sets larger than kMaxMultiStartFeatures are refined once from the estimator's pose: the samples and
local optimisation already put it in the right basin, and 27 starts would cost more than the rest
of the estimator. Elsewhere one refinement from the estimator's pose reaches the optimum.
*/
class MultiStartRefiner : public PoseRefiner
{
public:
    static constexpr int kMaxMultiStartFeatures = 60;

    /** @p severalBasins: whether the problem has several basins (scoring/known_structure.hpp);
    without, one refinement from the estimator's pose reaches the optimum and the starts would only
    cost time. @p searchStarts: whether to refine from the starts there; a problem whose samples
    already find the basin (the stereo rig's, scored with the known depth sliding) settles from
    all features (searchesSeveralBasins()) without them. */
    MultiStartRefiner(const ViewSet& set, const RefineOptions& params, const PoseSolver* solver, bool severalBasins,
                      bool searchStarts = true)
        : set_(set), params_(params), solver_(solver), severalBasins_(severalBasins),
          searchStarts_(severalBasins && searchStarts)
    {}

    bool searchesSeveralBasins() const override { return severalBasins_; }

    bool refine(const FeatureSubset& inliers, CameraPose& pose) const override
    {
        // Fewer than three features leave the pose and structure under-determined.
        if (inliers.size() < 3)
            return false;
        if (!searchStarts_ || inliers.size() > kMaxMultiStartFeatures)
        {
            refinePoseAndStructure(set_, pose, params_, &inliers.points, &inliers.lines);
            return true;
        }
        // The estimator asks again from the pose this returned, on the same features, when its
        // inliers settle at once and then settling from all features finds them all inliers: the
        // starts would be those of the previous call, moved by its refinement.
        if (last_.valid && inliers.points == last_.inliers.points && inliers.lines == last_.inliers.lines &&
            pose.R == last_.result.R && pose.t == last_.result.t)
            return true;
        std::vector<CameraPose> starts(1, pose);
        if (solver_ && inliers.size() >= solver_->nonMinimalSize())
            solver_->estimateNonMinimal(inliers, starts);
        centreDirectionStarts(set_, pose, starts);
        const LocalMinimum best = refineFromStarts(set_, starts, params_, &inliers.points, &inliers.lines);
        if (!best.finite())
            return false;
        pose = best.pose;
        last_.valid = true;
        last_.inliers = inliers;
        last_.result = pose;
        return true;
    }

private:
    //! The previous multi-start refinement: its features and result. State of one estimation:
    //! a refiner is built per call and not shared between threads.
    struct LastRefinement
    {
        bool valid = false;
        FeatureSubset inliers;
        CameraPose result;
    };

    const ViewSet& set_;
    const RefineOptions& params_;
    const PoseSolver* solver_;
    bool severalBasins_, searchStarts_;
    mutable LastRefinement last_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_MULTI_START_REFINER_HPP
