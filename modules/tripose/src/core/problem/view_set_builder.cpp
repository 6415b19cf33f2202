// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "view_set_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "../geometry/distortion.hpp"
#include "../geometry/rotation.hpp"
#include "../support/error.hpp"

namespace tripose {

namespace {

//! Largest |R^T R - I| (Frobenius) of an accepted rotation: a matrix printed with 4-6 significant digits.
constexpr double kRotationTolerance = 1e-4;

bool allFinite(const std::vector<double>& values)
{
    for (double v : values)
        if (!std::isfinite(v))
            return false;
    return true;
}

void requireFinite(const ArgumentMatrix& m)
{
    if (!allFinite(m.values))
        fail(ErrorCode::BadArgument, "%s contains NaN or Inf values", m.name.c_str());
}

/** Marks the rows of @p values (@p width values each) that are entirely NaN as not seen (0 in
@p seen, the row set to @p placeholder) and rejects any other non-finite value. @p seen is left
empty when every row is seen.
*/
void readMissingRows(double* values, int rows, int width, const double* placeholder, const std::string& name,
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
            fail(ErrorCode::BadArgument, "%s: %s %d has NaN or Inf values; mark a %s that this view does not see "
                 "with NaN in all its values", name.c_str(), what, r, what);
        seen[r] = 0;
        anyMissing = true;
        std::copy(placeholder, placeholder + width, row);
    }
    if (!anyMissing)
        seen.clear();
}

/** Nx2 points; with @p seen, a row of two NaN is a point the view does not see (readMissingRows());
without, any NaN or Inf is an error.
*/
void readPoints(const ArgumentMatrix& m, std::vector<Eigen::Vector2d>& out, std::vector<unsigned char>* seen)
{
    out.clear();
    if (seen)
        seen->clear();
    if (m.empty())
        return;
    TRIPOSE_ASSERT(m.cols == 2 && (int)m.values.size() == m.size());
    out.resize(m.rows);
    std::copy(m.values.begin(), m.values.end(), out[0].data()); // Eigen::Vector2d is two packed doubles
    if (allFinite(m.values))
        return;
    if (!seen)
        requireFinite(m);
    const double placeholder[2] = { 0, 0 };
    readMissingRows(out[0].data(), m.rows, 2, placeholder, m.name, "point", *seen);
}

/** Mx4 segments (into @p ends, two points per segment: the layout is the same, x0 y0 x1 y1) or Mx3
homogeneous lines (row-major into @p homogeneous); returns the width (4 or 3) and sets @p count. An
empty matrix means no lines (width 4). With @p seen, a row of NaN is a line the view does not see.
*/
int readLines(const ArgumentMatrix& m, std::vector<Eigen::Vector2d>& ends, std::vector<double>& homogeneous,
              int& count, std::vector<unsigned char>* seen)
{
    ends.clear();
    homogeneous.clear();
    count = 0;
    if (seen)
        seen->clear();
    if (m.empty())
        return 4;
    const int width = m.cols;
    TRIPOSE_ASSERT((width == 4 || width == 3) && (int)m.values.size() == m.size());
    count = m.rows;
    double* values;
    if (width == 4)
    {
        ends.resize(2 * (size_t)count);
        values = ends[0].data();
    }
    else
    {
        homogeneous.resize(3 * (size_t)count);
        values = homogeneous.data();
    }
    std::copy(m.values.begin(), m.values.end(), values);
    if (allFinite(m.values))
        return width;
    if (!seen)
        requireFinite(m);
    // A placeholder that converts like any line: never read for a view that does not see it.
    const double placeholder[4] = { 0, 0, 1, 0 };
    const double homogeneousPlaceholder[3] = { 0, 1, 0 };
    readMissingRows(values, count, width, width == 4 ? placeholder : homogeneousPlaceholder, m.name, "line", *seen);
    return width;
}

std::string viewCount(int n)
{
    static const char* const counts[] = { "zero", "one", "two", "three", "four" };
    return n <= 4 ? std::string(counts[n]) : formatString("%d", n);
}

//! The argument of view @p view among @p perView (one shared by every view, or one per view).
const ArgumentMatrix& forView(const std::vector<ArgumentMatrix>& perView, int view)
{
    return perView.size() == 1 ? perView[0] : perView[view];
}

void requirePerViewCount(const std::vector<ArgumentMatrix>& perView, const std::string& name, int numViews)
{
    const int n = (int)perView.size();
    if (n > 1 && n != numViews)
        fail(ErrorCode::BadArgument, "%s must be one array shared by the %s views or a vector of %s (got %d)",
             name.c_str(), viewCount(numViews).c_str(), viewCount(numViews).c_str(), n);
}

Eigen::Matrix3d readCameraMatrix(const ArgumentMatrix& m)
{
    if (m.rows * m.cols != 9)
        fail(ErrorCode::BadArgument, "%s must be a 3x3 matrix", m.name.c_str());
    requireFinite(m);
    Eigen::Matrix3d K = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.values.data());
    if (K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) == 0 || K(1, 0) != 0)
        fail(ErrorCode::BadArgument, "%s must be upper triangular [fx s cx; 0 fy cy; 0 0 1]", m.name.c_str());
    K /= K(2, 2);
    if (!(K(0, 0) > 0 && K(1, 1) > 0))
        fail(ErrorCode::BadArgument, "%s must have positive focal lengths (fx = %g, fy = %g)", m.name.c_str(), K(0, 0),
             K(1, 1));
    return K;
}

