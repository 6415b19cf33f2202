// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_GEOMETRY_CONDITIONING_HPP
#define TRIPOSE_CORE_GEOMETRY_CONDITIONING_HPP

namespace tripose {

/** The conditioning thresholds that several stages share, so that they judge a feature alike: the
scorer and the refinement triangulate the same structure, the three-view and stereo-rig systems
balance the same rows.
*/

/** det / trace^3 of a point's triangulation normal matrix (triangulatePoint()) below which its rays
count as parallel. The ratio is scale-free and, up to a factor of order one, the smallest
eigenvalue over the trace: at 1e-14 the solve is still two orders above double rounding (1e-16 of
the trace); below it the depth would be rounding.
*/
constexpr double kPointTriangulationConditioning = 1e-14;

/** Ratio of the second to the first singular value of a line's back-projected planes
(triangulateLine()) below which they do not pin the line down. For two planes it is about the sine
of the angle between them: 1e-5 rad is far below what image noise resolves, so the bound only drops
lines in (or within rounding of) an epipolar plane, which have no 3D position; lines merely close to
one are judged by their residuals.
*/
constexpr double kLineTriangulationConditioning = 1e-5;

/** Frobenius norm to which a feature's block of rows in the linear systems is scaled: that of a
line's two unit rows, so that a point's block (four rows of rank 2) weighs as much as a line's in
A^T A whatever the image scales. sqrt(2), written out because std::sqrt is not constexpr in C++11.
*/
constexpr double kBalancedBlockNorm = 1.4142135623730951;

} // namespace tripose

#endif // TRIPOSE_CORE_GEOMETRY_CONDITIONING_HPP
