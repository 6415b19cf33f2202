// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_pose_common.hpp"

#include "../src/opencv/opencv_compat.hpp"

namespace opencv_test {
namespace {

// Degenerate configurations: the solver never throws for geometry (only for malformed arguments)
// and never returns NaN. Where the features do not fix the pose it returns no candidate; where they
// fix it only up to a symmetry, every candidate explains the observations exactly.

struct Views
{
    Mat K, R12, t12, R3, t3;
};

Views makeViews()
{
    Views v;
    v.K = (Mat_<double>(3, 3) << 800, 0, 319.5, 0, 800, 239.5, 0, 0, 1);
    Rodrigues(Vec3d(0.02, -0.15, 0.01), v.R12);
    v.t12 = (Mat_<double>(3, 1) << 2.0, 0.1, 0.3);
    Rodrigues(Vec3d(-0.03, 0.2, -0.02), v.R3);
    v.t3 = (Mat_<double>(3, 1) << -1.5, 0.2, 0.5);
    return v;
}

Mat project(const Views& v, const Mat& R, const Mat& t, const std::vector<Vec3d>& X)
{
    Mat out((int)X.size(), 2, CV_64F);
    for (size_t i = 0; i < X.size(); ++i)
    {
        Mat x = v.K * (R * Mat(X[i]) + t);
        out.at<double>((int)i, 0) = x.at<double>(0) / x.at<double>(2);
        out.at<double>((int)i, 1) = x.at<double>(1) / x.at<double>(2);
    }
    return out;
}

//! Observations of world points and segments (pairs of world points) in the three views.
struct DegenerateProblem
{
    Mat p[3], l[3];
};

DegenerateProblem observe(const Views& v, const std::vector<Vec3d>& points, const std::vector<Vec3d>& segmentEnds)
{
    const Mat I = Mat::eye(3, 3, CV_64F), zero = Mat::zeros(3, 1, CV_64F);
    const Mat* Rs[3] = { &I, &v.R12, &v.R3 };
    const Mat* ts[3] = { &zero, &v.t12, &v.t3 };
    DegenerateProblem pr;
    for (int k = 0; k < 3; ++k)
    {
        pr.p[k] = points.empty() ? Mat() : project(v, *Rs[k], *ts[k], points);
        pr.l[k] = segmentEnds.empty() ? Mat() : project(v, *Rs[k], *ts[k], segmentEnds).reshape(1, (int)segmentEnds.size() / 2);
    }
    return pr;
}

//! What the linear solver returns for a problem; every candidate checked finite and a proper rotation.
struct Solution
{
    int n = -1;
    std::vector<Mat> Rs, ts;
    Mat errors;
};

Solution solve(const Views& v, const DegenerateProblem& pr, const std::string& what)
{
    Solution s;
    Mat R, t;
    EXPECT_NO_THROW(s.n = cv::tripose::estimatePoseLinePoint(pr.p[0], pr.p[1], pr.p[2], pr.l[0], pr.l[1], pr.l[2], v.K,
                                                         noArray(), v.R12, v.t12, R, t, cv::tripose::POSE_LINEAR, s.Rs,
                                                         s.ts, s.errors))
        << what;
    EXPECT_EQ(s.n == 0, R.empty()) << what;
    for (int i = 0; i < s.n; ++i)
    {
        EXPECT_TRUE(cv::checkRange(s.Rs[i]) && cv::checkRange(s.ts[i])) << what << ": candidate " << i << " not finite";
        EXPECT_NEAR(cv::determinant(s.Rs[i]), 1.0, 1e-9) << what;
    }
    return s;
}

//! Features that do not fix the pose: no candidate at all.
void expectNoSolution(const Views& v, const DegenerateProblem& pr, const std::string& what)
{
    EXPECT_EQ(solve(v, pr, what).n, 0) << what;
}

std::vector<Vec3d> pointsOnLine(int n)
{
    std::vector<Vec3d> X;
    for (int i = 0; i < n; ++i)
        X.emplace_back(-1.0 + 0.5 * i, 0.3 + 0.1 * i, 10.0 + 0.2 * i);
    return X;
}

TEST(Tripose_DegenerateGeometry, collinear_points)
{
    const Views v = makeViews();
    // Six collinear points fix the pose up to a rotation about their line: the linear system still
    // has the rank to give candidates, members of that family, and each must reproject them exactly.
    // Four leave the linear system rank deficient.
    const Solution six = solve(v, observe(v, pointsOnLine(6), {}), "six collinear points");
    EXPECT_GE(six.n, 1) << "six collinear points";
    for (int i = 0; i < six.n; ++i)
        EXPECT_LT(six.errors.at<double>(i), 1e-5) << "six collinear points, candidate " << i;
    expectNoSolution(v, observe(v, pointsOnLine(4), {}), "four collinear points");
}

TEST(Tripose_DegenerateGeometry, parallel_lines)
{
    const Views v = makeViews();
    std::vector<Vec3d> ends;
    for (int i = 0; i < 6; ++i)
    {
        ends.emplace_back(-2.0 + 0.7 * i, -1.0, 9.0 + 0.3 * i);
        ends.emplace_back(-2.0 + 0.7 * i, 1.5, 9.0 + 0.3 * i);
    }
    expectNoSolution(v, observe(v, {}, ends), "six parallel lines");
    ends.resize(8);
    expectNoSolution(v, observe(v, {}, ends), "four parallel lines");
}

TEST(Tripose_DegenerateGeometry, lines_through_one_point)
{
    const Views v = makeViews();
    const Vec3d centre(0.2, -0.1, 10.0);
    std::vector<Vec3d> ends;
    for (int i = 0; i < 6; ++i)
    {
        const double a = 0.5 * i;
        ends.push_back(centre);
        ends.push_back(centre + Vec3d(std::cos(a), std::sin(a), 0.3 * std::cos(2 * a)));
    }
    expectNoSolution(v, observe(v, {}, ends), "six concurrent lines");
}

// Planar structure through the centre of view 1 (every feature seen edge-on there) still fixes the
// pose: views 1-2 give the plane, and the planar closed form the pose.
TEST(Tripose_DegenerateGeometry, features_coplanar_with_camera_centre_one_give_the_pose)
{
    // The plane y = 0.1 z passes through the centre of view 1: every feature is seen edge-on.
    const Views v = makeViews();
    std::vector<Vec3d> points, ends;
    for (int i = 0; i < 5; ++i)
    {
        const double z = 8.0 + i, x = -1.0 + 0.4 * i;
        points.emplace_back(x, 0.1 * z, z);
        ends.emplace_back(x, 0.1 * z, z);
        ends.emplace_back(x + 1.0, 0.1 * (z + 0.5), z + 0.5);
    }
    const Solution s = solve(v, observe(v, points, ends), "coplanar with the centre of view 1");
    ASSERT_GT(s.n, 0);
    EXPECT_LT(cv::norm(s.Rs[0] - v.R3), 1e-6);
    EXPECT_LT(cv::norm(s.ts[0] - v.t3), 1e-6);
}

TEST(Tripose_DegenerateGeometry, features_behind_the_cameras)
{
    const Views v = makeViews();
    std::vector<Vec3d> points;
    for (int i = 0; i < 6; ++i)
        points.emplace_back(-1.0 + 0.4 * i, 0.5 - 0.2 * i, -10.0 - i);
    expectNoSolution(v, observe(v, points, {}), "points behind all cameras");
}

TEST(Tripose_DegenerateGeometry, identical_observations_in_all_views)
{
    // Views 2 and 3 see exactly what view 1 sees (no parallax anywhere).
    const Views v = makeViews();
    std::vector<Vec3d> X = { Vec3d(0, 0, 10), Vec3d(1, 0.5, 12), Vec3d(-1, 0.2, 9), Vec3d(0.5, -0.7, 11), Vec3d(-0.4, 0.9, 13) };
    DegenerateProblem pr = observe(v, X, {});
    pr.p[1] = pr.p[0].clone();
    pr.p[2] = pr.p[0].clone();
    // No pose of view 3 explains this with the known, translated view 2. The system of five points
    // is not rank deficient, so the solver returns its best fit, and the reported error of every
    // candidate must say that it does not fit.
    const Solution s = solve(v, pr, "identical observations");
    EXPECT_GE(s.n, 1);
    for (int i = 0; i < s.n; ++i)
        EXPECT_GT(s.errors.at<double>(i), 1.0) << "candidate " << i;
}

}} // namespace
