// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_PLANAR_KERNEL_SOLUTIONS_HPP
#define OPENCV_TRIPOSE_PLANAR_KERNEL_SOLUTIONS_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/camera.hpp"
#include "../geometry/view_set.hpp"
#include "kernel_solutions.hpp"
#include "linear_system.hpp"

namespace tripose {

//! How flat the structure of a problem is (structurePlane()).
enum StructureFlatness
{
    STRUCTURE_GENERAL = 0,     //!< Thick, collinear, or a feature without a position: no plane.
    STRUCTURE_NEAR_PLANAR = 1, //!< Within 10 % of a plane: noise may hide that it is one.
    STRUCTURE_PLANAR = 2,      //!< Planar to rounding (relative thickness about 1e-6).
};

/** The plane pi (homogeneous, pi^T [X; 1] = 0, in view 1's frame with t12 scaled by @p pose12 as
given) that best fits the structure the selected features have in views 1-2: points triangulated
from views 1-2, each line by two of its points; and how well it fits. @p plane is set unless the
result is STRUCTURE_GENERAL. Near-planar: the structure's thickness (its standard deviation across
the plane) is below 10 % of its extent within the plane, as noisy data on one plane triangulate,
once the positions far off the plane (three times the median distance, three rounds) are left out.
*/
StructureFlatness structurePlane(const ViewSet& set, const CameraPose& pose12, const std::vector<int>* pointIndices,
                                 const std::vector<int>* lineIndices, Eigen::Vector4d& plane);

/** Solution vectors of A v = 0 when all structure lies on the plane @p plane (structurePlane()).

Every P3 + a pi^T (a in R^3) maps the structure as P3 = [R | t] does, so the kernel of A holds that
3-dimensional family besides v: its dimension is 4 from four features on (5 for two points and two
lines, which do not fix a plane-to-image homography), whatever the count of the general case
(test/evaluation/codegen/planar_kernel.py measures it). The family is known from the plane: A
restricted to its orthogonal complement has a kernel of dimension 1 (2), containing
w = lambda v + a pi^T for some a. On directions u orthogonal to the plane's normal n, w's rotation
block maps u to lambda R u, which fixes R up to the sign of lambda: the second sign gives R turned
by pi about n, which puts the structure behind view 3 and is left to the selection. With two
kernel vectors their combination is fixed first by the same condition (|M e1| = |M e2|,
M e1 . M e2 = 0 for an orthonormal pair e1, e2 in the plane): two quadrics in [b1^2, b1 b2, b2^2]
with one common root on exact data. The t part of each appended vector is zero (the caller takes
the least-squares t). Appends and returns how many were appended; none when the restricted kernel
is wider than 2 (the features do not fix the pose).
*/
int planarKernelSolutions(const ConstraintMatrix& A, const Eigen::Vector4d& plane, std::vector<Vector12d>& solutions);

} // namespace tripose

#endif // OPENCV_TRIPOSE_PLANAR_KERNEL_SOLUTIONS_HPP
