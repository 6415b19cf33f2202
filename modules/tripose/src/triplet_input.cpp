// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>
#include "opencv_compat.hpp"

#include "triplet_input.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

void requireFinite(const Mat& m, const char* name)
{
    if (!m.empty() && !checkRange(m))
        CV_Error_(Error::StsBadArg, ("%s contains NaN or Inf values", name));
}

//! Nx2 points as CV_64F; an empty array means no points.
Mat readPoints(InputArray arr, const char* name)
{
    if (arr.empty())
        return Mat(0, 2, CV_64F);
    Mat m = arr.getMat();
    const int n = m.checkVector(2);
    if (n < 0 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name, m.rows, m.cols, m.channels(), m.depth()));
    Mat out;
    m.reshape(1, n).convertTo(out, CV_64F);
    requireFinite(out, name);
    return out;
}

//! Mx4 segments or Mx3 homogeneous lines as CV_64F; an empty array means no lines.
Mat readLines(InputArray arr, const char* name)
{
    if (arr.empty())
        return Mat(0, 4, CV_64F);
    Mat m = arr.getMat();
    int width = 4;
    int n = m.checkVector(4);
    if (n < 0)
    {
        width = 3;
        n = m.checkVector(3);
    }
    if (n < 0 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be Mx4 segments (x0 y0 x1 y1) or Mx3 homogeneous lines (a b c), "
                                     "1-channel or 1xM/Mx1 multi-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name, m.rows, m.cols, m.channels(), m.depth()));
    Mat out;
    m.reshape(1, n).convertTo(out, CV_64F);
    CV_Assert(out.cols == width);
    requireFinite(out, name);
    return out;
}

std::vector<Mat> readPerView(InputArrayOfArrays arr, const char* name)
{
    std::vector<Mat> mats;
    if (arr.empty())
        return mats;
    if (arr.isMatVector() || arr.isUMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR)
        arr.getMatVector(mats);
    else
        mats.push_back(arr.getMat());
    if (mats.size() != 1 && mats.size() != 3)
        CV_Error_(Error::StsBadArg, ("%s must be one array shared by the three views or a vector of three (got %d)",
                                     name, (int)mats.size()));
    return mats;
}

Eigen::Matrix3d readCameraMatrix(const Mat& m, const std::string& name)
{
    if (m.total() != 9 || m.channels() != 1 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 CV_32F or CV_64F matrix", name.c_str()));
    Mat K;
    m.reshape(1, 3).convertTo(K, CV_64F);
    requireFinite(K, name.c_str());
    Eigen::Matrix3d E;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            E(r, c) = K.at<double>(r, c);
    if (E(2, 0) != 0 || E(2, 1) != 0 || E(2, 2) == 0 || E(1, 0) != 0)
        CV_Error_(Error::StsBadArg, ("%s must be upper triangular [fx s cx; 0 fy cy; 0 0 1]", name.c_str()));
    E /= E(2, 2);
    if (!(E(0, 0) > 0 && E(1, 1) > 0))
        CV_Error_(Error::StsBadArg, ("%s must have positive focal lengths (fx = %g, fy = %g)", name.c_str(), E(0, 0), E(1, 1)));
    return E;
}

Mat readDistortion(const Mat& m, const std::string& name)
{
    if (m.empty())
        return Mat();
    const int n = (int)m.total() * m.channels();
    if (!(n == 4 || n == 5 || n == 8 || n == 12 || n == 14) || (m.depth() != CV_32F && m.depth() != CV_64F) ||
        (m.rows != 1 && m.cols != 1))
        CV_Error_(Error::StsBadArg, ("%s must be a vector of 4, 5, 8, 12 or 14 distortion coefficients, CV_32F or CV_64F "
                                     "(got %d values)", name.c_str(), n));
    Mat d;
    m.reshape(1, 1).convertTo(d, CV_64F);
    requireFinite(d, name.c_str());
    return countNonZero(d) == 0 ? Mat() : d;
}

Eigen::Vector3d readTranslation(InputArray arr, const char* name)
{
    Mat m = arr.getMat();
    if (m.empty() || !(m.depth() == CV_32F || m.depth() == CV_64F) || m.total() * m.channels() != 3)
        CV_Error_(Error::StsBadArg, ("%s must be a 3-element translation vector, CV_32F or CV_64F", name));
    Mat t;
    m.convertTo(t, CV_64F);
    requireFinite(t, name);
    t = t.reshape(1, 3);
    Eigen::Vector3d e(t.at<double>(0), t.at<double>(1), t.at<double>(2));
    if (!(e.norm() > 0))
        CV_Error_(Error::StsBadArg, ("%s must be non-zero: the baseline of views 1-2 fixes the metric scale", name));
    return e;
}

//! Undistorted pixel coordinates of an Nx2 CV_64F array of pixel points.
Mat undistortPixels(const Mat& pixels, const Eigen::Matrix3d& K, const Mat& dist)
{
    if (dist.empty() || pixels.empty())
        return pixels;
    Mat Kcv(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            Kcv.at<double>(r, c) = K(r, c);
    Mat out;
    // Many more iterations than the default 5: the solver is exact on exact data and should stay so.
    undistortPoints(pixels.reshape(2, pixels.rows), out, Kcv, dist, noArray(), Kcv,
                    TermCriteria(TermCriteria::COUNT | TermCriteria::EPS, 100, 1e-15));
    return out.reshape(1, pixels.rows);
}

Eigen::Vector2d calibrate(const Eigen::Matrix3d& Kinv, double u, double v)
{
    const Eigen::Vector3d x = Kinv * Eigen::Vector3d(u, v, 1.0);
    return x.head<2>() / x(2);
}

Eigen::Vector3d normalizedLine(const Eigen::Vector3d& l)
{
    return l / l.head<2>().norm();
}

//! Calibrated lines of one view, plus two undistorted pixel points on each line.
void convertLines(const Mat& lines, const Eigen::Matrix3d& K, const Mat& dist, const char* name,
                  std::vector<Eigen::Vector3d>& calibrated, std::vector<Eigen::Vector2d>& pixelEnds)
{
    const Eigen::Matrix3d Kinv = K.inverse();
    calibrated.clear();
    pixelEnds.clear();
    if (lines.cols == 4)
    {
        const Mat ends = undistortPixels(lines.reshape(1, lines.rows * 2), K, dist);
        for (int i = 0; i < lines.rows; ++i)
        {
            const Eigen::Vector2d a(ends.at<double>(2 * i, 0), ends.at<double>(2 * i, 1));
            const Eigen::Vector2d b(ends.at<double>(2 * i + 1, 0), ends.at<double>(2 * i + 1, 1));
            if (!((a - b).norm() > 1e-6))
                CV_Error_(Error::StsBadArg, ("%s: segment %d has zero length", name, i));
            const Eigen::Vector2d ca = calibrate(Kinv, a.x(), a.y()), cb = calibrate(Kinv, b.x(), b.y());
            calibrated.push_back(normalizedLine(ca.homogeneous().cross(cb.homogeneous())));
            pixelEnds.push_back(a);
            pixelEnds.push_back(b);
        }
        return;
    }
    const Eigen::Vector2d principal(K(0, 2), K(1, 2));
    for (int i = 0; i < lines.rows; ++i)
    {
        const Eigen::Vector3d l(lines.at<double>(i, 0), lines.at<double>(i, 1), lines.at<double>(i, 2));
        const double n = l.head<2>().norm();
        if (!(n > 0))
            CV_Error_(Error::StsBadArg, ("%s: line %d has a = b = 0, which is not a line", name, i));
        const Eigen::Vector3d lp = l / n;
        const Eigen::Vector2d foot = principal - (lp.head<2>().dot(principal) + lp(2)) * lp.head<2>();
        const Eigen::Vector2d dir(-lp(1), lp(0));
        pixelEnds.push_back(foot - kHomogeneousLineHalfLength * dir);
        pixelEnds.push_back(foot + kHomogeneousLineHalfLength * dir);
        calibrated.push_back(normalizedLine(K.transpose() * lp));
    }
}

} // namespace

Eigen::Matrix3d readRotation(InputArray arr, const char* name)
{
    Mat m = arr.getMat();
    if (m.empty() || !(m.depth() == CV_32F || m.depth() == CV_64F) ||
        !((m.total() == 9 && m.channels() == 1) || m.total() * m.channels() == 3))
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 rotation matrix or a 3-element Rodrigues vector, CV_32F or CV_64F", name));
    Mat R;
    m.convertTo(R, CV_64F);
    requireFinite(R, name);
    if (R.total() * R.channels() == 3)
    {
        Mat rmat;
        Rodrigues(R.reshape(1, 3), rmat);
        R = rmat;
    }
    R = R.reshape(1, 3);
    Eigen::Matrix3d E;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            E(r, c) = R.at<double>(r, c);
    const double tolerance = m.depth() == CV_32F ? 1e-4 : 1e-6;
    const double orthogonality = (E.transpose() * E - Eigen::Matrix3d::Identity()).norm();
    if (!(orthogonality < tolerance) || E.determinant() < 0)
        CV_Error_(Error::StsBadArg, ("%s is not a rotation: |R^T R - I| = %g, det = %g", name, orthogonality, E.determinant()));
    // Remove rounding so that later algebra sees an exact rotation.
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(E, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return svd.matrixU() * svd.matrixV().transpose();
}

TripletData readTripletInput(InputArray points1, InputArray points2, InputArray points3,
                             InputArray lines1, InputArray lines2, InputArray lines3,
                             InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                             InputArray R12, InputArray t12, int minFeatures)
{
    const Mat P[3] = { readPoints(points1, "points1"), readPoints(points2, "points2"), readPoints(points3, "points3") };
    const Mat L[3] = { readLines(lines1, "lines1"), readLines(lines2, "lines2"), readLines(lines3, "lines3") };
    for (int v = 1; v < 3; ++v)
    {
        if (P[v].rows != P[0].rows)
            CV_Error_(Error::StsBadSize, ("points%d has %d points but points1 has %d: every view needs the same points",
                                          v + 1, P[v].rows, P[0].rows));
        if (L[v].rows != L[0].rows)
            CV_Error_(Error::StsBadSize, ("lines%d has %d lines but lines1 has %d: every view needs the same lines",
                                          v + 1, L[v].rows, L[0].rows));
        if (L[v].rows > 0 && L[v].cols != L[0].cols)
            CV_Error_(Error::StsBadArg, ("lines%d are %s but lines1 are %s: use one kind in all views", v + 1,
                                         L[v].cols == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)",
                                         L[0].cols == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)"));
    }
    if (P[0].rows + L[0].rows < minFeatures)
        CV_Error_(Error::StsBadArg, ("at least %d features (points + lines) are required, got %d points and %d lines",
                                     minFeatures, P[0].rows, L[0].rows));

    const std::vector<Mat> Ks = readPerView(cameraMatrix, "cameraMatrix");
    if (Ks.empty())
        CV_Error(Error::StsBadArg, "cameraMatrix must be one 3x3 matrix or a vector of three");
    const std::vector<Mat> Ds = readPerView(distCoeffs, "distCoeffs");

    TripletData data;
    data.view2.R = readRotation(R12, "R12");
    data.view2.t = readTranslation(t12, "t12");

    std::vector<Eigen::Vector3d>* calibratedLines[3] = { &data.lines1, &data.lines2, &data.lines3 };
    std::vector<Eigen::Vector2d>* calibratedPoints[3] = { &data.points1, &data.points2, &data.points3 };
    static const char* lineNames[3] = { "lines1", "lines2", "lines3" };
    for (int v = 0; v < 3; ++v)
    {
        const std::string kName = Ks.size() == 1 ? "cameraMatrix" : format("cameraMatrix[%d]", v);
        const std::string dName = Ds.size() == 1 ? "distCoeffs" : format("distCoeffs[%d]", v);
        const Eigen::Matrix3d K = readCameraMatrix(Ks[Ks.size() == 1 ? 0 : v], kName);
        const Mat dist = Ds.empty() ? Mat() : readDistortion(Ds[Ds.size() == 1 ? 0 : v], dName);
        if (!dist.empty() && L[v].rows > 0 && L[v].cols == 3)
            CV_Error_(Error::StsBadArg, ("%s are homogeneous lines (Mx3), which cannot be undistorted: "
                                         "pass segments (Mx4) or empty %s", lineNames[v], dName.c_str()));
        const Eigen::Matrix3d Kinv = K.inverse();

        ViewObservations& view = data.pixels[v];
        view.K = K;
        const Mat points = undistortPixels(P[v], K, dist);
        calibratedPoints[v]->reserve(points.rows);
        view.points.reserve(points.rows);
        for (int i = 0; i < points.rows; ++i)
        {
            const double u = points.at<double>(i, 0), w = points.at<double>(i, 1);
            calibratedPoints[v]->push_back(calibrate(Kinv, u, w));
            view.points.emplace_back(u, w);
        }
        convertLines(L[v], K, dist, lineNames[v], *calibratedLines[v], view.lineEnds);
    }
    return data;
}

} // namespace detail
} // namespace tripose
} // namespace cv
