// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include <Eigen/Dense>
#include "../opencv_compat.hpp"

#include "../linear/pose_recovery.hpp"
#include "problem_input.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

/** Copies the values of a CV_32F/CV_64F array of at most two dimensions in row-major order (all
channels of an element in turn) into @p out, which must hold total() * channels() values.
Direct row pointers: a convertTo() into a new Mat plus checkRange() cost more than the solver's
own work on small problems. Returns false when a value is NaN or Inf.
*/
bool copyFinite(const Mat& m, double* out)
{
    const int width = m.cols * m.channels();
    bool finite = true;
    for (int r = 0; r < m.rows; ++r, out += width)
    {
        if (m.depth() == CV_64F)
        {
            const double* p = m.ptr<double>(r);
            for (int c = 0; c < width; ++c)
                out[c] = p[c];
        }
        else
        {
            const float* p = m.ptr<float>(r);
            for (int c = 0; c < width; ++c)
                out[c] = p[c];
        }
        for (int c = 0; c < width; ++c)
            finite &= std::isfinite(out[c]);
    }
    return finite;
}

void copyFiniteOrThrow(const Mat& m, double* out, const char* name)
{
    if (!copyFinite(m, out))
        CV_Error_(Error::StsBadArg, ("%s contains NaN or Inf values", name));
}

//! Name of a per-view argument in messages: "cameraMatrix" when shared, "cameraMatrix[v]" otherwise.
std::string viewArgumentName(const char* base, bool shared, int view)
{
    return shared ? std::string(base) : format("%s[%d]", base, view);
}

//! Nx2 points (row-major x y); an empty array means no points.
void readPoints(InputArray arr, const char* name, std::vector<Eigen::Vector2d>& out)
{
    out.clear();
    if (arr.empty())
        return;
    const Mat m = arr.getMat();
    const int n = m.checkVector(2);
    if (n < 0 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name, m.rows, m.cols, m.channels(), m.depth()));
    out.resize(n);
    if (n > 0)
        copyFiniteOrThrow(m, out[0].data(), name); // Eigen::Vector2d is two packed doubles
}

/** Mx4 segments (into @p ends, two points per segment: the layout is the same, x0 y0 x1 y1) or
Mx3 homogeneous lines (row-major into @p homogeneous); returns the width (4 or 3) and sets
@p count. An empty array means no lines (width 4).
*/
int readLines(InputArray arr, const char* name, std::vector<Eigen::Vector2d>& ends, std::vector<double>& homogeneous,
              int& count)
{
    ends.clear();
    homogeneous.clear();
    count = 0;
    if (arr.empty())
        return 4;
    const Mat m = arr.getMat();
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
    count = n;
    if (n == 0)
        return width;
    if (width == 4)
    {
        ends.resize(2 * (size_t)n);
        copyFiniteOrThrow(m, ends[0].data(), name);
    }
    else
    {
        homogeneous.resize(3 * (size_t)n);
        copyFiniteOrThrow(m, homogeneous.data(), name);
    }
    return width;
}

//! The arrays of a per-view argument: none, one shared by the three views, or three. Element
//! headers are taken one by one (getMat(i)): a vector of headers would cost an allocation per call.
struct PerViewArrays
{
    Mat mats[3];
    int count = 0;

    const Mat& forView(int v) const { return mats[count == 1 ? 0 : v]; }
    bool shared() const { return count == 1; }
};

PerViewArrays readPerView(InputArrayOfArrays arr, const char* name)
{
    PerViewArrays out;
    if (arr.empty())
        return out;
    if (arr.isMatVector() || arr.isUMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR)
    {
        const int n = (int)arr.total();
        if (n != 1 && n != 3)
            CV_Error_(Error::StsBadArg, ("%s must be one array shared by the three views or a vector of three (got %d)",
                                         name, n));
        for (int i = 0; i < n; ++i)
            out.mats[i] = arr.getMat(i);
        out.count = n;
    }
    else
    {
        out.mats[0] = arr.getMat();
        out.count = 1;
    }
    return out;
}

