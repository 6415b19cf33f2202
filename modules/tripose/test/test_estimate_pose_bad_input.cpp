// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The bad-input catalogue: every kind of malformed argument, each breaking one thing in a valid
// problem, must raise a cv::Exception whose message names the argument. Kinds of the shared inputs
// are checked through all three entry points (linear solver, robust estimator, refinement); the
// same catalogue runs through the command-line tool (test/python/test_cli_estimate.py) and through
// cv2.tripose (misc/python/test/test_tripose.py).

#include <cctype>

#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

enum Api { LINEAR, RANSAC, REFINE };

const char* apiName(Api api)
{
    return api == LINEAR ? "estimatePoseLinePoint" : api == RANSAC ? "estimatePoseLinePointRansac" : "refinePoseLinePoint";
}

//! The arguments of one call, starting from a valid problem; each test breaks one thing.
struct Call
{
    Mat p1, p2, p3, l1, l2, l3, K, dist, R12, t12;
    std::vector<Mat> Ks, dists;
    int method = cv::tripose::POSE_LINEAR;
    bool candidatesAsMat = false;      // pass Rs as a Mat instead of a vector of Mat
    cv::tripose::RansacParams ransac;
    cv::tripose::RefineParams refine;
    Mat R0, t0;                        // initial pose of the refinement

    explicit Call(const cv::tripose::support::SyntheticScene& s)
        : p1(s.points1.clone()), p2(s.points2.clone()), p3(s.points3.clone()),
          l1(s.lines1.clone()), l2(s.lines2.clone()), l3(s.lines3.clone()),
          K(s.cameraMatrices[0].clone()), R12(s.R12.clone()), t12(s.t12.clone()),
          R0(s.R.clone()), t0(s.t.clone())
    {
        ransac.minInliers = 0; // a few features, all right: no floor on the inliers above them
    }

    //! Solutions (linear), inliers (robust) or 1 for a finite refinement.
    int run(Api api) const
    {
        // Either a vector of intrinsics (Ks) or one matrix; the same for distortion.
        const _InputArray cameraMatrix = Ks.empty() ? _InputArray(K) : _InputArray(Ks);
        const _InputArray distCoeffs = dists.empty() ? _InputArray(dist) : _InputArray(dists);
        Mat R, t;
        switch (api)
        {
        case LINEAR:
        {
            std::vector<Mat> Rs;
            Mat RsMat;
            const _OutputArray candidates = candidatesAsMat ? _OutputArray(RsMat) : _OutputArray(Rs);
            return cv::tripose::estimatePoseLinePoint(p1, p2, p3, l1, l2, l3, cameraMatrix, distCoeffs, R12, t12, R, t,
                                                  method, candidates);
        }
        case RANSAC:
            return cv::tripose::estimatePoseLinePointRansac(p1, p2, p3, l1, l2, l3, cameraMatrix, distCoeffs, R12, t12,
                                                        R, t, ransac);
        case REFINE:
        default:
            R = R0.clone();
            t = t0.clone();
            return std::isfinite(cv::tripose::refinePoseLinePoint(p1, p2, p3, l1, l2, l3, cameraMatrix, distCoeffs, R12,
                                                              t12, R, t, refine)) ? 1 : 0;
        }
    }
};

bool isIdentifierChar(char c)
{
    return std::isalnum((unsigned char)c) || c == '_';
}

//! True when @p message names @p argument as a whole word ("R" is not found in "R12" or "Rodrigues").
bool namesArgument(const std::string& message, const std::string& argument)
{
    for (size_t at = message.find(argument); at != std::string::npos; at = message.find(argument, at + 1))
    {
        const size_t end = at + argument.size();
        const bool startsWord = at == 0 || !(isIdentifierChar(message[at - 1]) || message[at - 1] == '.');
        const bool endsWord = end == message.size() || !isIdentifierChar(message[end]);
        if (startsWord && endsWord)
            return true;
    }
    return false;
}

//! Runs the call through @p api and checks that it throws a cv::Exception whose message names @p argument.
void expectRejectedBy(Api api, const Call& call, const std::string& argument)
{
    try
    {
        call.run(api);
        ADD_FAILURE() << apiName(api) << ": no exception; expected one naming '" << argument << "'";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_TRUE(namesArgument(e.err, argument))
            << apiName(api) << ": message does not name '" << argument << "': " << e.err;
    }
}

