// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_ROTATION_POLISH_HPP
#define OPENCV_TRIPOSE_LINEAR_ROTATION_POLISH_HPP

#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "../geometry/camera.hpp"
#include "../geometry/rotation.hpp"

namespace tripose {

/** Gauss-Newton on an algebraic error over R in SO(3), the error a quadratic in r = vec(R) (the
columns of R stacked), from @p R, for at most @p maxIterations steps. R moves by the left increment
R <- exp([w]x) R (rotateLeft()). The nearest rotation of a solution vector does not minimise the
algebraic error: with exact data the polish restores the exact pose to full precision whatever the
conditioning of the step that produced the vector; with noise it lowers the error the linear
method minimises. Steps that do not lower the error are rejected, so the result is never worse than
the input rotation.

@p cost supplies, for the error f(r):
- `double evaluate(const Eigen::Matrix<double, 9, 1>& r, Eigen::Matrix<double, 9, 1>& g) const`:
  f(r), and in @p g half its gradient in r (for f = |B r - beta|^2, B^T (B r - beta));
- `Eigen::Matrix3d gaussNewtonMatrix(const Eigen::Matrix<double, 9, 3>& D) const`: D^T (B^T B) D,
  half the Hessian in w, where D = d r / d w.
*/
template <class Cost>
void polishRotation(const Cost& cost, int maxIterations, Eigen::Matrix3d& R)
{
    typedef Eigen::Matrix<double, 9, 1> Vector9;
    // Below this step (rad) the previous Gauss-Newton matrix is kept (a chord step, see below).
    const double kChordStepAngle = 1e-2;
    // A step that lowers the error by less than this fraction gains nothing measurable: rounding
    // in the error's evaluation is about 1e-16 of its terms.
    const double kNegligibleGain = 1e-12;

    Vector9 g;
    double error = cost.evaluate(Eigen::Map<const Vector9>(R.data()), g);
    Eigen::Matrix3d Hinv = Eigen::Matrix3d::Zero(); // set in the first iteration
    double lastAngle = HUGE_VAL;
    for (int iteration = 0; iteration < maxIterations && error > 0; ++iteration)
    {
        // d r_j / d w = -[r_j]x for the columns r_j of R.
        Eigen::Matrix<double, 9, 3> D;
        for (int j = 0; j < 3; ++j)
            D.block<3, 3>(3 * j, 0) = -skew(R.col(j));
        // The Gauss-Newton matrix changes with R by about the last step: once the steps are small
        // (near the minimum) the previous one serves (a chord step), which saves its product;
        // convergence stays superlinear as the steps shrink.
        const bool fresh = lastAngle > kChordStepAngle;
        if (fresh)
        {
            // 3x3 symmetric positive (semi-)definite: the closed-form inverse is the cheapest
            // solve; a singular matrix gives a non-finite step, which ends the polish.
            Hinv = cost.gaussNewtonMatrix(D).inverse();
        }
        const Eigen::Vector3d step = -(Hinv * (D.transpose() * g));
        const double angle = step.norm();
        // A zero step is a stationary point: a fresh matrix would give the same.
        if (!std::isfinite(angle) || angle == 0)
            break;
        const Eigen::Matrix3d next = rotateLeft(step, R);
        Vector9 gNext;
        const double nextError = cost.evaluate(Eigen::Map<const Vector9>(next.data()), gNext);
        if (!(nextError < error))
        {
            if (fresh)
                break;
            lastAngle = HUGE_VAL; // a stale matrix may be the cause: retry with a fresh one
            continue;
        }
        R = next;
        lastAngle = angle;
        g = gNext;
        const bool converged = error - nextError <= kNegligibleGain * error;
        error = nextError;
        if (converged)
            break;
    }
}

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_ROTATION_POLISH_HPP
