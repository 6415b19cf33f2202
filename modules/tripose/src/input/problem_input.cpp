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

/** Marks the rows of @p values (@p width values each) that are entirely NaN as not seen (0 in
@p seen, the row set to @p placeholder) and rejects any other non-finite value. @p seen is left
empty when every row is seen.
*/
void readMissingRows(double* values, int rows, int width, const double* placeholder, const char* name,
                     const char* what, std::vector<unsigned char>& seen)
{
    seen.assign(rows, 1);
    bool anyMissing = false;
    for (int r = 0; r < rows; ++r)
    {
        double* row = values + (size_t)r * width;
        int nan = 0, finite = 0;
        for (int c = 0; c < width; ++c)
        {
            nan += std::isnan(row[c]) ? 1 : 0;
            finite += std::isfinite(row[c]) ? 1 : 0;
        }
        if (finite == width)
            continue;
        if (nan != width)
            CV_Error_(Error::StsBadArg, ("%s: %s %d has NaN or Inf values; mark a %s that this view does not see "
                                         "with NaN in all its values", name, what, r, what));
        seen[r] = 0;
        anyMissing = true;
        std::copy(placeholder, placeholder + width, row);
    }
    if (!anyMissing)
        seen.clear();
}

/** Nx2 points (row-major x y); an empty array means no points. With @p seen, a row of two NaN is a
point the view does not see (readMissingRows()); without, any NaN or Inf is an error.
*/
void readPoints(InputArray arr, const char* name, std::vector<Eigen::Vector2d>& out,
                std::vector<unsigned char>* seen = nullptr)
{
    out.clear();
    if (seen)
        seen->clear();
    if (arr.empty())
        return;
    const Mat m = arr.getMat();
    const int n = m.checkVector(2);
    if (n < 0 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name, m.rows, m.cols, m.channels(), m.depth()));
    out.resize(n);
    if (n == 0)
        return;
    if (!seen)
    {
        copyFiniteOrThrow(m, out[0].data(), name); // Eigen::Vector2d is two packed doubles
        return;
    }
    if (!copyFinite(m, out[0].data()))
    {
        const double placeholder[2] = { 0, 0 };
        readMissingRows(out[0].data(), n, 2, placeholder, name, "point", *seen);
    }
}

/** Mx4 segments (into @p ends, two points per segment: the layout is the same, x0 y0 x1 y1) or
Mx3 homogeneous lines (row-major into @p homogeneous); returns the width (4 or 3) and sets
@p count. An empty array means no lines (width 4). With @p seen, a row of NaN is a line the view
does not see (readMissingRows()).
*/
int readLines(InputArray arr, const char* name, std::vector<Eigen::Vector2d>& ends, std::vector<double>& homogeneous,
              int& count, std::vector<unsigned char>* seen = nullptr)
{
    ends.clear();
    homogeneous.clear();
    count = 0;
    if (seen)
        seen->clear();
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
    double* values;
    if (width == 4)
    {
        ends.resize(2 * (size_t)n);
        values = ends[0].data();
    }
    else
    {
        homogeneous.resize(3 * (size_t)n);
        values = homogeneous.data();
    }
    if (!seen)
        copyFiniteOrThrow(m, values, name);
    else if (!copyFinite(m, values))
    {
        // A placeholder that converts like any line: never read for a view that does not see it.
        const double placeholder[4] = { 0, 0, 1, 0 };
        const double homogeneousPlaceholder[3] = { 0, 1, 0 };
        readMissingRows(values, n, width, width == 4 ? placeholder : homogeneousPlaceholder, name, "line", *seen);
    }
    return width;
}

//! The arrays of a per-view argument: none, one shared by every view, or one per view. Element
//! headers are taken one by one (getMat(i)) into a fixed array for the usual few views: a vector of
//! headers would cost an allocation per call. Registration against many known views uses @p extra.
struct PerViewArrays
{
    static const int kFixedViews = 4;
    Mat mats[kFixedViews];
    std::vector<Mat> extra; //!< Views kFixedViews and on.
    int count = 0;

    const Mat& forView(int v) const
    {
        const int i = count == 1 ? 0 : v;
        return i < kFixedViews ? mats[i] : extra[i - kFixedViews];
    }
    bool shared() const { return count == 1; }
};

