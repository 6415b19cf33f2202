// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_SOLVER_HPP
#define OPENCV_TRIPOSE_LINEAR_SOLVER_HPP

#include <vector>

#include "../geometry/view_set.hpp"
#include "linear_system.hpp"
#include "planar_kernel_solutions.hpp"

namespace tripose {

/** Dimension N of the kernel the linear method works in for a number of features. Each point and
each line constrains two of the 12 unknowns (a point's four trilinear rows have rank 2 on exact
data), so N = 12 - 2 (points + lines) for four or five features and N = 1 from six on. Structure
in general position; coplanar structure has a wider kernel (planar_kernel_solutions.hpp).
*/
int kernelDimensionFor(int numFeatures);

//! How linearPoseCandidates() builds its candidates; the defaults are the linear solver's.
struct CandidateOptions
{
    CandidateOptions() : twistedPairs(true), orderedKernel(false) {}

    //! Add each candidate's twisted pair (rotated by pi about the baseline).
    bool twistedPairs;
    /** Four or five features: rotate the kernel basis so that its last vector fits best. It helps
    samples scored without twisted pairs; with twisted pairs the QR order fails less often (the
    figures are in doc/studies/accuracy.md).
    */
    bool orderedKernel;
};

/** Candidate poses of view 3 by the unified linear method (@cite QadirNeubert2017, Sec. III), before
any scoring: the kernel of the stacked system, its combinations fixed by the orthonormality of R,
the nearest rotation and a least-squares translation for each, polished on the algebraic error,
plus its twisted pair as @p options say. Over-determined systems (N = 1) also contribute the N = 2
candidate. Uses the selected features only (null pointers: all of them). Appends to @p poses and
returns how many were appended.
*/
int linearPoseCandidates(const ViewSet& set, std::vector<CameraPose>& poses,
                         const std::vector<int>* pointIndices = nullptr,
                         const std::vector<int>* lineIndices = nullptr,
                         const CandidateOptions& options = CandidateOptions());

/** The candidates of linearPoseCandidates() from a constraint matrix built elsewhere (another
arrangement of views whose rows share the unknown v = [r1; r2; r3; t / translationScale]): rows laid
out as buildConstraintMatrix() lays them, the four rows of each of the @p numPoints points first,
then two rows per line, @p numFeatures features in all (at least four). The candidates' t is
multiplied by @p translationScale. @p structurePlane: the plane (in the rows' frame, translation
in units of @p translationScale) that the structure lies on or near, when it does (@p flatness, see
structurePlane()): on a plane the kernel is wider and the pose comes from the planar closed form
(planar_kernel_solutions.hpp) alone; near one, noise may hide a plane, so the closed form's
candidates join the general ones and the selection decides. Appends to @p poses and returns how many
were appended.
*/
int poseCandidatesFromRows(const ConstraintMatrix& A, int numPoints, int numFeatures, double translationScale,
                           std::vector<CameraPose>& poses, const CandidateOptions& options = CandidateOptions(),
                           const Eigen::Vector4d* structurePlane = nullptr,
                           StructureFlatness flatness = STRUCTURE_GENERAL);
} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_SOLVER_HPP