//! The distortion coefficients; false when there are none or all are zero.
bool readDistortion(const ArgumentMatrix& m, Distortion& distortion)
{
    if (m.empty())
        return false;
    const int n = m.size();
    if (!(n == 4 || n == 5 || n == 8 || n == 12 || n == 14) || (m.rows != 1 && m.cols != 1))
        fail(ErrorCode::BadArgument, "%s must be a vector of 4, 5, 8, 12 or 14 distortion coefficients (got %d values)",
             m.name.c_str(), n);
    requireFinite(m);
    bool allZero = true;
    distortion.k.fill(0.0);
    for (int i = 0; i < n; ++i)
    {
        distortion.k[i] = m.values[i];
        allZero &= m.values[i] == 0;
    }
    return !allZero;
}

Eigen::Vector3d normalizedLine(const Eigen::Vector3d& l)
{
    return l / l.head<2>().norm();
}

//! Calibrated lines of one view; @p pixelEnds holds the segments' end points (width 4, undistorted
//! here) or receives two points on each homogeneous line (width 3).
void convertLines(const std::vector<double>& homogeneous, int width, int count, const Intrinsics& camera,
                  const Eigen::Matrix3d& K, const Distortion* distortion, const std::string& name,
                  const std::vector<unsigned char>& seen, std::vector<Eigen::Vector3d>& calibrated,
                  std::vector<Eigen::Vector2d>& pixelEnds)
{
    calibrated.resize(count);
    pixelEnds.resize(2 * count);
    if (width == 4)
    {
        if (distortion && !pixelEnds.empty())
            distortion->undistortPixels(pixelEnds, K);
        for (int i = 0; i < count; ++i)
        {
            if (!seen.empty() && !seen[i])
                continue; // the placeholder converts to a line, but nothing reads it
            const Eigen::Vector2d& a = pixelEnds[2 * i];
            const Eigen::Vector2d& b = pixelEnds[2 * i + 1];
            if (!((a - b).norm() > 1e-6))
                fail(ErrorCode::BadArgument, "%s: segment %d has zero length", name.c_str(), i);
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
            fail(ErrorCode::BadArgument, "%s: line %d has a = b = 0, which is not a line", name.c_str(), i);
        const Eigen::Vector3d lp = l / n;
        const Eigen::Vector2d foot = principal - (lp.head<2>().dot(principal) + lp(2)) * lp.head<2>();
        const Eigen::Vector2d dir(-lp(1), lp(0));
        pixelEnds[2 * i] = foot - kHomogeneousLineHalfLength * dir;
        pixelEnds[2 * i + 1] = foot + kHomogeneousLineHalfLength * dir;
        calibrated[i] = normalizedLine(K.transpose() * lp);
    }
}

const char* lineKind(int width)
{
    return width == 4 ? "segments (Mx4)" : "homogeneous lines (Mx3)";
}

/** Validates, undistorts and calibrates the observations of every view into @p set.views (poses
left to the caller). Every view holds the same number of points and of lines (the first view's); a
view that may miss features may also pass an empty matrix: it sees none.
*/
void readViews(const ProblemArguments& arguments, ViewSet& set)
{
    const std::vector<ViewArguments>& args = arguments.views;
    const int numViews = (int)args.size();
    set.views.resize(numViews);
    std::vector<std::vector<double>> homogeneous(numViews); // homogeneous lines only; segments go straight to the line ends
    std::vector<int> lineCount(numViews), lineWidth(numViews);
    for (int v = 0; v < numViews; ++v)
    {
        View& view = set.views[v];
        readPoints(args[v].points, view.points, args[v].mayMiss ? &view.pointSeen : nullptr);
        lineWidth[v] = readLines(args[v].lines, view.lineEnds, homogeneous[v], lineCount[v],
                                 args[v].mayMiss ? &view.lineSeen : nullptr);
    }
    // The counts come from the first view; where every view may miss features, from the first
    // view that gives any (an empty matrix is a view that sees none).
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
            fail(ErrorCode::BadSize, "%s has %d points but %s has %d: every view needs the same points",
                 args[v].points.name.c_str(), points, args[pointSource].points.name.c_str(), numPoints);
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
            fail(ErrorCode::BadSize, "%s has %d lines but %s has %d: every view needs the same lines",
                 args[v].lines.name.c_str(), lineCount[v], args[lineSource].lines.name.c_str(), numLines);
        if (numLines > 0 && lineWidth[v] != lineWidth[lineSource])
            fail(ErrorCode::BadArgument, "%s are %s but %s are %s: use one kind in all views", args[v].lines.name.c_str(),
                 lineKind(lineWidth[v]), args[lineSource].lines.name.c_str(), lineKind(lineWidth[lineSource]));
    }
    set.numPoints = numPoints;
    set.numLines = numLines;

    if (arguments.cameraMatrices.empty())
        fail(ErrorCode::BadArgument, "%s must be one 3x3 matrix or a vector of %d", arguments.cameraMatrixName.c_str(),
             numViews);
    requirePerViewCount(arguments.cameraMatrices, arguments.cameraMatrixName, numViews);
    requirePerViewCount(arguments.distortions, arguments.distortionName, numViews);

    for (int v = 0; v < numViews; ++v)
    {
        const Eigen::Matrix3d K = readCameraMatrix(forView(arguments.cameraMatrices, v));
        Distortion distortion;
        const bool distorted = !arguments.distortions.empty() &&
                               readDistortion(forView(arguments.distortions, v), distortion);
        if (distorted && lineCount[v] > 0 && lineWidth[v] == 3)
            fail(ErrorCode::BadArgument, "%s are homogeneous lines (Mx3), which cannot be undistorted: "
                 "pass segments (Mx4) or empty %s", args[v].lines.name.c_str(),
                 forView(arguments.distortions, v).name.c_str());
        View& view = set.views[v];
        view.camera = Intrinsics(K);
        if (distorted && !view.points.empty())
            distortion.undistortPixels(view.points, K);
        view.calibratedPoints.resize(numPoints);
        for (int i = 0; i < numPoints; ++i)
            view.calibratedPoints[i] = view.camera.calibrate(view.points[i]);
        convertLines(homogeneous[v], lineWidth[v], lineCount[v], view.camera, K, distorted ? &distortion : nullptr,
                     args[v].lines.name, view.lineSeen, view.calibratedLines, view.lineEnds);
    }
}

