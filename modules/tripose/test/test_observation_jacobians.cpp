// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Every analytic Jacobian of the residuals (geometry/residuals.hpp) and of the refinement's
// observation model (refine/observation_model.hpp) against central finite differences, for a
// known view, the estimated camera itself and a camera mounted on it (a stereo rig's second camera).

#include "test_precomp.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "../src/core/geometry/line_parameterization.hpp"
#include "../src/core/geometry/residuals.hpp"
#include "../src/core/refine/observation_model.hpp"

namespace opencv_test {
namespace {

using namespace ::tripose;

typedef Eigen::Matrix<double, 6, 1> Vector6d; // a left increment (omega, dt) of the estimated pose

// Central differences with this step have a truncation error of about step^2 times the third
// derivative and a rounding error of about 1e-16 / step relative to the residuals (hundreds of px):
// a relative agreement of 1e-6 separates a right Jacobian from a wrong one by orders of magnitude.
const double kStep = 1e-6;
const double kRelativeTolerance = 1e-6;

Eigen::Vector3d randomVector(RNG& rng, double scale)
{
    // One draw per statement, as C++ leaves the order of arguments and operands unspecified: the last
    // coordinate first (z before y before x, here and below) is the order the seeded scenarios were
    // drawn in so far (GCC's, right to left).
    const double z = rng.uniform(-scale, scale);
    const double y = rng.uniform(-scale, scale);
    const double x = rng.uniform(-scale, scale);
    return Eigen::Vector3d(x, y, z);
}

//! A camera-frame point with x and y in [-2, 2] and depth in [minDepth, maxDepth].
Eigen::Vector3d randomPointInFront(RNG& rng, double minDepth, double maxDepth)
{
    const double z = rng.uniform(minDepth, maxDepth);
    const double y = rng.uniform(-2.0, 2.0);
    const double x = rng.uniform(-2.0, 2.0);
    return Eigen::Vector3d(x, y, z);
}

//! A pixel of a 640x480 image.
Eigen::Vector2d randomPixel(RNG& rng)
{
    const double y = rng.uniform(0.0, 480.0);
    const double x = rng.uniform(0.0, 640.0);
    return Eigen::Vector2d(x, y);
}

Eigen::Matrix3d randomRotation(RNG& rng, double maxAngle)
{
    const Eigen::Vector3d axis = randomVector(rng, 1.0).normalized();
    return Eigen::AngleAxisd(rng.uniform(-maxAngle, maxAngle), axis).toRotationMatrix();
}

CameraPose randomSmallPose(RNG& rng)
{
    CameraPose p;
    p.R = randomRotation(rng, 0.3);
    p.t = randomVector(rng, 1.0);
    return p;
}

Intrinsics randomIntrinsics(RNG& rng)
{
    Eigen::Matrix3d K;
    K << rng.uniform(600.0, 900.0), rng.uniform(-2.0, 2.0), rng.uniform(300.0, 340.0), 0, rng.uniform(600.0, 900.0),
        rng.uniform(220.0, 260.0), 0, 0, 1;
    return Intrinsics(K);
}

//! The estimated camera's pose moved by the left increment (omega, dt).
CameraPose moved(const CameraPose& pose, const Vector6d& delta)
{
    const Eigen::Vector3d omega = delta.head<3>();
    const double angle = omega.norm();
    CameraPose p;
    p.R = angle > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, omega / angle) * pose.R) : pose.R;
    p.t = pose.t + delta.tail<3>();
    return p;
}

/** Central differences of @p residual (a function of the estimated pose and the view at that pose,
returning false when undefined) with respect to the left increment of the estimated pose.
*/
template <typename Residual>
Matrix26d numericPoseJacobian(const View& view, const CameraPose& estimated, Residual residual)
{
    Matrix26d numeric;
    for (int k = 0; k < 6; ++k)
    {
        const Vector6d h = kStep * Vector6d::Unit(k);
        const CameraPose plusPose = moved(estimated, h), minusPose = moved(estimated, -h);
        ViewAtPose plusView, minusView;
        plusView.set(view, plusPose);
        minusView.set(view, minusPose);
        Eigen::Vector2d plus, minus;
        EXPECT_TRUE(residual(plusView, plusPose, plus));
        EXPECT_TRUE(residual(minusView, minusPose, minus));
        numeric.col(k) = (plus - minus) / (2 * kStep);
    }
    return numeric;
}