//! A kind of the shared inputs: rejected by all three entry points alike.
void expectRejected(const Call& call, const std::string& argument)
{
    expectRejectedBy(LINEAR, call, argument);
    expectRejectedBy(RANSAC, call, argument);
    expectRejectedBy(REFINE, call, argument);
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

class Tripose_BadInput : public testing::Test
{
protected:
    Tripose_BadInput() : call(makeScene({ 3, 3 }, cv::tripose::support::MOTION_LARGE, 0.0, 1)) {}
    void keepFeatures(int points, int lines)
    {
        call.p1 = call.p1.rowRange(0, points).clone(); call.p2 = call.p2.rowRange(0, points).clone();
        call.p3 = call.p3.rowRange(0, points).clone();
        call.l1 = call.l1.rowRange(0, lines).clone(); call.l2 = call.l2.rowRange(0, lines).clone();
        call.l3 = call.l3.rowRange(0, lines).clone();
    }
    Call call;
};

// The unbroken problem passes every entry point: each rejection below is caused by its one change.
TEST_F(Tripose_BadInput, valid_call_succeeds)
{
    EXPECT_GT(call.run(LINEAR), 0);
    EXPECT_GT(call.run(RANSAC), 0);
    EXPECT_EQ(call.run(REFINE), 1);
}

// Shapes and types of the observations.
TEST_F(Tripose_BadInput, points_with_wrong_width) { call.p2 = Mat::zeros(3, 3, CV_64F); expectRejected(call, "points2"); }
TEST_F(Tripose_BadInput, points_with_integer_type) { call.p1.convertTo(call.p1, CV_32S); expectRejected(call, "points1"); }
TEST_F(Tripose_BadInput, points_with_three_channels) { call.p3 = Mat::zeros(3, 1, CV_64FC3); expectRejected(call, "points3"); }
TEST_F(Tripose_BadInput, lines_with_wrong_width) { call.l1 = Mat::zeros(3, 5, CV_64F); expectRejected(call, "lines1"); }
TEST_F(Tripose_BadInput, lines_with_two_channels) { call.l2 = Mat::zeros(3, 2, CV_64FC2); expectRejected(call, "lines2"); }
TEST_F(Tripose_BadInput, segments_mixed_with_homogeneous_lines)
{
    call.l3 = Mat::ones(3, 3, CV_64F);
    expectRejected(call, "lines3");
}

// Counts across views and in total.
TEST_F(Tripose_BadInput, point_counts_differ) { call.p3 = call.p3.rowRange(0, 2).clone(); expectRejected(call, "points3"); }
TEST_F(Tripose_BadInput, points_missing_in_one_view) { call.p2 = Mat(); expectRejected(call, "points2"); }
TEST_F(Tripose_BadInput, line_counts_differ) { call.l2 = call.l2.rowRange(0, 1).clone(); expectRejected(call, "lines2"); }
TEST_F(Tripose_BadInput, fewer_than_four_features)
{
    keepFeatures(1, 2);
    expectRejectedBy(LINEAR, call, "at least 4 features");
    expectRejectedBy(RANSAC, call, "at least 4 features");
}
TEST_F(Tripose_BadInput, fewer_than_three_features_to_refine)
{
    keepFeatures(1, 1);
    expectRejectedBy(REFINE, call, "at least 3 features");
}
TEST_F(Tripose_BadInput, nothing_at_all)
{
    call.p1 = call.p2 = call.p3 = Mat();
    call.l1 = call.l2 = call.l3 = Mat();
    expectRejectedBy(LINEAR, call, "at least 4 features");
    expectRejectedBy(RANSAC, call, "at least 4 features");
    expectRejectedBy(REFINE, call, "at least 3 features");
}

// Values of the observations.
TEST_F(Tripose_BadInput, nan_in_points) { call.p2.at<double>(1, 0) = kNaN; expectRejected(call, "points2"); }
TEST_F(Tripose_BadInput, inf_in_lines) { call.l3.at<double>(0, 3) = kInf; expectRejected(call, "lines3"); }
TEST_F(Tripose_BadInput, zero_length_segment)
{
    call.l2.at<double>(1, 2) = call.l2.at<double>(1, 0);
    call.l2.at<double>(1, 3) = call.l2.at<double>(1, 1);
    expectRejected(call, "lines2");
}
TEST_F(Tripose_BadInput, homogeneous_line_with_zero_normal)
{
    call.l1 = call.l2 = call.l3 = (Mat_<double>(3, 3) << 1, 0, -300, 0, 1, -200, 1, 1, -500);
    call.l1 = call.l1.clone();
    call.l1.at<double>(2, 0) = call.l1.at<double>(2, 1) = 0;
    expectRejected(call, "lines1");
}

// The known pose of view 2.
TEST_F(Tripose_BadInput, R12_not_a_rotation) { call.R12 = call.R12 * 1.1; expectRejected(call, "R12"); }

//! @p R with every element rounded to 6 significant digits, as a camera file prints it.
Mat roundedToSixDigits(const Mat& R)
{
    Mat out(R.size(), CV_64F);
    for (int i = 0; i < (int)R.total(); ++i)
        out.at<double>(i) = std::stod(cv::format("%.6g", R.at<double>(i)));
    return out;
}

double orthogonality(const Mat& R)
{
    return cv::norm(R.t() * R, Mat::eye(3, 3, CV_64F), NORM_L2);
}

// A rotation printed with 6 digits is a rotation: each entry point takes its nearest one and gives
// the pose of the exact rotation.
TEST_F(Tripose_BadInput, R12_rounded_to_six_digits_gives_the_pose_of_the_exact_one)
{
    const Mat exact = call.R12.clone();
    Call rounded = call;
    rounded.R12 = roundedToSixDigits(exact);
    rounded.R0 = roundedToSixDigits(call.R0);
    ASSERT_GT(orthogonality(rounded.R12), 1e-6); // far more than rounding to double precision leaves
    const double maxDeg = 1e-5 * 180.0 / CV_PI;

    Mat R, t, Rr, tr;
    ASSERT_GT(cv::tripose::estimatePoseLinePoint(call.p1, call.p2, call.p3, call.l1, call.l2, call.l3, call.K,
                                                 noArray(), exact, call.t12, R, t), 0);
    ASSERT_GT(cv::tripose::estimatePoseLinePoint(rounded.p1, rounded.p2, rounded.p3, rounded.l1, rounded.l2,
                                                 rounded.l3, rounded.K, noArray(), rounded.R12, rounded.t12, Rr, tr), 0);
    EXPECT_LT(poseError(Rr, tr, R, t).rotationDeg, maxDeg);

    ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(call.p1, call.p2, call.p3, call.l1, call.l2, call.l3, call.K,
                                                       noArray(), exact, call.t12, R, t, call.ransac), 0);
    ASSERT_GT(cv::tripose::estimatePoseLinePointRansac(rounded.p1, rounded.p2, rounded.p3, rounded.l1, rounded.l2,
                                                       rounded.l3, rounded.K, noArray(), rounded.R12, rounded.t12, Rr,
                                                       tr, rounded.ransac), 0);
    EXPECT_LT(poseError(Rr, tr, R, t).rotationDeg, maxDeg);

    // The refinement from a rounded initial R as well.
    R = call.R0.clone();
    t = call.t0.clone();
    Rr = rounded.R0.clone();
    tr = rounded.t0.clone();
    cv::tripose::refinePoseLinePoint(call.p1, call.p2, call.p3, call.l1, call.l2, call.l3, call.K, noArray(), exact,
                                     call.t12, R, t);
    cv::tripose::refinePoseLinePoint(rounded.p1, rounded.p2, rounded.p3, rounded.l1, rounded.l2, rounded.l3,
                                     rounded.K, noArray(), rounded.R12, rounded.t12, Rr, tr);
    EXPECT_LT(poseError(Rr, tr, R, t).rotationDeg, maxDeg);
}