Eigen::Matrix3d readCameraMatrix(const Mat& m, bool shared, int view)
{
    if (m.total() != 9 || m.channels() != 1 || (m.depth() != CV_32F && m.depth() != CV_64F) || m.dims > 2)
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 CV_32F or CV_64F matrix",
                                     viewArgumentName("cameraMatrix", shared, view).c_str()));
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> E;
    if (!copyFinite(m, E.data()))
        CV_Error_(Error::StsBadArg, ("%s contains NaN or Inf values", viewArgumentName("cameraMatrix", shared, view).c_str()));
    if (E(2, 0) != 0 || E(2, 1) != 0 || E(2, 2) == 0 || E(1, 0) != 0)
        CV_Error_(Error::StsBadArg, ("%s must be upper triangular [fx s cx; 0 fy cy; 0 0 1]",
                                     viewArgumentName("cameraMatrix", shared, view).c_str()));
    E /= E(2, 2);
    if (!(E(0, 0) > 0 && E(1, 1) > 0))
        CV_Error_(Error::StsBadArg, ("%s must have positive focal lengths (fx = %g, fy = %g)",
                                     viewArgumentName("cameraMatrix", shared, view).c_str(), E(0, 0), E(1, 1)));
    return E;
}

//! The distortion coefficients as a 1xK CV_64F row; empty when there are none or all are zero.
Mat readDistortion(const Mat& m, bool shared, int view)
{
    if (m.empty())
        return Mat();
    const int n = (int)m.total() * m.channels();
    if (!(n == 4 || n == 5 || n == 8 || n == 12 || n == 14) || (m.depth() != CV_32F && m.depth() != CV_64F) ||
        (m.rows != 1 && m.cols != 1))
        CV_Error_(Error::StsBadArg, ("%s must be a vector of 4, 5, 8, 12 or 14 distortion coefficients, CV_32F or CV_64F "
                                     "(got %d values)", viewArgumentName("distCoeffs", shared, view).c_str(), n));
    double values[14];
    if (!copyFinite(m, values))
        CV_Error_(Error::StsBadArg, ("%s contains NaN or Inf values", viewArgumentName("distCoeffs", shared, view).c_str()));
    bool allZero = true;
    for (int i = 0; i < n; ++i)
        allZero &= values[i] == 0;
    return allZero ? Mat() : Mat(1, n, CV_64F, values).clone();
}

} // namespace

Eigen::Vector3d readTranslation(InputArray arr, const char* name, bool nonZero)
{
    const Mat m = arr.getMat();
    if (m.empty() || !(m.depth() == CV_32F || m.depth() == CV_64F) || m.total() * m.channels() != 3 || m.dims > 2)
        CV_Error_(Error::StsBadArg, ("%s must be a 3-element translation vector, CV_32F or CV_64F", name));
    Eigen::Vector3d e;
    copyFiniteOrThrow(m, e.data(), name);
    if (nonZero && !(e.norm() > 0))
        CV_Error_(Error::StsBadArg, ("%s must be non-zero: the baseline of views 1-2 fixes the metric scale", name));
    return e;
}