//! Max |analytic - numeric| relative to the largest entry of the numeric Jacobian.
template <typename A, typename B>
double relativeError(const A& analytic, const B& numeric)
{
    return (analytic - numeric).cwiseAbs().maxCoeff() / std::max(numeric.cwiseAbs().maxCoeff(), 1e-12);
}

//! A view that sees one point and one segment, in one of three roles.
struct Scenario
{
    View view;
    CameraPose estimated;
    Eigen::Vector3d X;
    PluckerLine L;
};

enum Role { KnownView, EstimatedCamera, MountedCamera };

Scenario makeScenario(RNG& rng, Role role)
{
    Scenario s;
    s.view.camera = randomIntrinsics(rng);
    s.estimated = randomSmallPose(rng);
    s.view.estimated = role != KnownView;
    if (role == KnownView)
        s.view.pose = randomSmallPose(rng);
    else if (role == MountedCamera)
        s.view.pose = randomSmallPose(rng); // the rig offset
    const CameraPose pose = s.view.poseFor(s.estimated);
    // Structure 4-12 m in front of the view; observations a few pixels off the projections.
    const Eigen::Vector3d Xc = randomPointInFront(rng, 4.0, 12.0);
    s.X = pose.R.transpose() * (Xc - pose.t);
    const Eigen::Vector3d Bc = Xc + randomVector(rng, 2.0);
    const Eigen::Vector3d A = s.X, B = pose.R.transpose() * (Bc - pose.t);
    s.L.d = B - A;
    s.L.m = A.cross(s.L.d);
    const double dy = rng.uniform(-3.0, 3.0);
    const double dx = rng.uniform(-3.0, 3.0);
    s.view.points.push_back(s.view.camera.project(Xc) + Eigen::Vector2d(dx, dy));
    s.view.lineEnds.push_back(s.view.camera.project(Xc) + Eigen::Vector2d(rng.uniform(-3.0, 3.0), 2.0));
    s.view.lineEnds.push_back(s.view.camera.project(Bc) + Eigen::Vector2d(-1.0, rng.uniform(-3.0, 3.0)));
    return s;
}

TEST(Tripose_ResidualJacobians, point_residual_matches_finite_differences)
{
    RNG rng(11);
    for (int trial = 0; trial < 100; ++trial)
    {
        const Intrinsics c = randomIntrinsics(rng);
        const Eigen::Vector3d Xc = randomPointInFront(rng, 2.0, 20.0);
        const Eigen::Vector2d observed = randomPixel(rng);
        Eigen::Vector2d r;
        Matrix23d J;
        ASSERT_TRUE(pointResidual(c, Xc, observed, r, &J));
        Matrix23d numeric;
        for (int k = 0; k < 3; ++k)
        {
            const double h = kStep * std::max(1.0, std::abs(Xc(k)));
            Eigen::Vector2d plus, minus;
            ASSERT_TRUE(pointResidual(c, Xc + h * Eigen::Vector3d::Unit(k), observed, plus));
            ASSERT_TRUE(pointResidual(c, Xc - h * Eigen::Vector3d::Unit(k), observed, minus));
            numeric.col(k) = (plus - minus) / (2 * h);
        }
        EXPECT_LT(relativeError(J, numeric), kRelativeTolerance) << "trial " << trial;
    }
}

TEST(Tripose_ResidualJacobians, line_residual_matches_finite_differences)
{
    RNG rng(12);
    for (int trial = 0; trial < 100; ++trial)
    {
        const Intrinsics c = randomIntrinsics(rng);
        const Eigen::Vector3d A = randomPointInFront(rng, 2.0, 20.0);
        const Eigen::Vector3d moment = A.cross(A + randomVector(rng, 2.0));
        const Eigen::Vector2d end0 = randomPixel(rng);
        const Eigen::Vector2d end1 = randomPixel(rng);
        Eigen::Vector2d r;
        Matrix23d J;
        ASSERT_TRUE(lineResidual(c, moment, end0, end1, r, &J));
        Matrix23d numeric;
        for (int k = 0; k < 3; ++k)
        {
            const double h = kStep * moment.norm();
            Eigen::Vector2d plus, minus;
            ASSERT_TRUE(lineResidual(c, moment + h * Eigen::Vector3d::Unit(k), end0, end1, plus));
            ASSERT_TRUE(lineResidual(c, moment - h * Eigen::Vector3d::Unit(k), end0, end1, minus));
            numeric.col(k) = (plus - minus) / (2 * h);
        }
        EXPECT_LT(relativeError(J, numeric), kRelativeTolerance) << "trial " << trial;
    }
}