std::string viewCount(int n)
{
    static const char* const counts[] = { "zero", "one", "two", "three", "four" };
    return n <= 4 ? std::string(counts[n]) : format("%d", n);
}

PerViewArrays readPerView(InputArrayOfArrays arr, const char* name, int numViews)
{
    PerViewArrays out;
    if (arr.empty())
        return out;
    if (arr.isMatVector() || arr.isUMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR)
    {
        const int n = (int)arr.total();
        if (n != 1 && n != numViews)
            CV_Error_(Error::StsBadArg, ("%s must be one array shared by the %s views or a vector of %s (got %d)",
                                         name, viewCount(numViews).c_str(), viewCount(numViews).c_str(), n));
        for (int i = 0; i < n; ++i)
        {
            if (i < PerViewArrays::kFixedViews)
                out.mats[i] = arr.getMat(i);
            else
                out.extra.push_back(arr.getMat(i));
        }
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
                  const Mat& dist, const char* name, const std::vector<unsigned char>& seen,
                  std::vector<Eigen::Vector3d>& calibrated, std::vector<Eigen::Vector2d>& pixelEnds)
{
    calibrated.resize(count);
    pixelEnds.resize(2 * count);
    if (width == 4)
    {
        undistortPixels(pixelEnds, K, dist);
        for (int i = 0; i < count; ++i)
        {
            if (!seen.empty() && !seen[i])
                continue; // the placeholder converts to a line, but nothing reads it
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

namespace {

//! The observation arguments of one view.
struct ViewArguments
{
    const _InputArray* points;
    const _InputArray* lines;
    const char* pointsName;
    const char* linesName;
    bool mayMiss; //!< Rows of NaN mark features this view does not see (else every feature is seen).
};

/** Reads, validates, undistorts and calibrates the observations of @p numViews views into
@p set.views (poses left to the caller). Every view holds the same number of points and of lines
(the first view's); a view that may miss features may also pass an empty array: it sees none.
*/
void readViews(const ViewArguments* args, int numViews, InputArrayOfArrays cameraMatrix,
               InputArrayOfArrays distCoeffs, ViewSet& set)
{
    set.views.resize(numViews);
    std::vector<std::vector<double>> homogeneous(numViews); // homogeneous lines only; segments go straight to the line ends
    std::vector<int> lineCount(numViews), lineWidth(numViews);
    for (int v = 0; v < numViews; ++v)
    {
        View& view = set.views[v];
        readPoints(*args[v].points, args[v].pointsName, view.points, args[v].mayMiss ? &view.pointSeen : nullptr);
        lineWidth[v] = readLines(*args[v].lines, args[v].linesName, view.lineEnds, homogeneous[v], lineCount[v],
                                 args[v].mayMiss ? &view.lineSeen : nullptr);
    }
    // The counts come from the first view; where every view may miss features, from the first
    // view that gives any (an empty array is a view that sees none).
    int pointSource = 0, lineSource = 0;
    while (args[pointSource].mayMiss && set.views[pointSource].points.empty() && pointSource + 1 < numViews)
        ++pointSource;
    while (args[lineSource].mayMiss && lineCount[lineSource] == 0 && lineSource + 1 < numViews)
        ++lineSource;
    const int numPoints = (int)set.views[pointSource].points.size();
    const int numLines = lineCount[lineSource];
    for (int v = 0; v < numViews; ++v)
    {
        View& view = set.views[v];
        const int points = (int)view.points.size();
        if (args[v].mayMiss && points == 0 && numPoints > 0)
        {
            view.points.assign(numPoints, Eigen::Vector2d::Zero());
            view.pointSeen.assign(numPoints, 0);
        }
        else if (points != numPoints)
            CV_Error_(Error::StsBadSize, ("%s has %d points but %s has %d: every view needs the same points",
                                          args[v].pointsName, points, args[pointSource].pointsName, numPoints));
        if (args[v].mayMiss && lineCount[v] == 0 && numLines > 0)
        {
            lineCount[v] = numLines;
            lineWidth[v] = 4;
            view.lineEnds.assign(2 * (size_t)numLines, Eigen::Vector2d::Zero());
            for (int i = 0; i < numLines; ++i)
                view.lineEnds[2 * i + 1] = Eigen::Vector2d(1, 0);
            view.lineSeen.assign(numLines, 0);
            continue; // no lines given: nothing to compare the kind with
        }
        if (lineCount[v] != numLines)
            CV_Error_(Error::StsBadSize, ("%s has %d lines but %s has %d: every view needs the same lines",
                                          args[v].linesName, lineCount[v], args[lineSource].linesName, numLines));
        if (numLines > 0 && lineWidth[v] != lineWidth[lineSource])
            CV_Error_(Error::StsBadArg, ("%s are %s but %s are %s: use one kind in all views", args[v].linesName,
                                         lineWidth[v] == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)",
                                         args[lineSource].linesName,
                                         lineWidth[lineSource] == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)"));
    }
    set.numPoints = numPoints;
    set.numLines = numLines;

    const PerViewArrays Ks = readPerView(cameraMatrix, "cameraMatrix", numViews);
    if (Ks.count == 0)
        CV_Error_(Error::StsBadArg, ("cameraMatrix must be one 3x3 matrix or a vector of %d", numViews));
    const PerViewArrays Ds = readPerView(distCoeffs, "distCoeffs", numViews);

    for (int v = 0; v < numViews; ++v)
    {
        const Eigen::Matrix3d K = readCameraMatrix(Ks.forView(v), Ks.shared(), v);
        const Mat dist = Ds.count == 0 ? Mat() : readDistortion(Ds.forView(v), Ds.shared(), v);
        if (!dist.empty() && lineCount[v] > 0 && lineWidth[v] == 3)
            CV_Error_(Error::StsBadArg, ("%s are homogeneous lines (Mx3), which cannot be undistorted: "
                                         "pass segments (Mx4) or empty %s", args[v].linesName,
                                         viewArgumentName("distCoeffs", Ds.shared(), v).c_str()));
        View& view = set.views[v];
        view.camera = Intrinsics(K);
        undistortPixels(view.points, K, dist);
        view.calibratedPoints.resize(numPoints);
        for (int i = 0; i < numPoints; ++i)
            view.calibratedPoints[i] = view.camera.calibrate(view.points[i]);
        convertLines(homogeneous[v], lineWidth[v], lineCount[v], view.camera, K, dist, args[v].linesName,
                     view.lineSeen, view.calibratedLines, view.lineEnds);
    }
}

void requireFeatures(int numPoints, int numLines, int minFeatures)
{
    if (numPoints + numLines < minFeatures)
        CV_Error_(Error::StsBadArg, ("at least %d features (points + lines) are required, got %d points and %d lines",
                                     minFeatures, numPoints, numLines));
}

} // namespace

ViewSet readThreeViewInput(InputArray points1, InputArray points2, InputArray points3,
                           InputArray lines1, InputArray lines2, InputArray lines3,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, int minFeatures)
{
    const ViewArguments args[3] = { { &points1, &lines1, "points1", "lines1", false },
                                    { &points2, &lines2, "points2", "lines2", false },
                                    { &points3, &lines3, "points3", "lines3", false } };
    ViewSet set;
    readViews(args, 3, cameraMatrix, distCoeffs, set);
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    set.views[ViewSet::kView2].pose.R = readRotation(R12, "R12");
    set.views[ViewSet::kView2].pose.t = readTranslation(t12, "t12", true);
    set.views[ViewSet::kView3].estimated = true; // mounted at the identity: it is the estimated camera
    return set;
}

ViewSet readStereoRigInput(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                           InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, int minFeatures)
{
    const ViewArguments args[4] = { { &points1, &lines1, "points1", "lines1", false },
                                    { &points2, &lines2, "points2", "lines2", false },
                                    { &points3, &lines3, "points3", "lines3", true },
                                    { &points4, &lines4, "points4", "lines4", true } };
    ViewSet set;
    readViews(args, 4, cameraMatrix, distCoeffs, set);
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    const View& left = set.views[ViewSet::kRigLeftB];
    const View& right = set.views[ViewSet::kRigRightB];
    for (int i = 0; i < set.numPoints; ++i)
        if (!left.seesPoint(i) && !right.seesPoint(i))
            CV_Error_(Error::StsBadArg, ("point %d is missing (NaN) in both points3 and points4: every feature must "
                                         "be seen in view 3 or view 4", i));
    for (int i = 0; i < set.numLines; ++i)
        if (!left.seesLine(i) && !right.seesLine(i))
            CV_Error_(Error::StsBadArg, ("line %d is missing (NaN) in both lines3 and lines4: every feature must "
                                         "be seen in view 3 or view 4", i));
    CameraPose rig;
    rig.R = readRotation(R12, "R12");
    rig.t = readTranslation(t12, "t12", true);
    set.views[ViewSet::kView2].pose = rig;
    set.views[ViewSet::kRigLeftB].estimated = true;  // the estimated camera itself
    set.views[ViewSet::kRigRightB].estimated = true; // mounted on it as the right camera on the left
    set.views[ViewSet::kRigRightB].pose = rig;
    return set;
}

namespace {

//! The arrays of a vector argument with one entry per view; @p layout says which views, for errors.
std::vector<Mat> readViewVector(InputArrayOfArrays arr, const char* name, int numViews, const char* what,
                                const char* layout)
{
    std::vector<Mat> out(numViews);
    if (arr.empty())
        return out; // every view sees none of this kind
    if (!(arr.isMatVector() || arr.isUMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR))
        CV_Error_(Error::StsBadArg, ("%s must be a vector of %s arrays, one per view: %s", name, what, layout));
    const int n = (int)arr.total();
    if (n != numViews)
        CV_Error_(Error::StsBadArg, ("%s must hold %d arrays (%s), got %d", name, numViews, layout, n));
    for (int i = 0; i < n; ++i)
        out[i] = arr.getMat(i);
    return out;
}

bool isArrayVector(InputArrayOfArrays arr)
{
    return arr.isMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR || arr.isUMatVector();
}

/** The observations of @p numViews views, each of which may miss features (NaN rows, empty arrays),
and the world poses Rs[k], ts[k] of the first Rs.total() of them (checked: at least two, as many
translations); @p posed names those views, @p layout the order of all views, in errors.
*/
ViewSet readPosedViews(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                       InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts, int unposedViews,
                       const char* posed, const char* layout)
{
    if (!isArrayVector(Rs) || Rs.total() < 2)
        CV_Error_(Error::StsBadArg, ("Rs must be a vector of at least two rotations, the world poses of the %s", posed));
    const int numPosed = (int)Rs.total();
    if (!isArrayVector(ts) || (int)ts.total() != numPosed)
        CV_Error_(Error::StsBadArg, ("ts must be a vector of %d translations, one per rotation in Rs", numPosed));
    const int numViews = numPosed + unposedViews;
    if (points.empty() && lines.empty())
        CV_Error(Error::StsBadArg, "points and lines are both empty: at least four features are required");

    const std::vector<Mat> pointMats = readViewVector(points, "points", numViews, "Nx2 point", layout);
    const std::vector<Mat> lineMats = readViewVector(lines, "lines", numViews, "Mx4 segment or Mx3 line", layout);
    std::vector<_InputArray> pointArrays, lineArrays;
    std::vector<std::string> pointNames(numViews), lineNames(numViews);
    std::vector<ViewArguments> args(numViews);
    pointArrays.reserve(numViews);
    lineArrays.reserve(numViews);
    for (int v = 0; v < numViews; ++v)
    {
        pointArrays.push_back(_InputArray(pointMats[v]));
        lineArrays.push_back(_InputArray(lineMats[v]));
        pointNames[v] = format("points[%d]", v);
        lineNames[v] = format("lines[%d]", v);
    }
    for (int v = 0; v < numViews; ++v)
    {
        ViewArguments a = { &pointArrays[v], &lineArrays[v], pointNames[v].c_str(), lineNames[v].c_str(), true };
        args[v] = a;
    }
    ViewSet set;
    readViews(args.data(), numViews, cameraMatrix, distCoeffs, set);
    for (int k = 0; k < numPosed; ++k)
    {
        const std::string rName = format("Rs[%d]", k), tName = format("ts[%d]", k);
        set.views[k].pose.R = readRotation(Rs.getMat(k), rName.c_str());
        set.views[k].pose.t = readTranslation(ts.getMat(k), tName.c_str(), false);
    }
    return set;
}

//! True when the known views of @p set do not all have one centre (up to rounding, relative to
//! their distance from the origin): then they fix the metric scale.
bool knownCentresDiffer(const ViewSet& set)
{
    const CameraPose* first = nullptr;
    double spread = 0, size = 0;
    for (const View& view : set.views)
    {
        if (view.estimated)
            continue;
        if (!first)
            first = &view.pose;
        spread = std::max(spread, (view.pose.centre() - first->centre()).norm());
        size = std::max(size, view.pose.centre().norm());
    }
    return first && spread > 1e-12 * size;
}

//! Number of the views of @p set in [begin, end) that see feature @p i of one kind.
int viewsSeeing(const ViewSet& set, bool point, int i, int begin, int end)
{
    int seen = 0;
    for (int k = begin; k < end; ++k)
        seen += (point ? set.views[k].seesPoint(i) : set.views[k].seesLine(i)) ? 1 : 0;
    return seen;
}

} // namespace

ViewSet readMultiViewInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                           InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts, int minFeatures)
{
    const int numKnown = isArrayVector(Rs) ? (int)Rs.total() : 0;
    const std::string layout = format("the %d known views, then the new view", numKnown);
    ViewSet set = readPosedViews(points, lines, cameraMatrix, distCoeffs, Rs, ts, 1, "known views", layout.c_str());
    set.views[numKnown].estimated = true; // mounted at the identity: it is the estimated camera
    if (!knownCentresDiffer(set))
        CV_Error(Error::StsBadArg, "ts: every known view has the same centre: no baseline fixes the scale");

    const View& target = set.views[numKnown];
    for (int kind = 0; kind < 2; ++kind)
    {
        const bool point = kind == 0;
        for (int i = 0; i < (point ? set.numPoints : set.numLines); ++i)
        {
            if (!(point ? target.seesPoint(i) : target.seesLine(i)))
                CV_Error_(Error::StsBadArg, ("%s[%d] (the new view) does not see %s %d: every feature must be seen "
                                             "in the new view", point ? "points" : "lines", numKnown,
                                             point ? "point" : "line", i));
            const int seen = viewsSeeing(set, point, i, 0, numKnown);
            if (seen < 2)
                CV_Error_(Error::StsBadArg, ("%s %d is seen in %d known view(s) of %s: every feature must be seen in "
                                             "at least two known views", point ? "point" : "line", i, seen,
                                             point ? "points" : "lines"));
        }
    }
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    return set;
}

ViewSet readSeveralPosesInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                              InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                              InputArray fixedViews, std::vector<int>& poseOfView,
                              std::vector<CameraPose>& initialPoses)
{
    const int numViews = isArrayVector(Rs) ? (int)Rs.total() : 0;
    ViewSet set = readPosedViews(points, lines, cameraMatrix, distCoeffs, Rs, ts, 0, "views", "one per view");
    Mat fixed = fixedViews.getMat();
    if (fixed.empty() || (int)fixed.total() != numViews || fixed.channels() != 1 ||
        (fixed.depth() != CV_8U && fixed.depth() != CV_32S && fixed.depth() != CV_8S))
        CV_Error_(Error::StsBadArg, ("fixedViews must hold %d values (CV_8U, CV_8S or CV_32S), one per view: nonzero "
                                     "where the view's pose is fixed", numViews));
    fixed.reshape(1, numViews).convertTo(fixed, CV_32S);
    poseOfView.assign(numViews, -1);
    initialPoses.clear();
    int numFree = 0;
    for (int v = 0; v < numViews; ++v)
        if (fixed.at<int>(v) == 0)
        {
            initialPoses.push_back(set.views[v].pose);
            set.views[v].estimated = true; // a camera of its own: mounted at the identity on its pose
            set.views[v].pose = CameraPose();
            poseOfView[v] = numFree++;
        }
    if (numFree == 0)
        CV_Error(Error::StsBadArg, "fixedViews: every view is fixed: nothing to refine");
    if (numViews - numFree < 2 || !knownCentresDiffer(set))
        CV_Error(Error::StsBadArg, "fixedViews: at least two fixed views at distinct centres are required: they fix "
                                   "the world frame and the scale");
    for (int kind = 0; kind < 2; ++kind)
    {
        const bool point = kind == 0;
        for (int i = 0; i < (point ? set.numPoints : set.numLines); ++i)
        {
            const int seen = viewsSeeing(set, point, i, 0, numViews);
            if (seen < 2)
                CV_Error_(Error::StsBadArg, ("%s %d is seen in %d view(s) of %s: every feature must be seen in at "
                                             "least two views", point ? "point" : "line", i, seen,
                                             point ? "points" : "lines"));
        }
    }
    requireFeatures(set.numPoints, set.numLines, 1);
    return set;
}

} // namespace detail
} // namespace tripose
} // namespace cv
