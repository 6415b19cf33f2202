// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

//! The arguments of one call, starting from a valid problem; each test breaks one thing.
struct Call
{
    Mat p1, p2, p3, l1, l2, l3, K, dist, R12, t12;
    std::vector<Mat> Ks;
    int method = tripose::POSE_LINEAR;

    explicit Call(const tripose::SyntheticScene& s)
        : p1(s.points1.clone()), p2(s.points2.clone()), p3(s.points3.clone()),
          l1(s.lines1.clone()), l2(s.lines2.clone()), l3(s.lines3.clone()),
          K(s.cameraMatrices[0].clone()), R12(s.R12.clone()), t12(s.t12.clone())
    {}

    int run() const
    {
        Mat R, t;
        if (!Ks.empty())
            return tripose::estimatePoseLinePoint(p1, p2, p3, l1, l2, l3, Ks, dist, R12, t12, R, t, method);
        return tripose::estimatePoseLinePoint(p1, p2, p3, l1, l2, l3, K, dist, R12, t12, R, t, method);
    }
};

//! Runs the call and checks that it throws a cv::Exception whose message contains @p argument.
void expectRejected(const Call& call, const std::string& argument)
{
    try
    {
        call.run();
        ADD_FAILURE() << "no exception; expected one naming '" << argument << "'";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(e.err.find(argument), std::string::npos)
            << "message does not name '" << argument << "': " << e.err;
    }
}

class Tripose_BadInput : public testing::Test
{
protected:
    Tripose_BadInput() : call(makeScene({ 3, 3 }, tripose::MOTION_LARGE, 0.0, 1)) {}
    Call call;
};

TEST_F(Tripose_BadInput, valid_call_succeeds) { EXPECT_GT(call.run(), 0); }

TEST_F(Tripose_BadInput, points_with_wrong_width) { call.p2 = Mat::zeros(3, 3, CV_64F); expectRejected(call, "points2"); }
TEST_F(Tripose_BadInput, points_with_integer_type) { call.p1.convertTo(call.p1, CV_32S); expectRejected(call, "points1"); }
TEST_F(Tripose_BadInput, point_counts_differ) { call.p3 = call.p3.rowRange(0, 2).clone(); expectRejected(call, "points3"); }
TEST_F(Tripose_BadInput, line_counts_differ) { call.l2 = call.l2.rowRange(0, 1).clone(); expectRejected(call, "lines2"); }
TEST_F(Tripose_BadInput, lines_with_wrong_width) { call.l1 = Mat::zeros(3, 5, CV_64F); expectRejected(call, "lines1"); }
TEST_F(Tripose_BadInput, segments_mixed_with_homogeneous_lines)
{
    call.l3 = Mat::ones(3, 3, CV_64F);
    expectRejected(call, "lines3");
}
TEST_F(Tripose_BadInput, fewer_than_four_features)
{
    call.p1 = call.p1.rowRange(0, 1).clone(); call.p2 = call.p2.rowRange(0, 1).clone(); call.p3 = call.p3.rowRange(0, 1).clone();
    call.l1 = call.l1.rowRange(0, 2).clone(); call.l2 = call.l2.rowRange(0, 2).clone(); call.l3 = call.l3.rowRange(0, 2).clone();
    expectRejected(call, "at least 4 features");
}
TEST_F(Tripose_BadInput, nothing_at_all)
{
    call.p1 = call.p2 = call.p3 = Mat();
    call.l1 = call.l2 = call.l3 = Mat();
    expectRejected(call, "at least 4 features");
}
TEST_F(Tripose_BadInput, nan_in_points) { call.p2.at<double>(1, 0) = std::numeric_limits<double>::quiet_NaN(); expectRejected(call, "points2"); }
TEST_F(Tripose_BadInput, inf_in_lines) { call.l3.at<double>(0, 3) = std::numeric_limits<double>::infinity(); expectRejected(call, "lines3"); }
TEST_F(Tripose_BadInput, zero_length_segment)
{
    call.l2.at<double>(1, 2) = call.l2.at<double>(1, 0);
    call.l2.at<double>(1, 3) = call.l2.at<double>(1, 1);
    expectRejected(call, "lines2");
}
TEST_F(Tripose_BadInput, R12_not_a_rotation) { call.R12 = call.R12 * 1.1; expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, R12_reflection) { call.R12 = -call.R12; expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, R12_wrong_shape) { call.R12 = Mat::eye(2, 2, CV_64F); expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, t12_zero) { call.t12 = Mat::zeros(3, 1, CV_64F); expectRejected(call, "t12"); }
TEST_F(Tripose_BadInput, t12_wrong_size) { call.t12 = Mat::ones(4, 1, CV_64F); expectRejected(call, "t12"); }
TEST_F(Tripose_BadInput, camera_matrix_negative_focal) { call.K.at<double>(0, 0) = -800; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_singular) { call.K.at<double>(2, 2) = 0; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_wrong_shape) { call.K = Mat::eye(3, 4, CV_64F); expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, two_camera_matrices) { call.Ks = { call.K, call.K }; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, distortion_with_wrong_count) { call.dist = Mat::zeros(1, 6, CV_64F); call.dist.at<double>(0) = 0.1; expectRejected(call, "distCoeffs"); }
TEST_F(Tripose_BadInput, homogeneous_lines_with_distortion)
{
    call.l1 = call.l2 = call.l3 = (Mat_<double>(3, 3) << 1, 0, -300, 0, 1, -200, 1, 1, -500);
    call.dist = (Mat_<double>(1, 4) << 0.1, 0, 0, 0);
    expectRejected(call, "lines1");
}
TEST_F(Tripose_BadInput, unknown_method) { call.method = 42; expectRejected(call, "method"); }

}} // namespace