// Further off than rounding (1e-3 in one element) is not a rotation.
TEST_F(Tripose_BadInput, R12_off_by_1e3_is_rejected)
{
    call.R12.at<double>(0, 1) += 1e-3;
    expectRejected(call, "R12");
}
TEST_F(Tripose_BadInput, refine_initial_R_off_by_1e3_is_rejected)
{
    call.R0.at<double>(1, 2) += 1e-3;
    expectRejectedBy(REFINE, call, "R");
}

TEST_F(Tripose_BadInput, R12_reflection) { call.R12 = -call.R12; expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, R12_wrong_shape) { call.R12 = Mat::eye(2, 2, CV_64F); expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, R12_integer_type) { call.R12 = Mat::eye(3, 3, CV_32S); expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, nan_in_R12) { call.R12.at<double>(0, 1) = kNaN; expectRejected(call, "R12"); }
TEST_F(Tripose_BadInput, t12_zero) { call.t12 = Mat::zeros(3, 1, CV_64F); expectRejected(call, "t12"); }
TEST_F(Tripose_BadInput, t12_wrong_size) { call.t12 = Mat::ones(4, 1, CV_64F); expectRejected(call, "t12"); }
TEST_F(Tripose_BadInput, inf_in_t12) { call.t12.at<double>(2) = -kInf; expectRejected(call, "t12"); }

