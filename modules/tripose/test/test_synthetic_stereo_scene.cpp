// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The support library's stereo-rig scene generator: the ground truth of the stereo tests, so it is
// checked here against its documented geometry without any module code.

#include "test_pose_common.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::SyntheticStereoParams;
using cv::tripose::support::SyntheticStereoScene;
using cv::tripose::support::generateSyntheticStereoScene;
using cv::tripose::support::SEEN_IN_BOTH;
using cv::tripose::support::SEEN_IN_VIEW3;
using cv::tripose::support::SEEN_IN_VIEW4;

struct RigPoses
{
    Matx33d R[4];
    Vec3d t[4];
};

RigPoses rigPoses(const SyntheticStereoScene& s)
{
    RigPoses p;
    p.R[0] = Matx33d::eye();
    p.t[0] = Vec3d(0, 0, 0);
    p.R[1] = toMatx33(s.R12);
    p.t[1] = toVec3(s.t12);
    p.R[2] = toMatx33(s.R);
    p.t[2] = toVec3(s.t);
    p.R[3] = p.R[1] * p.R[2];
    p.t[3] = p.R[1] * p.t[2] + p.t[1];
    return p;
}

Point2d projectTo(const Matx33d& K, const Matx33d& R, const Vec3d& t, const Vec3d& X, double* depth = nullptr)
{
    const Vec3d c = R * X + t;
    if (depth)
        *depth = c[2];
    const Vec3d x = K * c;
    return Point2d(x[0] / x[2], x[1] / x[2]);
}

bool rowIsNaN(const Mat& m, int row)
{
    for (int c = 0; c < m.cols; ++c)
        if (!cvIsNaN(m.at<double>(row, c)))
            return false;
    return true;
}

double angleDegrees(const Matx33d& R)
{
    return degrees(std::acos(std::max(-1.0, std::min(1.0, 0.5 * (cv::trace(R) - 1)))));
}

SyntheticStereoParams params(int points, int lines, int seed)
{
    SyntheticStereoParams p;
    p.numPoints = points;
    p.numLines = lines;
    p.seed = seed;
    return p;
}

TEST(Tripose_SyntheticStereoScene, shapes_types_and_defaults)
{
    const SyntheticStereoParams d;
    EXPECT_EQ(d.baselineMin, 0.1);
    EXPECT_EQ(d.baselineMax, 0.5);
    EXPECT_EQ(d.depthMin, 5.0);
    EXPECT_EQ(d.depthMax, 30.0);
    EXPECT_EQ(d.motionMin, 0.3);
    EXPECT_EQ(d.motionMax, 3.0);
    const SyntheticStereoScene s = generateSyntheticStereoScene(params(7, 5, 1));
    for (const Mat* m : { &s.points1, &s.points2, &s.points3, &s.points4 })
        EXPECT_TRUE(m->type() == CV_64F && m->size() == Size(2, 7));
    for (const Mat* m : { &s.lines1, &s.lines2, &s.lines3, &s.lines4 })
        EXPECT_TRUE(m->type() == CV_64F && m->size() == Size(4, 5));
    ASSERT_EQ(s.cameraMatrices.size(), 4u);
    EXPECT_EQ(s.points3d.size(), Size(3, 7));
    EXPECT_EQ(s.lines3d.size(), Size(6, 5));
    EXPECT_EQ(cv::countNonZero(s.pointInliers), 7);
    EXPECT_EQ(cv::countNonZero(s.lineVisibility == SEEN_IN_BOTH), 5);
    for (const Mat* R : { &s.R12, &s.R })
    {
        const Matx33d r = toMatx33(*R);
        EXPECT_LT(cv::norm(r.t() * r - Matx33d::eye()), 1e-12);
        EXPECT_NEAR(cv::determinant(r), 1.0, 1e-12);
    }
}

TEST(Tripose_SyntheticStereoScene, geometry_follows_the_parameters)
{
    SyntheticStereoParams p = params(30, 20, 0);
    for (int seed = 0; seed < 50; ++seed)
    {
        p.seed = seed;
        const SyntheticStereoScene s = generateSyntheticStereoScene(p);
        const RigPoses poses = rigPoses(s);
        const Vec3d rightCentre = -(poses.R[1].t() * poses.t[1]);
        EXPECT_GE(rightCentre[0], p.baselineMin);
        EXPECT_LE(rightCentre[0], p.baselineMax);
        EXPECT_GT(rightCentre[0] / cv::norm(rightCentre), 0.95); // y, z: 5 % of x, Gaussian
        EXPECT_LE(angleDegrees(poses.R[1]), p.rigTiltDegrees + 1e-9);
        const double motion = cv::norm(poses.R[2].t() * poses.t[2]);
        EXPECT_GE(motion, p.motionMin - 1e-12);
        EXPECT_LE(motion, p.motionMax + 1e-12);
        EXPECT_LE(angleDegrees(poses.R[2]), p.rotationDegrees + 1e-9);
        const Matx33d K = toMatx33(s.cameraMatrices[0]);
        EXPECT_EQ(K(0, 0), 800.0);
        for (int i = 0; i < s.points3d.rows; ++i)
        {
            const Vec3d X(s.points3d.ptr<double>(i));
            EXPECT_GE(X[2], p.depthMin);
            EXPECT_LE(X[2], p.depthMax);
            for (int v = 0; v < 4; ++v)
            {
                double depth;
                const Point2d x = projectTo(K, poses.R[v], poses.t[v], X, &depth);
                EXPECT_GT(depth, 1.0);
                EXPECT_TRUE(x.x >= 2 && x.x <= 637 && x.y >= 2 && x.y <= 477) << x;
            }
        }
        for (int i = 0; i < s.lines3d.rows; ++i)
        {
            const double* L = s.lines3d.ptr<double>(i);
            for (int v = 0; v < 4; ++v)
                EXPECT_GE(cv::norm(projectTo(K, poses.R[v], poses.t[v], Vec3d(L)) -
                                   projectTo(K, poses.R[v], poses.t[v], Vec3d(L + 3))), 20.0);
        }
    }
}

