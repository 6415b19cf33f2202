// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_SCORING_KNOWN_STRUCTURE_HPP
#define OPENCV_TRIPOSE_SCORING_KNOWN_STRUCTURE_HPP

#include "../geometry/view_set.hpp"
#include "pose_scorer.hpp"

namespace tripose {

/** How well the known views pin the structure down, from the structure PoseScorer triangulates
from them. It decides how much the estimators search: where the known pair's rays are nearly
parallel (a narrow baseline) or the structure is one plane, the cost over the estimated pose has
several basins and a single refinement from the best hypothesis often stops in the wrong one.
*/

//! Median over the points with structure (a line: its two end points) of the widest angle (deg)
//! between their rays from the known views that see them, which all triangulate them (with two
//! known views, the angle of the pair); 0 when there are none.
double medianTriangulationAngleDeg(const ViewSet& set, const PoseScorer& scorer);

/** Widest angle (deg, 0 to 90) between two of the planes through line @p line's image lines in the
known views that see it, which meet in the triangulated line; 0 when fewer than two known views see
it. Near 0 the line lies close to an epipolar plane of every pair and its lifted end points slide
along it with the image noise.
*/
double linePlaneAngleDeg(const ViewSet& set, int line);

//! Smallest over largest singular value of the centred structure (points and line end points),
//! without the positions far off its plane (trimPlaneFit()): near 0 for coplanar structure, noisy or
//! not; 1 when there are fewer than four structure points.
double structureThickness(const ViewSet& set, const PoseScorer& scorer);

//! Below this median angle the known pair's depth is poor (1-2 % of the depth as baseline).
constexpr double kWeakTriangulationAngleDeg = 2.0;
/** Below this plane angle (linePlaneAngleDeg()) a line's triangulated position is too poor to serve
in a minimal sample: an end point's depth error is about the image error over the sine of the angle,
20 times it at 3 degrees. Such lines still vote in every score. */
constexpr double kWeakLinePlaneAngleDeg = 3.0;
//! Below this thickness the structure counts as planar (a facade seen with noise).
constexpr double kPlanarThickness = 0.05;
/** With a moderate triangulation angle (the paper's small motion) noisy depths thicken planar
structure into the range of thin general structure. Below this angle, structure up to this
thickness counts as planar: the general scenes it takes in pay the multi-start search, which leaves
their errors as they are (doc/studies/accuracy.md). */
constexpr double kModerateTriangulationAngleDeg = 15.0;
constexpr double kNoisyPlanarThickness = 0.35;

//! True where the known pair's rays meet at a weak angle (kWeakTriangulationAngleDeg: a narrow baseline).
inline bool knownPairIsNarrow(double medianAngleDeg)
{
    return medianAngleDeg < kWeakTriangulationAngleDeg;
}

inline bool knownPairIsNarrow(const ViewSet& set, const PoseScorer& scorer)
{
    return knownPairIsNarrow(medianTriangulationAngleDeg(set, scorer));
}

//! True for the regimes of the structure with several basins: a weak triangulation angle or planar
//! structure.
inline bool structureHasSeveralBasins(const ViewSet& set, const PoseScorer& scorer)
{
    const double angle = medianTriangulationAngleDeg(set, scorer);
    if (knownPairIsNarrow(angle))
        return true;
    const double thickness = structureThickness(set, scorer);
    return thickness < kPlanarThickness || (angle < kModerateTriangulationAngleDeg && thickness < kNoisyPlanarThickness);
}

/** True for the regimes with several basins: those of the structure (structureHasSeveralBasins()),
or mostly lines (under a quarter of the features are points: a line's residuals leave the motion
along it free, and for a planar target seen through lines alone the pose turned by pi about the
plane's normal fits every line exactly, told apart only by the side of the segments,
geometry/segment_cheirality.hpp).
*/
inline bool hasSeveralBasins(const ViewSet& set, const PoseScorer& scorer)
{
    return 4 * set.numPoints < set.numFeatures() || structureHasSeveralBasins(set, scorer);
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_SCORING_KNOWN_STRUCTURE_HPP