class Tripose_ObservationJacobians : public testing::TestWithParam<int>
{
};

TEST_P(Tripose_ObservationJacobians, point_matches_finite_differences)
{
    const Role role = (Role)GetParam();
    RNG rng(100 + GetParam());
    for (int trial = 0; trial < 100; ++trial)
    {
        const Scenario s = makeScenario(rng, role);
        ViewAtPose v;
        v.set(s.view, s.estimated);
        Eigen::Vector2d r;
        Matrix23d dX;
        Matrix26d dPose = Matrix26d::Constant(std::numeric_limits<double>::quiet_NaN());
        ASSERT_TRUE(pointObservation(v, s.estimated, s.X, s.view.points[0], 0.0, r, &dX, &dPose));

        Matrix23d numericX;
        for (int k = 0; k < 3; ++k)
        {
            const Eigen::Vector3d h = kStep * Eigen::Vector3d::Unit(k);
            Eigen::Vector2d plus, minus;
            ASSERT_TRUE(pointObservation(v, s.estimated, s.X + h, s.view.points[0], 0.0, plus));
            ASSERT_TRUE(pointObservation(v, s.estimated, s.X - h, s.view.points[0], 0.0, minus));
            numericX.col(k) = (plus - minus) / (2 * kStep);
        }
        EXPECT_LT(relativeError(dX, numericX), kRelativeTolerance) << "trial " << trial;

        if (role == KnownView)
        {
            EXPECT_TRUE(dPose.hasNaN()) << "a known view has no pose Jacobian";
            continue;
        }
        const Matrix26d numericPose =
            numericPoseJacobian(s.view, s.estimated, [&](const ViewAtPose& v, const CameraPose& pose, Eigen::Vector2d& r) {
                return pointObservation(v, pose, s.X, s.view.points[0], 0.0, r);
            });
        EXPECT_LT(relativeError(dPose, numericPose), kRelativeTolerance) << "trial " << trial;
    }
}

TEST_P(Tripose_ObservationJacobians, line_matches_finite_differences)
{
    const Role role = (Role)GetParam();
    RNG rng(200 + GetParam());
    for (int trial = 0; trial < 100; ++trial)
    {
        const Scenario s = makeScenario(rng, role);
        OrthonormalLine line;
        ASSERT_TRUE(OrthonormalLine::fromPlucker(s.L, line));
        const PluckerLine L = line.plucker();
        const Eigen::Matrix<double, 6, 4> chart = line.pluckerJacobian();
        ViewAtPose v;
        v.set(s.view, s.estimated);
        const Eigen::Vector2d &end0 = s.view.lineEnds[0], &end1 = s.view.lineEnds[1];
        Eigen::Vector2d r;
        Matrix24d dLine;
        Matrix26d dPose = Matrix26d::Constant(std::numeric_limits<double>::quiet_NaN());
        ASSERT_TRUE(lineObservation(v, s.estimated, L, end0, end1, r, &chart, &dLine, &dPose));

        Matrix24d numericLine;
        for (int k = 0; k < 4; ++k)
        {
            const Eigen::Vector4d h = kStep * Eigen::Vector4d::Unit(k);
            Eigen::Vector2d plus, minus;
            ASSERT_TRUE(lineObservation(v, s.estimated, line.plus(h).plucker(), end0, end1, plus));
            ASSERT_TRUE(lineObservation(v, s.estimated, line.plus(-h).plucker(), end0, end1, minus));
            numericLine.col(k) = (plus - minus) / (2 * kStep);
        }
        EXPECT_LT(relativeError(dLine, numericLine), kRelativeTolerance) << "trial " << trial;

        if (role == KnownView)
        {
            EXPECT_TRUE(dPose.hasNaN()) << "a known view has no pose Jacobian";
            continue;
        }
        const Matrix26d numericPose =
            numericPoseJacobian(s.view, s.estimated, [&](const ViewAtPose& v, const CameraPose& pose, Eigen::Vector2d& r) {
                return lineObservation(v, pose, L, end0, end1, r);
            });
        EXPECT_LT(relativeError(dPose, numericPose), kRelativeTolerance) << "trial " << trial;
    }
}

INSTANTIATE_TEST_CASE_P(Roles, Tripose_ObservationJacobians,
                        testing::Values((int)KnownView, (int)EstimatedCamera, (int)MountedCamera));

} // namespace
} // namespace opencv_test
