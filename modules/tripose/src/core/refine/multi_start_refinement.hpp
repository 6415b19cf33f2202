// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_MULTI_START_REFINEMENT_HPP
#define OPENCV_TRIPOSE_REFINE_MULTI_START_REFINEMENT_HPP

#include <cmath>
#include <limits>
#include <vector>

#include "ml_refinement.hpp"

namespace tripose {

//! A local minimum of the maximum-likelihood cost.
struct LocalMinimum
{
    CameraPose pose;
    double rms = std::numeric_limits<double>::infinity(); //!< RMS reprojection error (px) over the used features.
    //! Features that entered the cost, less the lines that settled behind a view that sees them
    //! (RefinedStructure::lineInFront).
    int used = 0;
    int residuals = 0;  //!< Residuals in rms.
    int parameters = 0; //!< Pose and structure parameters that entered the cost: 6 + 3 per point + 4 per line.

    //! The cost the refinement minimises: the sum of squared residuals (px^2).
    double squares() const { return rms * rms * residuals; }
    //! The estimate of the noise variance (px^2) at this minimum; +inf without more residuals than parameters.
    double noiseVariance() const
    {
        return residuals > parameters ? squares() / (residuals - parameters) : std::numeric_limits<double>::infinity();
    }

    bool finite() const { return std::isfinite(rms) && pose.allFinite(); }
    /** Lower cost first; a minimum that leaves features out of the cost (behind a view, or not
    determined at the structure it started from) loses against one that uses more, whatever its RMS,
    since its RMS is over fewer residuals. So does one that explains lines only by seeing them
    behind a camera: for planar structure seen through lines alone, the pose turned by pi about the
    plane's normal has the true pose's residuals exactly (geometry/segment_cheirality.hpp). */
    bool betterThan(const LocalMinimum& other) const
    {
        if (finite() != other.finite())
            return finite();
        return used != other.used ? used > other.used : rms < other.rms;
    }
};

/** refinePoseAndStructure(), repeated from the refined pose with the structure triangulated afresh
there until that changes nothing: the structure triangulated at a poor start can sit in a minimum
of its own (a point pulled to the wrong depth, a feature left out of the cost) that the joint
iteration does not leave, though the pose is already in the right basin.
*/
LocalMinimum refineRetriangulating(const ViewSet& set, const CameraPose& start, const RefineOptions& params,
                                   const std::vector<int>* pointIndices = nullptr,
                                   const std::vector<int>* lineIndices = nullptr);

/** Starts that keep the rotation of @p pose and move the estimated camera's centre to each of the
26 directions of a 3x3x3 grid around the first known view, at the distance @p pose puts it from
that view: when the known pair's baseline is narrow or the structure is planar, the linear
estimate's rotation is close but its translation direction may be far off, in another basin.
Appends to @p starts.
*/
void centreDirectionStarts(const ViewSet& set, const CameraPose& pose, std::vector<CameraPose>& starts);

/** The best of the minima that refineRetriangulating() reaches from each of @p starts (see
LocalMinimum::betterThan()); non-finite when none was usable. */
LocalMinimum refineFromStarts(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& params,
                              const std::vector<int>* pointIndices = nullptr,
                              const std::vector<int>* lineIndices = nullptr,
                              std::vector<LocalMinimum>* minima = nullptr);

/** The search where the cost has several basins: refineFromStarts() from @p starts and from the
centreDirectionStarts() around the first of them; then, when the best minimum's rotation lies
apart from that first start's, from the centre-direction starts around the best minimum as well.
The first start's rotation is a hypothesis' (a linear estimate, degrees off with a narrow known
pair), and the starts that keep it miss basins that the same starts around the refined
rotation reach (doc/studies/accuracy.md, "Narrow known baselines: the lowest minimum"). The
refinements run at least kSearchIterations (multi_start_refinement.cpp; more when @p params asks);
then the lowest minima (a few, within a factor of the best cost) are refined again from their poses,
with more iterations and the structure re-triangulated there, and replaced by where that ends: the
best is chosen among minima refined to their ends, and refinement of the returned pose stays at its
cost. Appends every minimum kept to @p minima when given; returns the best.
*/
LocalMinimum searchBasins(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& params,
                          const std::vector<int>* pointIndices = nullptr,
                          const std::vector<int>* lineIndices = nullptr,
                          std::vector<LocalMinimum>* minima = nullptr);

/** The search of large sets where the cost has several basins: refineFromStarts() from @p starts
alone, with @p params' iterations, then the lowest minima settled as in searchBasins(). On large sets
the starts of the solver's estimates (the inliers' and hypothesis_starts') find the basin, and
searchBasins()' centre-direction starts add time without lowering the errors (doc/studies/accuracy.md,
"Narrow known baselines, large sets"). Appends every minimum kept to @p minima when given; returns
the best.
*/
LocalMinimum searchFromStarts(const ViewSet& set, const std::vector<CameraPose>& starts, const RefineOptions& params,
                              const std::vector<int>* pointIndices = nullptr,
                              const std::vector<int>* lineIndices = nullptr,
                              std::vector<LocalMinimum>* minima = nullptr);

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_MULTI_START_REFINEMENT_HPP
