// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_STRUCTURE_REFINER_HPP
#define OPENCV_TRIPOSE_REFINE_STRUCTURE_REFINER_HPP

#include "../robust/pose_solver.hpp"
#include "ml_refinement.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! Maximum-likelihood refinement of pose and structure over every view, as the robust estimator's final stage.
class StructureRefiner : public PoseRefiner
{
public:
    StructureRefiner(const ViewSet& set, const RefineParams& params) : set_(set), params_(params) {}

    bool refine(const FeatureSubset& inliers, CameraPose& pose) const CV_OVERRIDE
    {
        // Fewer than three features leave the pose and structure under-determined.
        if (inliers.size() < 3)
            return false;
        refinePoseAndStructure(set_, pose, params_, &inliers.points, &inliers.lines);
        return true;
    }

private:
    const ViewSet& set_;
    const RefineParams& params_;
};

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_REFINE_STRUCTURE_REFINER_HPP
