// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// triangulateMultiView: structure from posed views that reprojects onto every observation of
// noise-free scenes, a wrong observation found by its error, features without structure, and the
// input errors.

#include "test_pose_common.hpp"

#include <functional>
#include <limits>

#include "tripose_support/synthetic_multiview_scene.hpp"

namespace opencv_test {
namespace {

typedef cv::tripose::support::SyntheticMultiViewScene MultiViewScene;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

//! Every view of @p s posed: the known views, then the new view at its true pose.
struct PosedViews
{
    std::vector<Mat> Rs, ts;
    explicit PosedViews(const MultiViewScene& s) : Rs(s.Rs), ts(s.ts)
    {
        Rs.push_back(Mat(s.R));
        ts.push_back(Mat(s.t));
    }
};

bool seen(const Mat& rows, int i)
{
    return !rows.empty() && !cvIsNaN(rows.at<double>(i, 0));
}

//! Pixel of world point @p X in a view at (@p R, @p t) with intrinsics @p K.
Vec2d project(const Matx33d& K, const Mat& R, const Mat& t, const Vec3d& X)
{
    const Vec3d x = K * (Matx33d(R) * X + Vec3d(t));
    return Vec2d(x[0] / x[2], x[1] / x[2]);
}

double distanceToLine(const Vec2d& p, const Vec2d& a, const Vec2d& b)
{
    const Vec2d d = b - a;
    return std::abs(d[0] * (p[1] - a[1]) - d[1] * (p[0] - a[0])) / cv::norm(d);
}

// Noise-free data: the structure is exact to rounding amplified by the triangulation's conditioning.
const double kExactPixels = 1e-6;

TEST(Tripose_TriangulateMultiView, structure_reprojects_onto_every_observation)
{
    for (int seed = 1; seed <= 5; ++seed)
    {
        SCOPED_TRACE(cv::format("seed %d", seed));
        const MultiViewScene s(4, 15, 15, 500 + seed);
        const PosedViews posed(s);
        const int V = (int)posed.Rs.size();
        Mat points3d, lines3d, pointErrors, lineErrors;
        const int n = cv::tripose::triangulateMultiView(s.points, s.lines, s.K, noArray(), posed.Rs, posed.ts, points3d,
                                                      lines3d, pointErrors, lineErrors);
        EXPECT_EQ(30, n);
        ASSERT_EQ(Size(3, 15), points3d.size());
        ASSERT_EQ(Size(6, 15), lines3d.size());
        ASSERT_EQ(Size(V, 15), pointErrors.size());
        ASSERT_EQ(Size(V, 15), lineErrors.size());
        for (int i = 0; i < 15; ++i)
            for (int v = 0; v < V; ++v)
            {
                if (!seen(s.points[v], i))
                    EXPECT_TRUE(cvIsNaN(pointErrors.at<double>(i, v)));
                else
                {
                    EXPECT_LT(pointErrors.at<double>(i, v), kExactPixels);
                    const Vec2d x = project(s.K, posed.Rs[v], posed.ts[v], Vec3d(points3d.ptr<double>(i)));
                    EXPECT_LT(cv::norm(x - Vec2d(s.points[v].ptr<double>(i))), kExactPixels) << "point " << i;
                }
                if (!seen(s.lines[v], i))
                    EXPECT_TRUE(cvIsNaN(lineErrors.at<double>(i, v)));
                else
                {
                    EXPECT_LT(lineErrors.at<double>(i, v), kExactPixels);
                    const double* L = lines3d.ptr<double>(i);
                    const Vec2d a = project(s.K, posed.Rs[v], posed.ts[v], Vec3d(L));
                    const Vec2d b = project(s.K, posed.Rs[v], posed.ts[v], Vec3d(L + 3));
                    const double* e = s.lines[v].ptr<double>(i);
                    EXPECT_LT(distanceToLine(Vec2d(e[0], e[1]), a, b), kExactPixels) << "line " << i;
                    EXPECT_LT(distanceToLine(Vec2d(e[2], e[3]), a, b), kExactPixels) << "line " << i;
                }
            }
    }
}

//! The first feature of @p rows seen by at least @p minViews views.
int featureSeenBy(const std::vector<Mat>& rows, int minViews)
{
    for (int i = 0; i < rows[0].rows; ++i)
    {
        int count = 0;
        for (const Mat& m : rows)
            count += seen(m, i) ? 1 : 0;
        if (count >= minViews)
            return i;
    }
    return -1;
}

TEST(Tripose_TriangulateMultiView, a_wrong_observation_has_the_largest_error)
{
    // One observation of a point and of a line moved by 8 px (a wrong link of a track): the
    // feature's structure is pulled towards it, but its own error stays the largest and above the
    // others; the other features are untouched.
    MultiViewScene s(5, 12, 12, 77, 4);
    const PosedViews posed(s);
    const int p = featureSeenBy(s.points, 4), l = featureSeenBy(s.lines, 4);
    ASSERT_GE(p, 0);
    ASSERT_GE(l, 0);
    int pv = -1, lv = -1;
    for (int v = 0; v < (int)s.points.size() && (pv < 0 || lv < 0); ++v)
    {
        if (pv < 0 && seen(s.points[v], p))
            pv = v;
        if (lv < 0 && seen(s.lines[v], l))
            lv = v;
    }
    s.points[pv] = s.points[pv].clone();
    s.points[pv].at<double>(p, 0) += 8;
    s.lines[lv] = s.lines[lv].clone();
    s.lines[lv].at<double>(l, 1) += 8;
    s.lines[lv].at<double>(l, 3) += 8;
    Mat points3d, lines3d, pointErrors, lineErrors;
    cv::tripose::triangulateMultiView(s.points, s.lines, s.K, noArray(), posed.Rs, posed.ts, points3d, lines3d,
                                      pointErrors, lineErrors);
    for (int kind = 0; kind < 2; ++kind)
    {
        const Mat& errors = kind == 0 ? pointErrors : lineErrors;
        const int wrong = kind == 0 ? p : l, wrongView = kind == 0 ? pv : lv;
        for (int i = 0; i < errors.rows; ++i)
        {
            double largest = 0;
            int at = -1;
            for (int v = 0; v < errors.cols; ++v)
                if (!cvIsNaN(errors.at<double>(i, v)) && errors.at<double>(i, v) > largest)
                {
                    largest = errors.at<double>(i, v);
                    at = v;
                }
            if (i != wrong)
            {
                EXPECT_LT(largest, kExactPixels) << (kind == 0 ? "point " : "line ") << i;
                continue;
            }
            EXPECT_EQ(wrongView, at);
            EXPECT_GT(largest, 2.0); // 8 px shared among four or more views: most stays with the wrong one
        }
    }
}

TEST(Tripose_TriangulateMultiView, features_without_structure_are_nan_and_their_errors_infinite)
{
    // Point 0 and line 0 seen by view 0 only: no structure, an infinite error in view 0.
    MultiViewScene s(3, 6, 6, 5, 3);
    const PosedViews posed(s);
    const int V = (int)posed.Rs.size();
    for (int v = 0; v < V; ++v)
    {
        s.points[v] = s.points[v].clone();
        s.lines[v] = s.lines[v].clone();
        if (v > 0)
        {
            s.points[v].row(0).setTo(kNaN);
            s.lines[v].row(0).setTo(kNaN);
        }
    }
    Mat points3d, lines3d, pointErrors, lineErrors;
    const int n = cv::tripose::triangulateMultiView(s.points, s.lines, s.K, noArray(), posed.Rs, posed.ts, points3d,
                                                  lines3d, pointErrors, lineErrors);
    EXPECT_EQ(10, n);
    for (int c = 0; c < 3; ++c)
        EXPECT_TRUE(cvIsNaN(points3d.at<double>(0, c)));
    for (int c = 0; c < 6; ++c)
        EXPECT_TRUE(cvIsNaN(lines3d.at<double>(0, c)));
    EXPECT_TRUE(cvIsInf(pointErrors.at<double>(0, 0)));
    EXPECT_TRUE(cvIsInf(lineErrors.at<double>(0, 0)));
    for (int v = 1; v < V; ++v)
    {
        EXPECT_TRUE(cvIsNaN(pointErrors.at<double>(0, v)));
        EXPECT_TRUE(cvIsNaN(lineErrors.at<double>(0, v)));
    }
    EXPECT_TRUE(cv::checkRange(points3d.rowRange(1, 6)));
    EXPECT_TRUE(cv::checkRange(lines3d.rowRange(1, 6)));
}

TEST(Tripose_TriangulateMultiView, bad_input_is_named)
{
    const MultiViewScene s(3, 6, 6, 9);
    const PosedViews posed(s);
    Mat points3d, lines3d;
    auto run = [&](const std::vector<Mat>& points, const std::vector<Mat>& lines, const std::vector<Mat>& Rs,
                   const std::vector<Mat>& ts) {
        return [=, &points3d, &lines3d]() {
            cv::tripose::triangulateMultiView(points, lines, s.K, noArray(), Rs, ts, points3d, lines3d);
        };
    };
    // One view only.
    expectNamed(run({ s.points[0] }, { s.lines[0] }, { posed.Rs[0] }, { posed.ts[0] }), "Rs");
    // ts not matching Rs.
    expectNamed(run(s.points, s.lines, posed.Rs, { posed.ts[0], posed.ts[1] }), "ts");
    // One array too few.
    expectNamed(run({ s.points[0], s.points[1], s.points[2] }, s.lines, posed.Rs, posed.ts), "points");
    // A row count that differs.
    std::vector<Mat> shortLines = s.lines;
    shortLines[2] = shortLines[2].rowRange(0, 5).clone();
    expectNamed(run(s.points, shortLines, posed.Rs, posed.ts), "lines[2]");
    // A rotation that is not one.
    std::vector<Mat> badR = posed.Rs;
    badR[1] = Mat(2 * posed.Rs[1]);
    expectNamed(run(s.points, s.lines, badR, posed.ts), "Rs[1]");
    // A non-finite translation.
    std::vector<Mat> badT = posed.ts;
    badT[2] = posed.ts[2].clone();
    badT[2].at<double>(1) = kNaN;
    expectNamed(run(s.points, s.lines, posed.Rs, badT), "ts[2]");
    // No features.
    expectNamed(run({}, {}, posed.Rs, posed.ts), "points");
}

} // namespace
} // namespace opencv_test
