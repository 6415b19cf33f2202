// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "../core/problem/view_set_builder.hpp"
#include "argument_reading.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

bool isFloatingPoint(const Mat& m)
{
    return m.depth() == CV_32F || m.depth() == CV_64F;
}

/** The values of a CV_32F/CV_64F array of at most two dimensions in row-major order (all channels
of an element in turn), as @p rows x @p cols. Direct row pointers: a convertTo() into a new Mat
costs more than the solver's own work on small problems.
*/
core::ArgumentMatrix copyValues(const Mat& m, const std::string& name, int rows, int cols)
{
    core::ArgumentMatrix out;
    out.name = name;
    out.rows = rows;
    out.cols = cols;
    out.values.resize((size_t)rows * cols);
    const int width = m.cols * m.channels();
    double* dst = out.values.data();
    for (int r = 0; r < m.rows; ++r, dst += width)
    {
        if (m.depth() == CV_64F)
            std::copy(m.ptr<double>(r), m.ptr<double>(r) + width, dst);
        else
            std::copy(m.ptr<float>(r), m.ptr<float>(r) + width, dst);
    }
    return out;
}

//! Nx2 points: Nx2 1-channel or 1xN/Nx1 2-channel; empty: none.
core::ArgumentMatrix readPoints(InputArray arr, const std::string& name)
{
    core::ArgumentMatrix out;
    out.name = name;
    if (arr.empty())
        return out;
    const Mat m = arr.getMat();
    const int n = m.checkVector(2);
    if (n < 0 || !isFloatingPoint(m))
        CV_Error_(Error::StsBadArg, ("%s must be Nx2 1-channel or 1xN/Nx1 2-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name.c_str(), m.rows, m.cols, m.channels(), m.depth()));
    return copyValues(m, name, n, 2);
}

//! Mx4 segments or Mx3 homogeneous lines, 1-channel or 1xM/Mx1 multi-channel; empty: none.
core::ArgumentMatrix readLines(InputArray arr, const std::string& name)
{
    core::ArgumentMatrix out;
    out.name = name;
    if (arr.empty())
        return out;
    const Mat m = arr.getMat();
    int width = 4;
    int n = m.checkVector(4);
    if (n < 0)
    {
        width = 3;
        n = m.checkVector(3);
    }
    if (n < 0 || !isFloatingPoint(m))
        CV_Error_(Error::StsBadArg, ("%s must be Mx4 segments (x0 y0 x1 y1) or Mx3 homogeneous lines (a b c), "
                                     "1-channel or 1xM/Mx1 multi-channel, CV_32F or CV_64F "
                                     "(got %dx%d, %d channel(s), depth %d)",
                                     name.c_str(), m.rows, m.cols, m.channels(), m.depth()));
    return copyValues(m, name, n, width);
}

bool isArrayVector(InputArrayOfArrays arr)
{
    return arr.isMatVector() || arr.isUMatVector() || arr.kind() == _InputArray::STD_VECTOR_VECTOR;
}

//! The arrays of a per-view argument: none, one shared by every view, or a vector (one per view).
std::vector<Mat> readPerView(InputArrayOfArrays arr)
{
    std::vector<Mat> out;
    if (arr.empty())
        return out;
    if (!isArrayVector(arr))
    {
        out.push_back(arr.getMat());
        return out;
    }
    const int n = (int)arr.total();
    out.reserve(n);
    for (int i = 0; i < n; ++i)
        out.push_back(arr.getMat(i));
    return out;
}

//! Name of a per-view argument in messages: "cameraMatrix" when shared, "cameraMatrix[v]" otherwise.
std::string viewArgumentName(const char* base, bool shared, int view)
{
    return shared ? std::string(base) : format("%s[%d]", base, view);
}

core::ArgumentMatrix readCameraMatrix(const Mat& m, const std::string& name)
{
    if (m.total() != 9 || m.channels() != 1 || !isFloatingPoint(m) || m.dims > 2)
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 CV_32F or CV_64F matrix", name.c_str()));
    return copyValues(m, name, 3, 3);
}

core::ArgumentMatrix readDistortion(const Mat& m, const std::string& name)
{
    core::ArgumentMatrix out;
    out.name = name;
    if (m.empty())
        return out;
    const int n = (int)m.total() * m.channels();
    if (!isFloatingPoint(m) || (m.rows != 1 && m.cols != 1) || m.dims > 2)
        CV_Error_(Error::StsBadArg, ("%s must be a vector of 4, 5, 8, 12 or 14 distortion coefficients, CV_32F or CV_64F "
                                     "(got %d values)", name.c_str(), n));
    return copyValues(m, name, 1, n);
}

/** The calibration arguments: one camera matrix (and distortion) shared by every view or one per
view; the core checks the counts.
*/
void readCalibration(InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs, core::ProblemArguments& args)
{
    const std::vector<Mat> Ks = readPerView(cameraMatrix);
    for (size_t v = 0; v < Ks.size(); ++v)
        args.cameraMatrices.push_back(readCameraMatrix(Ks[v], viewArgumentName("cameraMatrix", Ks.size() == 1, (int)v)));
    const std::vector<Mat> dists = readPerView(distCoeffs);
    for (size_t v = 0; v < dists.size(); ++v)
        args.distortions.push_back(readDistortion(dists[v], viewArgumentName("distCoeffs", dists.size() == 1, (int)v)));
}

core::ViewArguments readView(InputArray points, InputArray lines, const std::string& pointsName,
                             const std::string& linesName, bool mayMiss)
{
    core::ViewArguments view;
    view.points = readPoints(points, pointsName);
    view.lines = readLines(lines, linesName);
    view.mayMiss = mayMiss;
    return view;
}

core::ArgumentMatrix readRotationArgument(InputArray arr, const std::string& name)
{
    const Mat m = arr.getMat();
    if (m.empty() || !isFloatingPoint(m) || m.dims > 2 ||
        !((m.total() == 9 && m.channels() == 1) || m.total() * m.channels() == 3))
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 rotation matrix or a 3-element Rodrigues vector, CV_32F or CV_64F",
                                     name.c_str()));
    const int n = (int)m.total() * m.channels();
    return n == 9 ? copyValues(m, name, 3, 3) : copyValues(m, name, 3, 1);
}