// Intrinsics.
TEST_F(Tripose_BadInput, camera_matrix_negative_focal) { call.K.at<double>(0, 0) = -800; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_zero_focal) { call.K.at<double>(1, 1) = 0; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_singular) { call.K.at<double>(2, 2) = 0; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_not_upper_triangular) { call.K.at<double>(1, 0) = 5; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_wrong_shape) { call.K = Mat::eye(3, 4, CV_64F); expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_integer_type) { call.K.convertTo(call.K, CV_32S); expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, nan_in_camera_matrix) { call.K.at<double>(0, 2) = kNaN; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, camera_matrix_missing) { call.K = Mat(); expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, two_camera_matrices) { call.Ks = { call.K, call.K }; expectRejected(call, "cameraMatrix"); }
TEST_F(Tripose_BadInput, one_of_three_camera_matrices_bad)
{
    Mat bad = call.K.clone();
    bad.at<double>(0, 0) = -1;
    call.Ks = { call.K, bad, call.K };
    expectRejected(call, "cameraMatrix[1]");
}

// Distortion.
TEST_F(Tripose_BadInput, distortion_with_wrong_count) { call.dist = Mat::zeros(1, 6, CV_64F); call.dist.at<double>(0) = 0.1; expectRejected(call, "distCoeffs"); }
TEST_F(Tripose_BadInput, distortion_as_matrix) { call.dist = Mat::zeros(2, 4, CV_64F); expectRejected(call, "distCoeffs"); }
TEST_F(Tripose_BadInput, nan_in_distortion) { call.dist = (Mat_<double>(1, 5) << 0.1, kNaN, 0, 0, 0); expectRejected(call, "distCoeffs"); }
TEST_F(Tripose_BadInput, two_distortion_vectors)
{
    const Mat d = Mat::zeros(1, 5, CV_64F);
    call.dists = { d, d };
    expectRejected(call, "distCoeffs");
}
TEST_F(Tripose_BadInput, homogeneous_lines_with_distortion)
{
    call.l1 = call.l2 = call.l3 = (Mat_<double>(3, 3) << 1, 0, -300, 0, 1, -200, 1, 1, -500);
    call.dist = (Mat_<double>(1, 4) << 0.1, 0, 0, 0);
    expectRejected(call, "lines1");
}

// Flags and outputs of the linear solver.
TEST_F(Tripose_BadInput, unknown_method) { call.method = 42; expectRejectedBy(LINEAR, call, "method"); }
TEST_F(Tripose_BadInput, candidates_output_not_a_vector) { call.candidatesAsMat = true; expectRejectedBy(LINEAR, call, "candidateRs"); }

// Parameters of the robust estimator.
TEST_F(Tripose_BadInput, ransac_threshold_zero) { call.ransac.threshold = 0; expectRejectedBy(RANSAC, call, "params.threshold"); }
TEST_F(Tripose_BadInput, ransac_threshold_not_finite) { call.ransac.threshold = kInf; expectRejectedBy(RANSAC, call, "params.threshold"); }
TEST_F(Tripose_BadInput, ransac_confidence_zero) { call.ransac.confidence = 0; expectRejectedBy(RANSAC, call, "params.confidence"); }
TEST_F(Tripose_BadInput, ransac_confidence_one) { call.ransac.confidence = 1; expectRejectedBy(RANSAC, call, "params.confidence"); }
TEST_F(Tripose_BadInput, ransac_max_iterations_zero) { call.ransac.maxIterations = 0; expectRejectedBy(RANSAC, call, "params.maxIterations"); }