namespace {

//! Undistorts pixel points in place (no-op without distortion).
void undistortPixels(std::vector<Eigen::Vector2d>& pixels, const Eigen::Matrix3d& K, const Mat& dist)
{
    if (dist.empty() || pixels.empty())
        return;
    Mat Kcv(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            Kcv.at<double>(r, c) = K(r, c);
    // The vector's storage is N packed (x, y) pairs: a 2-channel header over it, no copy.
    const Mat in((int)pixels.size(), 1, CV_64FC2, pixels[0].data());
    Mat out;
    // Many more iterations than the default 5: the solver is exact on exact data and should stay so.
    undistortPoints(in, out, Kcv, dist, noArray(), Kcv, TermCriteria(TermCriteria::COUNT | TermCriteria::EPS, 100, 1e-15));
    CV_Assert(out.isContinuous() && out.type() == CV_64FC2 && (int)out.total() == (int)pixels.size());
    std::copy(out.ptr<double>(), out.ptr<double>() + 2 * pixels.size(), pixels[0].data());
}

Eigen::Vector3d normalizedLine(const Eigen::Vector3d& l)
{
    return l / l.head<2>().norm();
}

//! Calibrated lines of one view; @p pixelEnds holds the segments' end points (width 4, undistorted
//! here) or receives two points on each homogeneous line (width 3).
void convertLines(const std::vector<double>& homogeneous, int width, int count, const Intrinsics& camera, const Eigen::Matrix3d& K,
                  const Mat& dist, const char* name, std::vector<Eigen::Vector3d>& calibrated,
                  std::vector<Eigen::Vector2d>& pixelEnds)
{
    calibrated.resize(count);
    pixelEnds.resize(2 * count);
    if (width == 4)
    {
        undistortPixels(pixelEnds, K, dist);
        for (int i = 0; i < count; ++i)
        {
            const Eigen::Vector2d& a = pixelEnds[2 * i];
            const Eigen::Vector2d& b = pixelEnds[2 * i + 1];
            if (!((a - b).norm() > 1e-6))
                CV_Error_(Error::StsBadArg, ("%s: segment %d has zero length", name, i));
            calibrated[i] = normalizedLine(camera.calibrate(a).homogeneous().cross(camera.calibrate(b).homogeneous()));
        }
        return;
    }
    const Eigen::Vector2d principal(K(0, 2), K(1, 2));
    for (int i = 0; i < count; ++i)
    {
        const Eigen::Vector3d l(homogeneous[3 * i], homogeneous[3 * i + 1], homogeneous[3 * i + 2]);
        const double n = l.head<2>().norm();
        if (!(n > 0))
            CV_Error_(Error::StsBadArg, ("%s: line %d has a = b = 0, which is not a line", name, i));
        const Eigen::Vector3d lp = l / n;
        const Eigen::Vector2d foot = principal - (lp.head<2>().dot(principal) + lp(2)) * lp.head<2>();
        const Eigen::Vector2d dir(-lp(1), lp(0));
        pixelEnds[2 * i] = foot - kHomogeneousLineHalfLength * dir;
        pixelEnds[2 * i + 1] = foot + kHomogeneousLineHalfLength * dir;
        calibrated[i] = normalizedLine(K.transpose() * lp);
    }
}

} // namespace

Eigen::Matrix3d readRotation(InputArray arr, const char* name)
{
    const Mat m = arr.getMat();
    if (m.empty() || !(m.depth() == CV_32F || m.depth() == CV_64F) || m.dims > 2 ||
        !((m.total() == 9 && m.channels() == 1) || m.total() * m.channels() == 3))
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 rotation matrix or a 3-element Rodrigues vector, CV_32F or CV_64F", name));
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> E;
    copyFiniteOrThrow(m, E.data(), name);
    if (m.total() * m.channels() == 3)
    {
        const Mat rvec(3, 1, CV_64F, E.data());
        Mat rmat;
        Rodrigues(rvec.clone(), rmat);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                E(r, c) = rmat.at<double>(r, c);
    }
    const double tolerance = m.depth() == CV_32F ? 1e-4 : 1e-6;
    const double orthogonality = (E.transpose() * E - Eigen::Matrix3d::Identity()).norm();
    if (!(orthogonality < tolerance) || E.determinant() < 0)
        CV_Error_(Error::StsBadArg, ("%s is not a rotation: |R^T R - I| = %g, det = %g", name, orthogonality, E.determinant()));
    // Remove rounding so that later algebra sees an exact rotation (det > 0 was checked).
    return nearestRotation(E);
}

ViewSet readThreeViewInput(InputArray points1, InputArray points2, InputArray points3,
                           InputArray lines1, InputArray lines2, InputArray lines3,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, int minFeatures)
{
    ViewSet set;
    set.views.resize(3);
    View* pixels = set.views.data();
    readPoints(points1, "points1", pixels[0].points);
    readPoints(points2, "points2", pixels[1].points);
    readPoints(points3, "points3", pixels[2].points);
    std::vector<double> L[3]; // homogeneous lines only; segments go straight to the line ends
    int lineCount[3];
    const int lineWidth[3] = { readLines(lines1, "lines1", pixels[0].lineEnds, L[0], lineCount[0]),
                               readLines(lines2, "lines2", pixels[1].lineEnds, L[1], lineCount[1]),
                               readLines(lines3, "lines3", pixels[2].lineEnds, L[2], lineCount[2]) };
    const int numPoints = (int)pixels[0].points.size();
    for (int v = 1; v < 3; ++v)
    {
        if ((int)pixels[v].points.size() != numPoints)
            CV_Error_(Error::StsBadSize, ("points%d has %d points but points1 has %d: every view needs the same points",
                                          v + 1, (int)pixels[v].points.size(), numPoints));
        if (lineCount[v] != lineCount[0])
            CV_Error_(Error::StsBadSize, ("lines%d has %d lines but lines1 has %d: every view needs the same lines",
                                          v + 1, lineCount[v], lineCount[0]));
        if (lineCount[v] > 0 && lineWidth[v] != lineWidth[0])
            CV_Error_(Error::StsBadArg, ("lines%d are %s but lines1 are %s: use one kind in all views", v + 1,
                                         lineWidth[v] == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)",
                                         lineWidth[0] == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)"));
    }
    if (numPoints + lineCount[0] < minFeatures)
        CV_Error_(Error::StsBadArg, ("at least %d features (points + lines) are required, got %d points and %d lines",
                                     minFeatures, numPoints, lineCount[0]));

    const PerViewArrays Ks = readPerView(cameraMatrix, "cameraMatrix");
    if (Ks.count == 0)
        CV_Error(Error::StsBadArg, "cameraMatrix must be one 3x3 matrix or a vector of three");
    const PerViewArrays Ds = readPerView(distCoeffs, "distCoeffs");

    set.numPoints = numPoints;
    set.numLines = lineCount[0];
    set.views[ViewSet::kView2].pose.R = readRotation(R12, "R12");
    set.views[ViewSet::kView2].pose.t = readTranslation(t12, "t12", true);
    set.views[ViewSet::kView3].estimated = true; // mounted at the identity: it is the estimated camera

    static const char* lineNames[3] = { "lines1", "lines2", "lines3" };
    for (int v = 0; v < 3; ++v)
    {
        const Eigen::Matrix3d K = readCameraMatrix(Ks.forView(v), Ks.shared(), v);
        const Mat dist = Ds.count == 0 ? Mat() : readDistortion(Ds.forView(v), Ds.shared(), v);
        if (!dist.empty() && lineCount[v] > 0 && lineWidth[v] == 3)
            CV_Error_(Error::StsBadArg, ("%s are homogeneous lines (Mx3), which cannot be undistorted: "
                                         "pass segments (Mx4) or empty %s", lineNames[v],
                                         viewArgumentName("distCoeffs", Ds.shared(), v).c_str()));
        View& view = pixels[v];
        view.camera = Intrinsics(K);
        undistortPixels(view.points, K, dist);
        view.calibratedPoints.resize(numPoints);
        for (int i = 0; i < numPoints; ++i)
            view.calibratedPoints[i] = view.camera.calibrate(view.points[i]);
        convertLines(L[v], lineWidth[v], lineCount[v], view.camera, K, dist, lineNames[v], view.calibratedLines,
                     view.lineEnds);
    }
    return set;
}

} // namespace detail
} // namespace tripose
} // namespace cv