core::ArgumentMatrix readTranslationArgument(InputArray arr, const std::string& name)
{
    const Mat m = arr.getMat();
    if (m.empty() || !isFloatingPoint(m) || m.total() * m.channels() != 3 || m.dims > 2)
        CV_Error_(Error::StsBadArg, ("%s must be a 3-element translation vector, CV_32F or CV_64F", name.c_str()));
    return copyValues(m, name, 3, 1);
}

//! The arrays of a vector argument with one entry per view; @p layout says which views, for errors.
std::vector<Mat> readViewVector(InputArrayOfArrays arr, const char* name, int numViews, const char* what,
                                const char* layout)
{
    std::vector<Mat> out(numViews);
    if (arr.empty())
        return out; // every view sees none of this kind
    if (!isArrayVector(arr))
        CV_Error_(Error::StsBadArg, ("%s must be a vector of %s arrays, one per view: %s", name, what, layout));
    const int n = (int)arr.total();
    if (n != numViews)
        CV_Error_(Error::StsBadArg, ("%s must hold %d arrays (%s), got %d", name, numViews, layout, n));
    for (int i = 0; i < n; ++i)
        out[i] = arr.getMat(i);
    return out;
}

/** The arguments of @p numPosed views with world poses plus @p unposedViews without; every view
may miss features. @p posed names the posed views, @p layout the order of all views, in errors.
*/
core::ProblemArguments readPosedViewArguments(InputArrayOfArrays points, InputArrayOfArrays lines,
                                              InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                              InputArrayOfArrays Rs, InputArrayOfArrays ts, int unposedViews,
                                              const char* posed, const char* layout,
                                              std::vector<core::ArgumentMatrix>& rotations,
                                              std::vector<core::ArgumentMatrix>& translations)
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
    core::ProblemArguments args;
    for (int v = 0; v < numViews; ++v)
        args.views.push_back(readView(pointMats[v], lineMats[v], format("points[%d]", v), format("lines[%d]", v), true));
    readCalibration(cameraMatrix, distCoeffs, args);
    for (int k = 0; k < numPosed; ++k)
    {
        rotations.push_back(readRotationArgument(Rs.getMat(k), format("Rs[%d]", k)));
        translations.push_back(readTranslationArgument(ts.getMat(k), format("ts[%d]", k)));
    }
    return args;
}

} // namespace

