// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The support library's pose error, which every accuracy figure of the tests, samples, benchmarks
// and evaluation goes through.

#include "test_pose_common.hpp"

#include <functional>

#include "../src/opencv/opencv_compat.hpp"

namespace opencv_test {
namespace {

Mat rotationAbout(const Vec3d& axis, double radians)
{
    Mat R;
    Rodrigues(Mat(axis * (radians / cv::norm(axis))), R);
    return R;
}

TEST(Tripose_PoseError, equal_poses_have_no_error)
{
    const Mat R = rotationAbout(Vec3d(1, 2, 3), 0.7), t = (Mat_<double>(3, 1) << 1, -2, 0.5);
    const PoseError e = poseError(R, t, R, t);
    EXPECT_EQ(e.rotationDeg, 0.0);
    EXPECT_EQ(e.translation, 0.0);
    EXPECT_EQ(e.relativeTranslation, 0.0);
}

TEST(Tripose_PoseError, rotation_angle_in_degrees_from_tiny_to_half_turn)
{
    const Mat t = (Mat_<double>(3, 1) << 0, 0, 1);
    const Mat Rref = rotationAbout(Vec3d(-1, 0.5, 2), 1.1);
    for (double radians : { 1e-9, 1e-6, 0.3, 2.0, 3.1 })
    {
        const Mat R = rotationAbout(Vec3d(0.3, -1, 0.2), radians) * Rref;
        const double expected = radians * 180.0 / CV_PI;
        // The chord formula keeps the relative accuracy down to tiny angles (acos of the trace would
        // give 0 or ~1e-6 deg at 1e-9 rad).
        EXPECT_NEAR(poseError(R, t, Rref, t).rotationDeg, expected, 1e-5 * expected) << radians << " rad";
    }
}

TEST(Tripose_PoseError, translation_absolute_and_relative)
{
    const Mat R = Mat::eye(3, 3, CV_64F);
    const Mat t = (Mat_<double>(3, 1) << 1, 2, 2), tref = (Mat_<double>(3, 1) << 0, 0, 3);
    const PoseError e = poseError(R, t, R, tref);
    EXPECT_DOUBLE_EQ(e.translation, std::sqrt(6.0));
    EXPECT_DOUBLE_EQ(e.relativeTranslation, std::sqrt(6.0) / 3.0);
}

// Estimators return 3x1 translations, while solvers and readers elsewhere give 1x3 rows, 3-channel
// elements, Rodrigues vectors or float matrices: every combination gives the same errors.
TEST(Tripose_PoseError, shapes_and_types_of_either_pose_do_not_matter)
{
    const Mat R = rotationAbout(Vec3d(1, 1, 0), 0.2), Rref = rotationAbout(Vec3d(0, 1, 1), 0.25);
    const Mat t = (Mat_<double>(3, 1) << 0.5, -1, 4), tref = (Mat_<double>(3, 1) << 0.4, -1.1, 4.2);
    const PoseError reference = poseError(R, t, Rref, tref);
    EXPECT_GT(reference.rotationDeg, 1.0);
    EXPECT_GT(reference.relativeTranslation, 0.01);

    Mat rvec, rvecRef;
    Rodrigues(R, rvec);
    Rodrigues(Rref, rvecRef);
    Mat R32, t32;
    R.convertTo(R32, CV_32F);
    t.convertTo(t32, CV_32F);
    const Mat rotations[] = { R, rvec, rvec.t(), rvec.reshape(3, 1), R32 };
    const Mat translations[] = { t, t.t(), t.reshape(3, 1), t32, t32.t() };
    for (const Mat& r : rotations)
        for (const Mat& tr : translations)
            for (bool swapShapes : { false, true })
            {
                // The reference in the other shape: a row against a column, Rodrigues against 3x3.
                const Mat& rr = swapShapes ? rvecRef : Rref;
                const Mat trr = swapShapes ? tref.t() : tref;
                const PoseError e = poseError(r, tr, rr, trr);
                const bool isFloat = r.depth() == CV_32F || tr.depth() == CV_32F;
                const double tolerance = isFloat ? 1e-5 : 1e-12;
                EXPECT_NEAR(e.rotationDeg, reference.rotationDeg, tolerance * 100)
                    << "R " << r.size() << "x" << r.channels() << ", t " << tr.size() << "x" << tr.channels();
                EXPECT_NEAR(e.translation, reference.translation, tolerance);
                EXPECT_NEAR(e.relativeTranslation, reference.relativeTranslation, tolerance);
            }

    // A translation taken as a column of a larger matrix (not continuous).
    Mat Rt;
    cv::hconcat(R, t, Rt);
    EXPECT_NEAR(poseError(Rt.colRange(0, 3), Rt.col(3), Rref, tref).relativeTranslation,
                reference.relativeTranslation, 1e-15);
}

void expectArgumentNamed(const std::function<void()>& call, const std::string& argument)
{
    try
    {
        call();
        ADD_FAILURE() << "no exception for a bad " << argument;
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(e.msg.find("poseError: " + argument + " "), std::string::npos) << e.msg;
    }
}

TEST(Tripose_PoseError, bad_input_throws_naming_the_argument)
{
    const Mat R = Mat::eye(3, 3, CV_64F), t = (Mat_<double>(3, 1) << 0, 0, 1);
    Mat nanT = t.clone();
    nanT.at<double>(1) = std::numeric_limits<double>::quiet_NaN();
    Mat infR = R.clone();
    infR.at<double>(2, 2) = std::numeric_limits<double>::infinity();
    expectArgumentNamed([&] { poseError(Mat::eye(2, 2, CV_64F), t, R, t); }, "R");
    expectArgumentNamed([&] { poseError(R, Mat::ones(4, 1, CV_64F), R, t); }, "t");
    expectArgumentNamed([&] { poseError(R, t, Mat::eye(3, 3, CV_32S), t); }, "Rref");
    expectArgumentNamed([&] { poseError(R, t, R, nanT); }, "tref");
    expectArgumentNamed([&] { poseError(infR, t, R, t); }, "R");
    expectArgumentNamed([&] { poseError(Mat(), t, R, t); }, "R");
}

}} // namespace opencv_test::namespace