TEST(Tripose_SyntheticStereoScene, noise_free_observations_reproject_exactly_and_missing_rows_are_nan)
{
    SyntheticStereoParams p = params(40, 30, 3);
    p.missingRatio = 0.5;
    const SyntheticStereoScene s = generateSyntheticStereoScene(p);
    const RigPoses poses = rigPoses(s);
    const Matx33d K = toMatx33(s.cameraMatrices[0]);
    const Mat* points[4] = { &s.points1, &s.points2, &s.points3, &s.points4 };
    const Mat* lines[4] = { &s.lines1, &s.lines2, &s.lines3, &s.lines4 };
    // Exactly round(0.5 * count) features seen by one time-B view, each by view 3 or view 4.
    EXPECT_EQ(cv::countNonZero(s.pointVisibility == SEEN_IN_BOTH), 20);
    EXPECT_EQ(cv::countNonZero(s.lineVisibility == SEEN_IN_BOTH), 15);
    EXPECT_GT(cv::countNonZero(s.pointVisibility == SEEN_IN_VIEW3), 0);
    EXPECT_GT(cv::countNonZero(s.pointVisibility == SEEN_IN_VIEW4), 0);
    for (int v = 0; v < 4; ++v)
    {
        const int bit = v == 2 ? SEEN_IN_VIEW3 : SEEN_IN_VIEW4;
        for (int i = 0; i < s.points3d.rows; ++i)
        {
            const bool seen = v < 2 || (s.pointVisibility.at<uchar>(i) & bit);
            EXPECT_EQ(rowIsNaN(*points[v], i), !seen) << "view " << v + 1 << " point " << i;
            if (seen)
            {
                const Point2d x = projectTo(K, poses.R[v], poses.t[v], Vec3d(s.points3d.ptr<double>(i)));
                EXPECT_LT(cv::norm(x - Point2d(points[v]->at<double>(i, 0), points[v]->at<double>(i, 1))), 1e-9);
            }
        }
        for (int i = 0; i < s.lines3d.rows; ++i)
        {
            const bool seen = v < 2 || (s.lineVisibility.at<uchar>(i) & bit);
            EXPECT_EQ(rowIsNaN(*lines[v], i), !seen) << "view " << v + 1 << " line " << i;
            if (seen)
            {
                const double* L = s.lines3d.ptr<double>(i);
                const double* o = lines[v]->ptr<double>(i);
                EXPECT_LT(cv::norm(projectTo(K, poses.R[v], poses.t[v], Vec3d(L)) - Point2d(o[0], o[1])), 1e-9);
                EXPECT_LT(cv::norm(projectTo(K, poses.R[v], poses.t[v], Vec3d(L + 3)) - Point2d(o[2], o[3])), 1e-9);
            }
        }
    }
}

TEST(Tripose_SyntheticStereoScene, given_visibility_is_honoured)
{
    SyntheticStereoParams p = params(3, 2, 4);
    p.pointVisibility = { SEEN_IN_VIEW3, SEEN_IN_VIEW4, SEEN_IN_BOTH };
    p.lineVisibility = { SEEN_IN_VIEW4, SEEN_IN_VIEW3 };
    p.missingRatio = 1.0; // ignored: the visibility is given
    const SyntheticStereoScene s = generateSyntheticStereoScene(p);
    EXPECT_TRUE(!rowIsNaN(s.points3, 0) && rowIsNaN(s.points4, 0));
    EXPECT_TRUE(rowIsNaN(s.points3, 1) && !rowIsNaN(s.points4, 1));
    EXPECT_TRUE(!rowIsNaN(s.points3, 2) && !rowIsNaN(s.points4, 2));
    EXPECT_TRUE(rowIsNaN(s.lines3, 0) && !rowIsNaN(s.lines4, 0));
    EXPECT_TRUE(!rowIsNaN(s.lines3, 1) && rowIsNaN(s.lines4, 1));
}