core::ViewSet readThreeViewInput(InputArray points1, InputArray points2, InputArray points3, InputArray lines1,
                                 InputArray lines2, InputArray lines3, InputArrayOfArrays cameraMatrix,
                                 InputArrayOfArrays distCoeffs, InputArray R12, InputArray t12, int minFeatures)
{
    core::ProblemArguments args;
    args.views.push_back(readView(points1, lines1, "points1", "lines1", false));
    args.views.push_back(readView(points2, lines2, "points2", "lines2", false));
    args.views.push_back(readView(points3, lines3, "points3", "lines3", false));
    readCalibration(cameraMatrix, distCoeffs, args);
    return core::buildThreeViewSet(args, readRotationArgument(R12, "R12"), readTranslationArgument(t12, "t12"),
                                   minFeatures);
}

core::ViewSet readStereoRigInput(InputArray points1, InputArray points2, InputArray points3, InputArray points4,
                                 InputArray lines1, InputArray lines2, InputArray lines3, InputArray lines4,
                                 InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs, InputArray R12,
                                 InputArray t12, int minFeatures)
{
    core::ProblemArguments args;
    args.views.push_back(readView(points1, lines1, "points1", "lines1", false));
    args.views.push_back(readView(points2, lines2, "points2", "lines2", false));
    args.views.push_back(readView(points3, lines3, "points3", "lines3", true));
    args.views.push_back(readView(points4, lines4, "points4", "lines4", true));
    readCalibration(cameraMatrix, distCoeffs, args);
    return core::buildStereoRigSet(args, readRotationArgument(R12, "R12"), readTranslationArgument(t12, "t12"),
                                   minFeatures);
}

core::ViewSet readMultiViewInput(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                                 InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                                 int minFeatures)
{
    const int numKnown = isArrayVector(Rs) ? (int)Rs.total() : 0;
    const std::string layout = format("the %d known views, then the new view", numKnown);
    std::vector<core::ArgumentMatrix> rotations, translations;
    const core::ProblemArguments args = readPosedViewArguments(points, lines, cameraMatrix, distCoeffs, Rs, ts, 1,
                                                               "known views", layout.c_str(), rotations, translations);
    return core::buildMultiViewSet(args, rotations, translations, minFeatures);
}

core::ViewSet readPosedViewsInput(InputArrayOfArrays points, InputArrayOfArrays lines,
                                  InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                  InputArrayOfArrays Rs, InputArrayOfArrays ts)
{
    std::vector<core::ArgumentMatrix> rotations, translations;
    const core::ProblemArguments args = readPosedViewArguments(points, lines, cameraMatrix, distCoeffs, Rs, ts, 0,
                                                               "views", "one per view", rotations, translations);
    return core::buildPosedViewSet(args, rotations, translations);
}

core::ViewSet readSeveralPosesInput(InputArrayOfArrays points, InputArrayOfArrays lines,
                                    InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                                    InputArrayOfArrays Rs, InputArrayOfArrays ts, InputArray fixedViews,
                                    std::vector<int>& poseOfView, std::vector<core::CameraPose>& initialPoses)
{
    std::vector<core::ArgumentMatrix> rotations, translations;
    const core::ProblemArguments args = readPosedViewArguments(points, lines, cameraMatrix, distCoeffs, Rs, ts, 0,
                                                               "views", "one per view", rotations, translations);
    const int numViews = (int)rotations.size();
    Mat fixed = fixedViews.getMat();
    if (fixed.empty() || (int)fixed.total() != numViews || fixed.channels() != 1 ||
        (fixed.depth() != CV_8U && fixed.depth() != CV_32S && fixed.depth() != CV_8S))
        CV_Error_(Error::StsBadArg, ("fixedViews must hold %d values (CV_8U, CV_8S or CV_32S), one per view: nonzero "
                                     "where the view's pose is fixed", numViews));
    fixed.reshape(1, numViews).convertTo(fixed, CV_32S);
    const std::vector<int> fixedFlags(fixed.ptr<int>(), fixed.ptr<int>() + numViews);
    return core::buildSeveralPosesSet(args, rotations, translations, fixedFlags, "fixedViews", poseOfView,
                                      initialPoses);
}

Eigen::Matrix3d readRotation(InputArray rotation, const char* name)
{
    return core::readRotation(readRotationArgument(rotation, name));
}

Eigen::Vector3d readTranslation(InputArray translation, const char* name, bool nonZero)
{
    return core::readTranslation(readTranslationArgument(translation, name), nonZero);
}

} // namespace detail
} // namespace tripose
} // namespace cv
