// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINE_PARAMETERIZATION_HPP
#define OPENCV_TRIPOSE_LINE_PARAMETERIZATION_HPP

#include <Eigen/Core>

namespace tripose {

/** A 3D line in Plücker coordinates (m, d): d is a direction and m = X x d the moment, for any
point X of the line. The pair is homogeneous (defined up to a non-zero scale). Seen by a camera
x ~ R X + t, the line has moment R m + t x (R d) in the camera frame, which is also its image line
in calibrated coordinates.
*/
struct PluckerLine
{
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    Eigen::Vector3d d = Eigen::Vector3d::UnitZ();
};

/** The orthonormal representation of a 3D line (Bartoli & Sturm, CVIU 2005): the Plücker pair is
[m d] = U diag(w1, w2) restricted to its first two columns, with U in SO(3) and (w1, w2) a unit
2-vector, i.e. an element of SO(2). A line has 4 degrees of freedom and so does the update

    U <- U Exp([dtheta]x),  (w1, w2) <- rotation of (w1, w2) by dphi,

a minimal chart without singularities (unlike two-point or angle parameterizations), which is why
the refinement uses it. w2 / w1 is the inverse of the distance of the line from the origin.
*/
struct OrthonormalLine
{
    Eigen::Matrix3d U = Eigen::Matrix3d::Identity();
    double w1 = 0, w2 = 1;

    //! Returns false when d is zero or either input is not finite.
    static bool fromPlucker(const PluckerLine& line, OrthonormalLine& out);

    PluckerLine plucker() const
    {
        PluckerLine L;
        L.m = w1 * U.col(0);
        L.d = w2 * U.col(1);
        return L;
    }

    //! d(m, d) / d(dtheta, dphi) at the current line: rows 0-2 the moment, rows 3-5 the direction.
    Eigen::Matrix<double, 6, 4> pluckerJacobian() const;

    //! The line moved by the increment (dtheta, dphi) of the chart above.
    OrthonormalLine plus(const Eigen::Vector4d& delta) const;
};

/** Line closest (in the least-squares sense over the homogeneous planes) to the intersection of
@p count (at least 2) planes pi_k (pi^T X = 0 for homogeneous X): the null space of the rank-2
approximation of the stacked planes. Each plane should be scaled so that its residual is comparable
to an image distance. Returns false when the planes do not pin a line down: the second largest
singular value below @p minRatio times the largest (planes coincide), or the line is at infinity.
*/
bool lineFromPlanes(const Eigen::Vector4d* planes, int count, PluckerLine& line, double minRatio = 1e-6);

/** Point of @p line closest to the ray @p origin + lambda * @p ray (by default through the world
origin, the centre of view 1); the foot of the perpendicular from the world origin to the line when
the ray is parallel to it.
*/
Eigen::Vector3d closestPointToRay(const PluckerLine& line, const Eigen::Vector3d& ray,
                                  const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINE_PARAMETERIZATION_HPP