TEST(Tripose_SyntheticStereoScene, outliers_are_counted_marked_and_far_from_the_truth)
{
    SyntheticStereoParams p = params(40, 20, 5);
    p.missingRatio = 0.3;
    const SyntheticStereoScene clean = generateSyntheticStereoScene(p);
    p.outlierRatio = 0.3;
    const SyntheticStereoScene s = generateSyntheticStereoScene(p);
    EXPECT_EQ(cv::countNonZero(s.pointInliers), 28);
    EXPECT_EQ(cv::countNonZero(s.lineInliers), 14);
    // Same geometry and visibility as without outliers; only the time-B observations of the
    // outliers differ, by at least 20 px in every view that sees them.
    EXPECT_EQ(cv::norm(s.points3d, clean.points3d, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(s.pointVisibility, clean.pointVisibility, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(s.points1, clean.points1, NORM_INF), 0.0);
    for (int i = 0; i < 40; ++i)
        for (const auto& views : { std::make_pair(&s.points3, &clean.points3), std::make_pair(&s.points4, &clean.points4) })
        {
            if (rowIsNaN(*views.second, i))
                continue;
            const double d = cv::norm(views.first->row(i), views.second->row(i));
            if (s.pointInliers.at<uchar>(i))
                EXPECT_EQ(d, 0.0);
            else
                EXPECT_GE(d, 20.0);
        }
}

TEST(Tripose_SyntheticStereoScene, deterministic_with_separate_streams)
{
    SyntheticStereoParams p = params(10, 10, 6);
    const SyntheticStereoScene a = generateSyntheticStereoScene(p), b = generateSyntheticStereoScene(p);
    EXPECT_EQ(cv::norm(a.points3, b.points3, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(a.lines4, b.lines4, NORM_INF), 0.0);
    p.noiseSigma = 1.0;
    p.missingRatio = 0.5;
    p.numLines = 3;
    const SyntheticStereoScene c = generateSyntheticStereoScene(p);
    EXPECT_EQ(cv::norm(a.points3d, c.points3d, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(a.R, c.R, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(a.t12, c.t12, NORM_INF), 0.0);
    EXPECT_GT(cv::norm(a.points1, c.points1, NORM_INF), 0.0);
    p.seed = 7;
    EXPECT_GT(cv::norm(a.R, generateSyntheticStereoScene(p).R, NORM_INF), 0.0);
}

TEST(Tripose_SyntheticStereoScene, bad_parameters_throw_naming_the_parameter)
{
    const auto expectNamed = [](const SyntheticStereoParams& p, const std::string& name) {
        try
        {
            generateSyntheticStereoScene(p);
            ADD_FAILURE() << "no exception; expected one naming " << name;
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(e.err.find("SyntheticStereoParams::" + name + ":"), std::string::npos) << e.err;
        }
    };
    SyntheticStereoParams p;
    p.numPoints = -1; expectNamed(p, "numPoints"); p = SyntheticStereoParams();
    p.baselineMin = 0; expectNamed(p, "baselineMin"); p = SyntheticStereoParams();
    p.baselineMax = 0.05; expectNamed(p, "baselineMax"); p = SyntheticStereoParams();
    p.depthMin = 0.5; expectNamed(p, "depthMin"); p = SyntheticStereoParams();
    p.motionMax = std::numeric_limits<double>::infinity(); expectNamed(p, "motionMax"); p = SyntheticStereoParams();
    p.rotationDegrees = -1; expectNamed(p, "rotationDegrees"); p = SyntheticStereoParams();
    p.outlierRatio = 1; expectNamed(p, "outlierRatio"); p = SyntheticStereoParams();
    p.missingRatio = 1.5; expectNamed(p, "missingRatio"); p = SyntheticStereoParams();
    p.pointVisibility = { SEEN_IN_BOTH }; expectNamed(p, "pointVisibility"); p = SyntheticStereoParams();
    p.lineVisibility = { 3, 3, 0, 3 }; expectNamed(p, "lineVisibility"); p = SyntheticStereoParams();
    p.focalLength = 0; expectNamed(p, "focalLength"); p = SyntheticStereoParams();
    p.noiseSigma = -1; expectNamed(p, "noiseSigma");
}

TEST(Tripose_SyntheticStereoScene, infeasible_parameters_throw_instead_of_looping)
{
    // The rig turning round completely: nothing stays in view of all four cameras.
    SyntheticStereoParams p = params(5, 0, 0);
    p.rotationDegrees = 180;
    p.motionMin = p.motionMax = 3;
    bool threw = false;
    for (int seed = 0; seed < 20 && !threw; ++seed)
    {
        p.seed = seed;
        try
        {
            generateSyntheticStereoScene(p);
        }
        catch (const cv::Exception& e)
        {
            threw = e.err.find("four views barely overlap") != std::string::npos;
        }
    }
    EXPECT_TRUE(threw);
}

}} // namespace