// Parameters and initial pose of the refinement.
TEST_F(Tripose_BadInput, refine_max_iterations_negative) { call.refine.maxIterations = -1; expectRejectedBy(REFINE, call, "params.maxIterations"); }
TEST_F(Tripose_BadInput, refine_unknown_loss) { call.refine.loss = 7; expectRejectedBy(REFINE, call, "params.loss"); }
TEST_F(Tripose_BadInput, refine_loss_scale_zero) { call.refine.lossScale = 0; expectRejectedBy(REFINE, call, "params.lossScale"); }
TEST_F(Tripose_BadInput, refine_negative_tolerance) { call.refine.tolerance = -1e-3; expectRejectedBy(REFINE, call, "params.tolerance"); }
TEST_F(Tripose_BadInput, refine_initial_R_not_a_rotation) { call.R0 = 2.0 * call.R0; expectRejectedBy(REFINE, call, "R"); }
TEST_F(Tripose_BadInput, refine_initial_R_nan) { call.R0.at<double>(2, 2) = kNaN; expectRejectedBy(REFINE, call, "R"); }
TEST_F(Tripose_BadInput, refine_initial_t_wrong_size) { call.t0 = Mat::ones(2, 1, CV_64F); expectRejectedBy(REFINE, call, "t"); }
TEST_F(Tripose_BadInput, refine_initial_t_inf) { call.t0.at<double>(0) = kInf; expectRejectedBy(REFINE, call, "t"); }

// The stereo-rig functions: the same arguments plus points4 and lines4, where a row of NaN marks a
// feature that view 3 or 4 does not see.
enum StereoApi { STEREO_LINEAR, STEREO_RANSAC, STEREO_REFINE };

const char* stereoApiName(StereoApi api)
{
    return api == STEREO_LINEAR ? "estimatePoseLinePointStereo"
                                : api == STEREO_RANSAC ? "estimatePoseLinePointStereoRansac" : "refinePoseLinePointStereo";
}

struct StereoCall
{
    Mat p[4], l[4], K, R12, t12, R0, t0;
    std::vector<Mat> Ks, dists;
    int method = cv::tripose::POSE_LINEAR;

    explicit StereoCall(const cv::tripose::support::SyntheticStereoScene& s)
        : K(s.cameraMatrices[0].clone()), R12(s.R12.clone()), t12(s.t12.clone()), R0(s.R.clone()), t0(s.t.clone())
    {
        const Mat* points[4] = { &s.points1, &s.points2, &s.points3, &s.points4 };
        const Mat* lines[4] = { &s.lines1, &s.lines2, &s.lines3, &s.lines4 };
        for (int v = 0; v < 4; ++v)
        {
            p[v] = points[v]->clone();
            l[v] = lines[v]->clone();
        }
    }

    int run(StereoApi api) const
    {
        const _InputArray cameraMatrix = Ks.empty() ? _InputArray(K) : _InputArray(Ks);
        const _InputArray distCoeffs = dists.empty() ? _InputArray(noArray()) : _InputArray(dists);
        Mat R, t;
        switch (api)
        {
        case STEREO_LINEAR:
            return cv::tripose::estimatePoseLinePointStereo(p[0], p[1], p[2], p[3], l[0], l[1], l[2], l[3], cameraMatrix,
                                                        distCoeffs, R12, t12, R, t, method);
        case STEREO_RANSAC:
        {
            cv::tripose::RansacParams params;
            params.minInliers = 0; // a few features, all right: no floor on the inliers above them
            return cv::tripose::estimatePoseLinePointStereoRansac(p[0], p[1], p[2], p[3], l[0], l[1], l[2], l[3],
                                                              cameraMatrix, distCoeffs, R12, t12, R, t, params);
        }
        case STEREO_REFINE:
        default:
            R = R0.clone();
            t = t0.clone();
            return std::isfinite(cv::tripose::refinePoseLinePointStereo(p[0], p[1], p[2], p[3], l[0], l[1], l[2], l[3],
                                                                    cameraMatrix, distCoeffs, R12, t12, R, t))
                       ? 1 : 0;
        }
    }
};

void expectStereoRejectedBy(StereoApi api, const StereoCall& call, const std::string& argument)
{
    try
    {
        call.run(api);
        ADD_FAILURE() << stereoApiName(api) << ": no exception; expected one naming '" << argument << "'";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_TRUE(namesArgument(e.err, argument))
            << stereoApiName(api) << ": message does not name '" << argument << "': " << e.err;
    }
}

void expectStereoRejected(const StereoCall& call, const std::string& argument)
{
    expectStereoRejectedBy(STEREO_LINEAR, call, argument);
    expectStereoRejectedBy(STEREO_RANSAC, call, argument);
    expectStereoRejectedBy(STEREO_REFINE, call, argument);
}

