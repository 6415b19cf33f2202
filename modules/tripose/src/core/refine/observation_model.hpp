// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_OBSERVATION_MODEL_HPP
#define OPENCV_TRIPOSE_REFINE_OBSERVATION_MODEL_HPP

#include <Eigen/Core>

#include "../geometry/residuals.hpp"
#include "../geometry/view_set.hpp"

namespace tripose {

typedef Eigen::Matrix<double, 2, 4> Matrix24d;
typedef Eigen::Matrix<double, 2, 6> Matrix26d;

/** One view of a ViewSet at the current estimate of the estimated camera's pose, in the form the
refinement's residuals need: its pose in the world and, for a view that moves with the estimated
camera, its mount (x_view = R_mount x_estimated + t_mount).

The pose Jacobians below are with respect to the estimated camera's left increment
R <- Exp([omega]x) R, t <- t + dt, as 6-vectors (omega, dt).
*/
struct ViewAtPose
{
    const View* view = nullptr;
    CameraPose pose;
    bool moves = false;
    CameraPose mount;
    //! The products with an identity pose or mount are skipped: the first known view of most
    //! problems is the world frame, and the estimated camera is its own mount.
    bool identityPose = false, identityMount = false;
    //! d(line moment in this camera) / d(m, d) = [R, [t]x R].
    Eigen::Matrix<double, 3, 6> momentJacobian;

    void set(const View& v, const CameraPose& estimated)
    {
        view = &v;
        moves = v.estimated;
        if (moves)
            mount = v.pose;
        identityMount = moves && isIdentity(mount);
        pose = v.poseFor(estimated);
        identityPose = isIdentity(pose);
        momentJacobian.leftCols<3>() = pose.R;
        momentJacobian.rightCols<3>().noalias() = skew(pose.t) * pose.R;
    }

    static bool isIdentity(const CameraPose& p) { return p.R.isIdentity(0.0) && p.t.isZero(0.0); }
};

/** Residual (pointResidual()) of world point @p X observed at @p observed in @p v, with the
estimated camera at @p estimated. Optionally d(residual)/dX and, for a view that moves, d(residual)
/ d(omega, dt) (left untouched for a known view). False as pointResidual().
*/
inline bool pointObservation(const ViewAtPose& v, const CameraPose& estimated, const Eigen::Vector3d& X,
                             const Eigen::Vector2d& observed, double minDepth, Eigen::Vector2d& residual,
                             Matrix23d* dStructure = nullptr, Matrix26d* dPose = nullptr)
{
    Matrix23d dCamera;
    const bool jacobians = dStructure || dPose;
    if (!pointResidual(v.view->camera, v.pose.toCamera(X), observed, residual, jacobians ? &dCamera : nullptr,
                       minDepth))
        return false;
    if (dStructure)
    {
        if (v.identityPose)
            *dStructure = dCamera;
        else
            dStructure->noalias() = dCamera * v.pose.R;
    }
    if (dPose && v.moves)
    {
        // In the estimated camera's frame: d(R X + t) = -[R X]x domega + dt; the mount rotates it.
        Matrix23d dEstimated = dCamera;
        if (!v.identityMount)
            dEstimated.noalias() = dCamera * v.mount.R;
        dPose->leftCols<3>().noalias() = -dEstimated * skew(estimated.R * X);
        dPose->rightCols<3>() = dEstimated;
    }
    return true;
}

/** The smallest image-line normal (lineResidual()'s minNorm) with which 3D line @p L still counts as
a line in a camera at @p pose rather than as passing through its centre: relative to the size of
the moment, so that it does not depend on the line's scale.
*/
inline double minLineImageNorm(const CameraPose& pose, const PluckerLine& L)
{
    return 1e-12 * (L.m.norm() + pose.t.norm() * L.d.norm());
}

/** Residuals (lineResidual()) of the 3D line @p L against its observed end points @p end0, @p end1
in @p v, with the estimated camera at @p estimated. Optionally d(residuals)/d(line increment), given
@p chart = d(m, d)/d(increment) of the line's parameterization, and d(residuals)/d(omega, dt) for a
view that moves (left untouched for a known view). False when the line passes through the view's
centre (minLineImageNorm()).
*/
inline bool lineObservation(const ViewAtPose& v, const CameraPose& estimated, const PluckerLine& L,
                            const Eigen::Vector2d& end0, const Eigen::Vector2d& end1, Eigen::Vector2d& residual,
                            const Eigen::Matrix<double, 6, 4>* chart = nullptr, Matrix24d* dStructure = nullptr,
                            Matrix26d* dPose = nullptr)
{
    Matrix23d dMoment;
    const bool jacobians = dStructure || dPose;
    if (!lineResidual(v.view->camera, lineMomentInCamera(v.pose, L), end0, end1, residual,
                      jacobians ? &dMoment : nullptr, minLineImageNorm(v.pose, L)))
        return false;
    if (dStructure)
    {
        if (v.identityPose)
            dStructure->noalias() = dMoment * chart->topRows<3>();
        else
            dStructure->noalias() = (dMoment * v.momentJacobian) * (*chart);
    }
    if (dPose && v.moves)
    {
        // In the estimated camera's frame the moment is m_e = R m + t x (R d) and the direction
        // d_e = R d: dm_e = (-[Rm]x - [t]x [Rd]x) domega - [Rd]x dt, dd_e = -[Rd]x domega. The
        // mounted camera sees the moment R_mount m_e + t_mount x (R_mount d_e).
        const Eigen::Vector3d Rm = estimated.R * L.m, Rd = estimated.R * L.d;
        const Eigen::Matrix3d skewRd = skew(Rd);
        if (v.identityMount)
        {
            dPose->leftCols<3>().noalias() = -dMoment * (skew(Rm) + skew(estimated.t) * skewRd);
            dPose->rightCols<3>().noalias() = -dMoment * skewRd;
            return true;
        }
        const Matrix23d dMomentEstimated = dMoment * v.mount.R;
        const Matrix23d dDirectionEstimated = dMoment * skew(v.mount.t) * v.mount.R;
        dPose->leftCols<3>().noalias() = -dMomentEstimated * (skew(Rm) + skew(estimated.t) * skewRd);
        dPose->leftCols<3>().noalias() -= dDirectionEstimated * skewRd;
        dPose->rightCols<3>().noalias() = -dMomentEstimated * skewRd;
    }
    return true;
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_OBSERVATION_MODEL_HPP