void requireFeatures(int numPoints, int numLines, int minFeatures)
{
    if (numPoints + numLines < minFeatures)
        fail(ErrorCode::BadArgument, "at least %d features (points + lines) are required, got %d points and %d lines",
             minFeatures, numPoints, numLines);
}

/** The observations of every view, each of which may miss features, and the world poses Rs[k],
ts[k] of the first Rs.size() of them (checked: at least two, as many translations); @p posed names
those views in errors.
*/
ViewSet readPosedViews(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                       const std::vector<ArgumentMatrix>& ts, const char* posed)
{
    if (Rs.size() < 2)
        fail(ErrorCode::BadArgument, "Rs must be a vector of at least two rotations, the world poses of the %s", posed);
    const int numPosed = (int)Rs.size();
    if ((int)ts.size() != numPosed)
        fail(ErrorCode::BadArgument, "ts must be a vector of %d translations, one per rotation in Rs", numPosed);
    ViewSet set;
    readViews(arguments, set);
    for (int k = 0; k < numPosed; ++k)
    {
        set.views[k].pose.R = readRotation(Rs[k]);
        set.views[k].pose.t = readTranslation(ts[k], false);
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

Eigen::Vector3d readTranslation(const ArgumentMatrix& m, bool nonZero)
{
    if (m.size() != 3)
        fail(ErrorCode::BadArgument, "%s must be a 3-element translation vector", m.name.c_str());
    requireFinite(m);
    const Eigen::Vector3d t(m.values[0], m.values[1], m.values[2]);
    if (nonZero && !(t.norm() > 0))
        fail(ErrorCode::BadArgument, "%s must be non-zero: the baseline of views 1-2 fixes the metric scale",
             m.name.c_str());
    return t;
}

Eigen::Matrix3d readRotation(const ArgumentMatrix& m)
{
    if (m.size() != 9 && m.size() != 3)
        fail(ErrorCode::BadArgument, "%s must be a 3x3 rotation matrix or a 3-element rotation vector", m.name.c_str());
    requireFinite(m);
    Eigen::Matrix3d R;
    if (m.size() == 3)
        R = rotationFromVector(Eigen::Vector3d(m.values[0], m.values[1], m.values[2]));
    else
        R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.values.data());
    const double orthogonality = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
    if (!(orthogonality <= kRotationTolerance) || !(R.determinant() > 0))
        fail(ErrorCode::BadArgument, "%s is not a rotation: |R^T R - I| = %g, det = %g", m.name.c_str(), orthogonality,
             R.determinant());
    // The nearest rotation (the SVD's U V^T; det > 0 was checked) replaces the rounded one.
    return nearestRotation(R);
}

ViewSet buildThreeViewSet(const ProblemArguments& arguments, const ArgumentMatrix& R12, const ArgumentMatrix& t12,
                          int minFeatures)
{
    TRIPOSE_ASSERT(arguments.views.size() == 3);
    ViewSet set;
    readViews(arguments, set);
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    set.views[ViewSet::kView2].pose.R = readRotation(R12);
    set.views[ViewSet::kView2].pose.t = readTranslation(t12, true);
    set.views[ViewSet::kView3].estimated = true; // mounted at the identity: it is the estimated camera
    return set;
}

ViewSet buildStereoRigSet(const ProblemArguments& arguments, const ArgumentMatrix& R12, const ArgumentMatrix& t12,
                          int minFeatures)
{
    TRIPOSE_ASSERT(arguments.views.size() == 4);
    ViewSet set;
    readViews(arguments, set);
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    const View& left = set.views[ViewSet::kRigLeftB];
    const View& right = set.views[ViewSet::kRigRightB];
    const ViewArguments& left3 = arguments.views[ViewSet::kRigLeftB];
    const ViewArguments& right4 = arguments.views[ViewSet::kRigRightB];
    for (int i = 0; i < set.numPoints; ++i)
        if (!left.seesPoint(i) && !right.seesPoint(i))
            fail(ErrorCode::BadArgument, "point %d is missing (NaN) in both %s and %s: every feature must be seen in "
                 "view 3 or view 4", i, left3.points.name.c_str(), right4.points.name.c_str());
    for (int i = 0; i < set.numLines; ++i)
        if (!left.seesLine(i) && !right.seesLine(i))
            fail(ErrorCode::BadArgument, "line %d is missing (NaN) in both %s and %s: every feature must be seen in "
                 "view 3 or view 4", i, left3.lines.name.c_str(), right4.lines.name.c_str());
    CameraPose rig;
    rig.R = readRotation(R12);
    rig.t = readTranslation(t12, true);
    set.views[ViewSet::kView2].pose = rig;
    set.views[ViewSet::kRigLeftB].estimated = true;  // the estimated camera itself
    set.views[ViewSet::kRigRightB].estimated = true; // mounted on it as the right camera on the left
    set.views[ViewSet::kRigRightB].pose = rig;
    return set;
}

ViewSet buildMultiViewSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                          const std::vector<ArgumentMatrix>& ts, int minFeatures)
{
    const int numKnown = (int)Rs.size();
    ViewSet set = readPosedViews(arguments, Rs, ts, "known views");
    TRIPOSE_ASSERT((int)set.views.size() == numKnown + 1);
    set.views[numKnown].estimated = true; // mounted at the identity: it is the estimated camera
    if (!knownCentresDiffer(set))
        fail(ErrorCode::BadArgument, "ts: every known view has the same centre: no baseline fixes the scale");

    const View& target = set.views[numKnown];
    for (int kind = 0; kind < 2; ++kind)
    {
        const bool point = kind == 0;
        const char* name = point ? "points" : "lines";
        for (int i = 0; i < (point ? set.numPoints : set.numLines); ++i)
        {
            if (!(point ? target.seesPoint(i) : target.seesLine(i)))
                fail(ErrorCode::BadArgument, "%s[%d] (the new view) does not see %s %d: every feature must be seen "
                     "in the new view", name, numKnown, point ? "point" : "line", i);
            const int seen = viewsSeeing(set, point, i, 0, numKnown);
            if (seen < 2)
                fail(ErrorCode::BadArgument, "%s %d is seen in %d known view(s) of %s: every feature must be seen in "
                     "at least two known views", point ? "point" : "line", i, seen, name);
        }
    }
    requireFeatures(set.numPoints, set.numLines, minFeatures);
    return set;
}