cv::tripose::support::SyntheticStereoScene stereoCatalogueScene()
{
    // Four points and three lines, point 3 and line 2 seen by view 3 only, point 1 by view 4 only.
    cv::tripose::support::SyntheticStereoParams params;
    params.numPoints = 4;
    params.numLines = 3;
    params.pointVisibility = { cv::tripose::support::SEEN_IN_BOTH, cv::tripose::support::SEEN_IN_VIEW4,
                               cv::tripose::support::SEEN_IN_BOTH, cv::tripose::support::SEEN_IN_VIEW3 };
    params.lineVisibility = { cv::tripose::support::SEEN_IN_BOTH, cv::tripose::support::SEEN_IN_BOTH,
                              cv::tripose::support::SEEN_IN_VIEW3 };
    params.seed = 1;
    return cv::tripose::support::generateSyntheticStereoScene(params);
}

class Tripose_StereoBadInput : public testing::Test
{
protected:
    Tripose_StereoBadInput() : call(stereoCatalogueScene()) {}
    StereoCall call;
};

TEST_F(Tripose_StereoBadInput, valid_call_succeeds)
{
    EXPECT_GT(call.run(STEREO_LINEAR), 0);
    EXPECT_GT(call.run(STEREO_RANSAC), 0);
    EXPECT_EQ(call.run(STEREO_REFINE), 1);
}

// Counts and shapes of the time-B observations.
TEST_F(Tripose_StereoBadInput, points4_with_another_row_count) { call.p[3] = call.p[3].rowRange(0, 3).clone(); expectStereoRejected(call, "points4"); }
TEST_F(Tripose_StereoBadInput, lines4_with_another_row_count) { call.l[3] = Mat::zeros(5, 4, CV_64F); expectStereoRejected(call, "lines4"); }
TEST_F(Tripose_StereoBadInput, points3_with_wrong_width) { call.p[2] = Mat::zeros(4, 3, CV_64F); expectStereoRejected(call, "points3"); }
TEST_F(Tripose_StereoBadInput, points4_with_integer_type) { call.p[3] = Mat::ones(4, 2, CV_32S); expectStereoRejected(call, "points4"); }
TEST_F(Tripose_StereoBadInput, lines4_homogeneous_beside_segments) { call.l[3] = Mat::ones(3, 3, CV_64F); expectStereoRejected(call, "lines4"); }
TEST_F(Tripose_StereoBadInput, points2_empty) { call.p[1] = Mat(); expectStereoRejected(call, "points2"); }

// Values: NaN marks a whole row, only in views 3 and 4, and never in both for one feature.
TEST_F(Tripose_StereoBadInput, partly_nan_point_row) { call.p[3].at<double>(0, 1) = kNaN; expectStereoRejected(call, "points4"); }
TEST_F(Tripose_StereoBadInput, partly_nan_line_row) { call.l[2].at<double>(1, 2) = kNaN; expectStereoRejected(call, "lines3"); }
TEST_F(Tripose_StereoBadInput, inf_in_points3) { call.p[2].at<double>(0, 0) = kInf; expectStereoRejected(call, "points3"); }
TEST_F(Tripose_StereoBadInput, inf_row_in_lines4) { call.l[3].row(0).setTo(kInf); expectStereoRejected(call, "lines4"); }
TEST_F(Tripose_StereoBadInput, nan_row_in_a_time_A_view) { call.p[0].row(0).setTo(kNaN); expectStereoRejected(call, "points1"); }
TEST_F(Tripose_StereoBadInput, nan_row_in_lines2) { call.l[1].row(1).setTo(kNaN); expectStereoRejected(call, "lines2"); }
// Point 1 is seen by view 4 only, line 2 by view 3 only.
TEST_F(Tripose_StereoBadInput, point_missing_in_both_views_3_and_4) { call.p[3].row(1).setTo(kNaN); expectStereoRejected(call, "points4"); }
TEST_F(Tripose_StereoBadInput, line_missing_in_both_views_3_and_4) { call.l[2].row(2).setTo(kNaN); expectStereoRejected(call, "lines3"); }
TEST_F(Tripose_StereoBadInput, no_time_B_points_at_all) { call.p[2] = call.p[3] = Mat(); expectStereoRejected(call, "points3"); }
TEST_F(Tripose_StereoBadInput, zero_length_segment_in_view_4)
{
    call.l[3].at<double>(0, 2) = call.l[3].at<double>(0, 0);
    call.l[3].at<double>(0, 3) = call.l[3].at<double>(0, 1);
    expectStereoRejected(call, "lines4");
}
TEST_F(Tripose_StereoBadInput, fewer_than_two_features)
{
    for (Mat& m : call.p)
        m = m.rowRange(0, 1).clone();
    for (Mat& m : call.l)
        m = Mat();
    expectStereoRejectedBy(STEREO_LINEAR, call, "at least 2 features");
    expectStereoRejectedBy(STEREO_RANSAC, call, "at least 3 features");
    expectStereoRejectedBy(STEREO_REFINE, call, "at least 2 features");
}
TEST_F(Tripose_StereoBadInput, fewer_than_three_features_for_ransac)
{
    for (Mat& m : call.p)
        m = m.rowRange(0, 1).clone();
    for (Mat& m : call.l)
        m = m.rowRange(0, 1).clone();
    // Two features seen by both time-B views: enough for the linear solver, which gives the exact motion.
    Mat R, t;
    EXPECT_GE(cv::tripose::estimatePoseLinePointStereo(call.p[0], call.p[1], call.p[2], call.p[3], call.l[0], call.l[1],
                                                   call.l[2], call.l[3], call.K, noArray(), call.R12, call.t12, R, t),
              1);
    ASSERT_FALSE(R.empty());
    EXPECT_LT(poseError(R, t, call.R0, call.t0).rotationDeg, 1e-6);
    EXPECT_LT(poseError(R, t, call.R0, call.t0).relativeTranslation, 1e-6);
    expectStereoRejectedBy(STEREO_RANSAC, call, "at least 3 features");
}

// The rig, the intrinsics and the flags.
TEST_F(Tripose_StereoBadInput, R12_not_a_rotation) { call.R12 = call.R12 * 1.1; expectStereoRejected(call, "R12"); }
TEST_F(Tripose_StereoBadInput, t12_zero) { call.t12 = Mat::zeros(3, 1, CV_64F); expectStereoRejected(call, "t12"); }
TEST_F(Tripose_StereoBadInput, three_camera_matrices) { call.Ks = { call.K, call.K, call.K }; expectStereoRejected(call, "cameraMatrix"); }
TEST_F(Tripose_StereoBadInput, one_of_four_camera_matrices_bad)
{
    Mat bad = call.K.clone();
    bad.at<double>(1, 1) = -5;
    call.Ks = { call.K, call.K, call.K, bad };
    expectStereoRejected(call, "cameraMatrix[3]");
}
TEST_F(Tripose_StereoBadInput, three_distortion_vectors)
{
    const Mat d = Mat::zeros(1, 5, CV_64F);
    call.dists = { d, d, d };
    expectStereoRejected(call, "distCoeffs");
}
TEST_F(Tripose_StereoBadInput, unknown_method) { call.method = 3; expectStereoRejectedBy(STEREO_LINEAR, call, "method"); }

// The robust functions' optional outputs follow the inlier masks in the order of the candidate
// functions (candidateRs, candidateTs, reprojectionErrors, covariance, noiseVariance). A call written
// for the earlier order of estimatePoseLinePointRansac() (covariance, noiseVariance right after the
// masks, the candidates last), or one that puts a vector where a single array goes, is rejected
// naming the output before any work, in every family.
TEST(Tripose_BadOutput, outputs_in_another_order_are_rejected)
{
    const cv::tripose::support::SyntheticScene s = makeScene({ 6, 6 }, cv::tripose::support::MOTION_LARGE, 0.0, 1);
    cv::tripose::support::SyntheticStereoParams stereoParams;
    stereoParams.numPoints = 6;
    stereoParams.numLines = 6;
    stereoParams.seed = 1;
    const cv::tripose::support::SyntheticStereoScene rig = cv::tripose::support::generateSyntheticStereoScene(stereoParams);
    const cv::tripose::support::SyntheticMultiViewScene mv(3, 6, 6, 1);
    cv::tripose::RansacParams params;
    params.minInliers = 0; // a few features, all right: no floor on the inliers above them

    // Each call with the given last five outputs; the name its message must hold.
    const auto threeView = [&](OutputArrayOfArrays a, OutputArrayOfArrays b, OutputArray c, OutputArray d, OutputArray e) {
        Mat R, t, pointInliers, lineInliers;
        cv::tripose::estimatePoseLinePointRansac(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                 s.cameraMatrices, noArray(), s.R12, s.t12, R, t, params, pointInliers,
                                                 lineInliers, a, b, c, d, e);
    };
    const auto stereo = [&](OutputArrayOfArrays a, OutputArrayOfArrays b, OutputArray c, OutputArray d, OutputArray e) {
        Mat R, t, pointInliers, lineInliers;
        cv::tripose::estimatePoseLinePointStereoRansac(rig.points1, rig.points2, rig.points3, rig.points4, rig.lines1,
                                                       rig.lines2, rig.lines3, rig.lines4, rig.cameraMatrices,
                                                       noArray(), rig.R12, rig.t12, R, t, params, pointInliers,
                                                       lineInliers, a, b, c, d, e);
    };
    const auto multiView = [&](OutputArrayOfArrays a, OutputArrayOfArrays b, OutputArray c, OutputArray d, OutputArray e) {
        Mat R, t, pointInliers, lineInliers;
        cv::tripose::estimatePoseMultiViewRansac(mv.points, mv.lines, mv.K, noArray(), mv.Rs, mv.ts, R, t, params,
                                                 pointInliers, lineInliers, a, b, c, d, e);
    };
    const auto linear = [&](OutputArrayOfArrays a, OutputArrayOfArrays b, OutputArray c, OutputArray d, OutputArray e) {
        Mat R, t;
        cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                           s.cameraMatrices, noArray(), s.R12, s.t12, R, t,
                                           cv::tripose::POSE_LINEAR_REFINE, a, b, c, d, e);
    };
    typedef std::function<void(OutputArrayOfArrays, OutputArrayOfArrays, OutputArray, OutputArray, OutputArray)> Api;
    const std::pair<const char*, Api> apis[] = { { "estimatePoseLinePointRansac", threeView },
                                                 { "estimatePoseLinePointStereoRansac", stereo },
                                                 { "estimatePoseMultiViewRansac", multiView },
                                                 { "estimatePoseLinePoint", linear } };
    const auto expectNamed = [](const char* api, const std::function<void()>& call, const std::string& argument) {
        try
        {
            call();
            ADD_FAILURE() << api << ": no exception; expected one naming '" << argument << "'";
        }
        catch (const cv::Exception& e)
        {
            EXPECT_TRUE(namesArgument(e.err, argument)) << api << ": message does not name '" << argument << "': " << e.err;
        }
    };
    for (const auto& api : apis)
    {
        Mat covariance, noiseVariance, errors;
        std::vector<Mat> Rs, ts;
        // The earlier order: covariance, noiseVariance, candidateRs, candidateTs, reprojectionErrors.
        expectNamed(api.first, [&] { api.second(covariance, noiseVariance, Rs, ts, errors); }, "candidateRs");
        expectNamed(api.first, [&] { api.second(noArray(), noiseVariance, noArray(), noArray(), noArray()); },
                    "candidateTs");
        expectNamed(api.first, [&] { api.second(noArray(), noArray(), Rs, noArray(), noArray()); }, "reprojectionErrors");
        expectNamed(api.first, [&] { api.second(noArray(), noArray(), noArray(), Rs, noArray()); }, "covariance");
        expectNamed(api.first, [&] { api.second(noArray(), noArray(), noArray(), noArray(), ts); }, "noiseVariance");
        // The order of the declarations: every output written, each of its own kind.
        EXPECT_NO_THROW(api.second(Rs, ts, errors, covariance, noiseVariance)) << api.first;
        EXPECT_GE(Rs.size(), 1u) << api.first;
        EXPECT_EQ(Rs.size(), ts.size()) << api.first;
        EXPECT_EQ((int)Rs.size(), errors.rows) << api.first;
        EXPECT_EQ(6, covariance.rows) << api.first;
        EXPECT_EQ(1u, noiseVariance.total()) << api.first;
    }
}

// The matcher itself must be able to fail: a message naming only a longer word does not count.
TEST(Tripose_BadInputMessage, argument_is_named_as_a_whole_word)
{
    EXPECT_TRUE(namesArgument("R is not a rotation", "R"));
    EXPECT_TRUE(namesArgument("params.threshold must be positive", "params.threshold"));
    EXPECT_TRUE(namesArgument("cameraMatrix[1] must be 3x3", "cameraMatrix[1]"));
    EXPECT_FALSE(namesArgument("R12 is not a rotation", "R"));
    EXPECT_FALSE(namesArgument("Rodrigues vector", "R"));
    EXPECT_FALSE(namesArgument("at least 4 features", "t"));
    EXPECT_FALSE(namesArgument("params.maxIterations must be positive", "maxIterations"));
}

}} // namespace