ViewSet buildPosedViewSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                          const std::vector<ArgumentMatrix>& ts)
{
    ViewSet set = readPosedViews(arguments, Rs, ts, "views");
    TRIPOSE_ASSERT(set.views.size() == Rs.size());
    requireFeatures(set.numPoints, set.numLines, 1);
    return set;
}

ViewSet buildSeveralPosesSet(const ProblemArguments& arguments, const std::vector<ArgumentMatrix>& Rs,
                             const std::vector<ArgumentMatrix>& ts, const std::vector<int>& fixedViews,
                             const char* fixedViewsName, std::vector<int>& poseOfView,
                             std::vector<CameraPose>& initialPoses)
{
    const int numViews = (int)Rs.size();
    ViewSet set = readPosedViews(arguments, Rs, ts, "views");
    if ((int)fixedViews.size() != numViews)
        fail(ErrorCode::BadArgument, "%s must hold %d values, one per view: nonzero where the view's pose is fixed",
             fixedViewsName, numViews);
    poseOfView.assign(numViews, -1);
    initialPoses.clear();
    int numFree = 0;
    for (int v = 0; v < numViews; ++v)
        if (fixedViews[v] == 0)
        {
            initialPoses.push_back(set.views[v].pose);
            set.views[v].estimated = true; // a camera of its own: mounted at the identity on its pose
            set.views[v].pose = CameraPose();
            poseOfView[v] = numFree++;
        }
    if (numFree == 0)
        fail(ErrorCode::BadArgument, "%s: every view is fixed: nothing to refine", fixedViewsName);
    if (numViews - numFree < 2 || !knownCentresDiffer(set))
        fail(ErrorCode::BadArgument, "%s: at least two fixed views at distinct centres are required: they fix "
             "the world frame and the scale", fixedViewsName);
    for (int kind = 0; kind < 2; ++kind)
    {
        const bool point = kind == 0;
        const char* name = point ? "points" : "lines";
        for (int i = 0; i < (point ? set.numPoints : set.numLines); ++i)
        {
            const int seen = viewsSeeing(set, point, i, 0, numViews);
            if (seen < 2)
                fail(ErrorCode::BadArgument, "%s %d is seen in %d view(s) of %s: every feature must be seen in at "
                     "least two views", point ? "point" : "line", i, seen, name);
        }
    }
    requireFeatures(set.numPoints, set.numLines, 1);
    return set;
}

} // namespace tripose
