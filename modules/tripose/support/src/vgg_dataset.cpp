// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Reader of the Oxford VGG multi-view sequences (Model House, Corridor, Merton College I-III,
// University Library, Wadham College). A sequence folder holds, per view, <stem>.P (3x4 camera
// matrix), <stem>.corners ("x y" rows) and <stem>.lines ("x0 y0 x1 y1", Model House adds two
// columns), and per sequence <prefix>p3d, <prefix>l3d, <prefix>nview-corners and
// <prefix>nview-lines, where <prefix> is "house.", "bt." or empty. Row i of an nview file lists, per
// view in image order, the 0-based index of 3D feature i in that view's file, '*' when unseen.

#include "tripose_support/vgg_dataset.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include "opencv2/core/utils/filesystem.hpp"
#include "opencv_geometry.hpp"

namespace cv {
namespace tripose {
namespace support {

namespace {

//! A numeric text table read row by row; '*' (unseen feature) is stored as -1.
struct Table
{
    std::string path;
    int cols = 0;
    std::vector<double> values;

    int rows() const { return cols ? (int)(values.size() / cols) : 0; }
    const double* row(int i) const { return &values[(size_t)i * cols]; }
};

enum class Columns
{
    EXACT,      //!< every row has exactly the given number of columns
    AT_LEAST    //!< extra columns are ignored (Model House .lines carry two more)
};

[[noreturn]] void fileError(cv::Error::Code code, const std::string& path, const std::string& what)
{
    CV_Error(code, format("VGG reader: %s: %s", path.c_str(), what.c_str()));
}

Table readTable(const std::string& path, int cols, Columns rule, bool allowMissing)
{
    std::ifstream in(path);
    if (!in)
        fileError(Error::StsObjectNotFound, path, "cannot open the file");
    Table table;
    table.path = path;
    table.cols = cols;
    std::string line;
    int lineNumber = 0;
    std::vector<double> row;
    while (std::getline(in, line))
    {
        ++lineNumber;
        row.clear();
        const char* p = line.c_str();
        for (;;)
        {
            while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n' || *p == '\v' || *p == '\f')
                ++p;
            if (!*p)
                break;
            if (*p == '*' && allowMissing)
            {
                row.push_back(-1);
                ++p;
            }
            else
            {
                char* end = nullptr;
                errno = 0;
                const double v = std::strtod(p, &end);
                if (end == p || errno == ERANGE || !std::isfinite(v))
                    fileError(Error::StsParseError, path, format("line %d: expected a number, got '%s'", lineNumber,
                                                                 std::string(p, std::min<size_t>(std::strlen(p), 20)).c_str()));
                row.push_back(v);
                p = end;
            }
            if (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n' && *p != '\v' && *p != '\f')
                fileError(Error::StsParseError, path, format("line %d: unexpected character '%c'", lineNumber, *p));
        }
        if (row.empty()) // blank lines, e.g. at the end of the file
            continue;
        if ((rule == Columns::EXACT && (int)row.size() != cols) || (int)row.size() < cols)
            fileError(Error::StsParseError, path, format("line %d: expected %s%d values, got %d", lineNumber,
                                                         rule == Columns::EXACT ? "" : "at least ", cols, (int)row.size()));
        table.values.insert(table.values.end(), row.begin(), row.begin() + cols);
    }
    return table;
}

//! The files of a sequence; views in image order.
struct SequenceLayout
{
    std::vector<std::string> viewStems; //!< <folder>/<stem>, e.g. .../bt.003
    std::string prefix;                 //!< <folder>/ followed by "bt.", "house." or nothing
};

SequenceLayout findLayout(const String& sequenceDir, const char* caller)
{
    if (!utils::fs::isDirectory(sequenceDir))
        CV_Error(Error::StsObjectNotFound, format("%s: sequenceDir '%s' is not a folder", caller, sequenceDir.c_str()));
    std::vector<String> cameraFiles;
    glob(utils::fs::join(sequenceDir, "*.P"), cameraFiles, false);
    std::sort(cameraFiles.begin(), cameraFiles.end()); // zero-padded numbers: name order is image order
    if (cameraFiles.empty())
        CV_Error(Error::StsObjectNotFound,
                 format("%s: sequenceDir '%s' holds no camera matrix files (*.P)", caller, sequenceDir.c_str()));
    SequenceLayout layout;
    for (size_t i = 0; i < cameraFiles.size(); ++i)
    {
        const std::string stem = cameraFiles[i].substr(0, cameraFiles[i].size() - 2);
        const size_t slash = stem.find_last_of("/\\");
        const size_t dot = stem.find_last_of('.');
        // "bt.003" -> "bt.", "001" -> ""
        const std::string prefix = (dot != std::string::npos && (slash == std::string::npos || dot > slash))
                                       ? stem.substr(0, dot + 1)
                                       : stem.substr(0, slash == std::string::npos ? 0 : slash + 1);
        if (i == 0)
            layout.prefix = prefix;
        else if (prefix != layout.prefix)
            CV_Error(Error::StsBadArg, format("%s: %s does not follow the naming of %s", caller,
                                              cameraFiles[i].c_str(), cameraFiles[0].c_str()));
        layout.viewStems.push_back(stem);
    }
    return layout;
}

//! Indices of an nview column: -1 (unseen, '*' or -1) or a row of the view's feature file.
void checkCorrespondences(const Table& nview, int view, int featureCount, const std::string& featureFile)
{
    for (int i = 0; i < nview.rows(); ++i)
    {
        const double index = nview.row(i)[view];
        if (index == -1)
            continue;
        if (index != std::floor(index) || index < 0 || index >= featureCount)
            fileError(Error::StsParseError, nview.path,
                      format("row %d, view %d: index %g is not a row of %s (%d rows)", i + 1, view, index,
                             featureFile.c_str(), featureCount));
    }
}

//! P = lambda K [R | t] with K upper triangular, positive diagonal, K(2,2) = 1 and lambda > 0.
//! The caller has made det(P(:, 0:3)) > 0.
void decomposeCamera(const Matx34d& P, const std::string& path, Matx33d& K, Matx33d& R, Vec3d& t)
{
    const Matx33d M = P.get_minor<3, 3>(0, 0);
    Matx33d upper, orthogonal;
    RQDecomp3x3(M, upper, orthogonal);
    // RQ is unique up to the signs of the diagonal: make it positive.
    Matx33d signs = Matx33d::eye();
    for (int i = 0; i < 3; ++i)
        if (upper(i, i) < 0)
            signs(i, i) = -1;
    upper = upper * signs;
    orthogonal = signs * orthogonal;
    if (!(upper(0, 0) > 0 && upper(1, 1) > 0 && upper(2, 2) > 0) || !(determinant(orthogonal) > 0))
        fileError(Error::StsError, path, "the camera matrix is singular or its world frame is left-handed");
    t = upper.solve(Vec3d(P(0, 3), P(1, 3), P(2, 3)), DECOMP_LU);
    K = upper * (1.0 / upper(2, 2));
    K(1, 0) = K(2, 0) = K(2, 1) = 0; // exactly upper triangular
    K(2, 2) = 1;
    R = orthogonal;
}

//! Third coordinate of P [X; 1]: positive for points in front when P = lambda K [R|t] with lambda > 0.
inline double homogeneousDepth(const Matx34d& P, const double* X)
{
    return P(2, 0) * X[0] + P(2, 1) * X[1] + P(2, 2) * X[2] + P(2, 3);
}

//! Fixes the overall sign of P so that the structure seen in the view is in front of it.
void orientTowardsStructure(Matx34d& P, int view, const Table& p3d, const Table& nviewCorners, const Table& l3d,
                            const Table& nviewLines)
{
    int positive = 0, negative = 0;
    for (int i = 0; i < p3d.rows(); ++i)
        if (nviewCorners.row(i)[view] >= 0)
            (homogeneousDepth(P, p3d.row(i)) > 0 ? positive : negative)++;
    for (int i = 0; i < l3d.rows(); ++i)
        if (nviewLines.row(i)[view] >= 0)
        {
            (homogeneousDepth(P, l3d.row(i)) > 0 ? positive : negative)++;
            (homogeneousDepth(P, l3d.row(i) + 3) > 0 ? positive : negative)++;
        }
    if (negative > positive)
        P *= -1.0;
}

Mat toMat(const Matx33d& m) { return Mat(m, true); }
Mat toMat(const Vec3d& v) { return Mat(v, true); }

} // namespace

int vggSequenceViewCount(const String& sequenceDir)
{
    return (int)findLayout(sequenceDir, "vggSequenceViewCount").viewStems.size();
}

namespace {

//! What the files of a sequence say about some of its views, cameras decomposed in the (possibly
//! Z-flipped) world frame of the sequence.
struct LoadedViews
{
    Table p3d, l3d, nviewCorners, nviewLines;
    std::vector<Table> corners, segments;
    std::vector<Matx33d> K, Rw;
    std::vector<Vec3d> tw;
    double flip = 1; //!< -1 where the sequence's world frame is mirrored (Z flipped on reading)
};

LoadedViews loadViews(const SequenceLayout& layout, const std::vector<int>& views)
{
    const int numViews = (int)layout.viewStems.size();
    LoadedViews out;
    out.p3d = readTable(layout.prefix + "p3d", 3, Columns::EXACT, false);
    out.l3d = readTable(layout.prefix + "l3d", 6, Columns::EXACT, false);
    out.nviewCorners = readTable(layout.prefix + "nview-corners", numViews, Columns::EXACT, true);
    out.nviewLines = readTable(layout.prefix + "nview-lines", numViews, Columns::EXACT, true);
    if (out.nviewCorners.rows() != out.p3d.rows())
        fileError(Error::StsBadSize, out.nviewCorners.path, format("has %d rows but %s has %d (one per 3D point)",
                                                                   out.nviewCorners.rows(), out.p3d.path.c_str(), out.p3d.rows()));
    if (out.nviewLines.rows() != out.l3d.rows())
        fileError(Error::StsBadSize, out.nviewLines.path, format("has %d rows but %s has %d (one per 3D line)",
                                                                 out.nviewLines.rows(), out.l3d.path.c_str(), out.l3d.rows()));

    const int n = (int)views.size();
    out.corners.resize(n);
    out.segments.resize(n);
    std::vector<Matx34d> P(n);
    bool mirrored = false;
    for (int k = 0; k < n; ++k)
    {
        const std::string& stem = layout.viewStems[views[k]];
        out.corners[k] = readTable(stem + ".corners", 2, Columns::AT_LEAST, false);
        out.segments[k] = readTable(stem + ".lines", 4, Columns::AT_LEAST, false);
        checkCorrespondences(out.nviewCorners, views[k], out.corners[k].rows(), out.corners[k].path);
        checkCorrespondences(out.nviewLines, views[k], out.segments[k].rows(), out.segments[k].path);

        const Table camera = readTable(stem + ".P", 4, Columns::EXACT, false);
        if (camera.rows() != 3)
            fileError(Error::StsParseError, camera.path, format("expected 3 rows of 4 values, got %d rows", camera.rows()));
        P[k] = Matx34d(camera.row(0));
        orientTowardsStructure(P[k], views[k], out.p3d, out.nviewCorners, out.l3d, out.nviewLines);
        // With the structure in front, a negative determinant means a mirrored (left-handed) world frame.
        const bool left = determinant(P[k].get_minor<3, 3>(0, 0)) < 0;
        if (k == 0)
            mirrored = left;
        else if (left != mirrored)
            fileError(Error::StsBadArg, camera.path,
                      format("its world frame is %s-handed but that of %s.P is %s-handed", left ? "left" : "right",
                             layout.viewStems[views[0]].c_str(), mirrored ? "left" : "right"));
    }

    // Mirrored sequences (Model House, Corridor) are read in a world frame with Z flipped:
    // X' = S X and P' = P S with S = diag(1, 1, -1), so that P' X' = P X.
    out.flip = mirrored ? -1.0 : 1.0;
    out.K.resize(n);
    out.Rw.resize(n);
    out.tw.resize(n);
    for (int k = 0; k < n; ++k)
    {
        for (int r = 0; r < 3; ++r)
            P[k](r, 2) *= out.flip;
        decomposeCamera(P[k], layout.viewStems[views[k]] + ".P", out.K[k], out.Rw[k], out.tw[k]);
    }
    return out;
}

} // namespace

VggTriplet loadVggTriplet(const String& sequenceDir, int view1, int view2, int view3)
{
    const SequenceLayout layout = findLayout(sequenceDir, "loadVggTriplet");
    const int numViews = (int)layout.viewStems.size();
    const int views[3] = { view1, view2, view3 };
    for (int k = 0; k < 3; ++k)
    {
        if (views[k] < 0 || views[k] >= numViews)
            CV_Error(Error::StsOutOfRange, format("loadVggTriplet: view%d = %d is out of range [0, %d) for the %d views of '%s'",
                                                  k + 1, views[k], numViews, numViews, sequenceDir.c_str()));
        for (int j = 0; j < k; ++j)
            if (views[j] == views[k])
                CV_Error(Error::StsBadArg, format("loadVggTriplet: view%d and view%d are both %d; expected three distinct views",
                                                  j + 1, k + 1, views[k]));
    }

    const LoadedViews loaded = loadViews(layout, std::vector<int>(views, views + 3));
    const Table& p3d = loaded.p3d;
    const Table& l3d = loaded.l3d;
    const Table& nviewCorners = loaded.nviewCorners;
    const Table& nviewLines = loaded.nviewLines;
    const std::vector<Table>& corners = loaded.corners;
    const std::vector<Table>& segments = loaded.segments;
    const std::vector<Matx33d>& K = loaded.K;
    const std::vector<Matx33d>& Rw = loaded.Rw;
    const std::vector<Vec3d>& tw = loaded.tw;
    const double flip = loaded.flip;

    // Everything in the frame of the first chosen view: X1 = R1 S X + t1, R_k1 = R_k R1^T, t_k1 = t_k - R_k1 t1.
    auto toView1 = [&](const double* X) { return Rw[0] * Vec3d(X[0], X[1], flip * X[2]) + tw[0]; };
    VggTriplet triplet;
    triplet.cameraMatrices.resize(3);
    for (int k = 0; k < 3; ++k)
        triplet.cameraMatrices[k] = toMat(K[k]);
    const Matx33d R12 = Rw[1] * Rw[0].t(), R13 = Rw[2] * Rw[0].t();
    triplet.R12 = toMat(R12);
    triplet.t12 = toMat(Vec3d(tw[1] - R12 * tw[0]));
    triplet.R = toMat(R13);
    triplet.t = toMat(Vec3d(tw[2] - R13 * tw[0]));

    std::vector<int> pointIds, lineIds;
    for (int i = 0; i < p3d.rows(); ++i)
    {
        const double* row = nviewCorners.row(i);
        if (row[views[0]] >= 0 && row[views[1]] >= 0 && row[views[2]] >= 0)
            pointIds.push_back(i);
    }
    for (int i = 0; i < l3d.rows(); ++i)
    {
        const double* row = nviewLines.row(i);
        if (row[views[0]] >= 0 && row[views[1]] >= 0 && row[views[2]] >= 0)
            lineIds.push_back(i);
    }

    const int N = (int)pointIds.size(), M = (int)lineIds.size();
    Mat* points[3] = { &triplet.points1, &triplet.points2, &triplet.points3 };
    Mat* lines[3] = { &triplet.lines1, &triplet.lines2, &triplet.lines3 };
    triplet.pointIds.create(N, 1, CV_32S);
    triplet.lineIds.create(M, 1, CV_32S);
    triplet.points3d.create(N, 3, CV_64F);
    triplet.lines3d.create(M, 6, CV_64F);
    for (int k = 0; k < 3; ++k)
    {
        points[k]->create(N, 2, CV_64F);
        lines[k]->create(M, 4, CV_64F);
    }
    for (int n = 0; n < N; ++n)
    {
        const int id = pointIds[n];
        triplet.pointIds.at<int>(n) = id;
        const Vec3d X = toView1(p3d.row(id));
        std::copy(X.val, X.val + 3, triplet.points3d.ptr<double>(n));
        for (int k = 0; k < 3; ++k)
        {
            const double* x = corners[k].row((int)nviewCorners.row(id)[views[k]]);
            std::copy(x, x + 2, points[k]->ptr<double>(n));
        }
    }
    for (int m = 0; m < M; ++m)
    {
        const int id = lineIds[m];
        triplet.lineIds.at<int>(m) = id;
        const Vec3d A = toView1(l3d.row(id)), B = toView1(l3d.row(id) + 3);
        double* L = triplet.lines3d.ptr<double>(m);
        std::copy(A.val, A.val + 3, L);
        std::copy(B.val, B.val + 3, L + 3);
        for (int k = 0; k < 3; ++k)
        {
            const double* s = segments[k].row((int)nviewLines.row(id)[views[k]]);
            std::copy(s, s + 4, lines[k]->ptr<double>(m));
        }
    }
    return triplet;
}


VggSequence loadVggSequence(const String& sequenceDir)
{
    const SequenceLayout layout = findLayout(sequenceDir, "loadVggSequence");
    const int F = (int)layout.viewStems.size();
    std::vector<int> all(F);
    for (int k = 0; k < F; ++k)
        all[k] = k;
    const LoadedViews loaded = loadViews(layout, all);

    VggSequence sequence;
    sequence.stems = std::vector<String>(layout.viewStems.begin(), layout.viewStems.end());
    const double flip = loaded.flip;
    auto toView0 = [&](const double* X) { return loaded.Rw[0] * Vec3d(X[0], X[1], flip * X[2]) + loaded.tw[0]; };
    const int N = loaded.p3d.rows(), M = loaded.l3d.rows();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int k = 0; k < F; ++k)
    {
        sequence.cameraMatrices.push_back(toMat(loaded.K[k]));
        const Matx33d R = loaded.Rw[k] * loaded.Rw[0].t();
        sequence.Rs.push_back(toMat(R));
        sequence.ts.push_back(toMat(Vec3d(loaded.tw[k] - R * loaded.tw[0])));
        Mat points(N, 2, CV_64F, Scalar::all(nan)), lines(M, 4, CV_64F, Scalar::all(nan));
        for (int i = 0; i < N; ++i)
        {
            const double index = loaded.nviewCorners.row(i)[k];
            if (index >= 0)
            {
                const double* x = loaded.corners[k].row((int)index);
                std::copy(x, x + 2, points.ptr<double>(i));
            }
        }
        for (int i = 0; i < M; ++i)
        {
            const double index = loaded.nviewLines.row(i)[k];
            if (index >= 0)
            {
                const double* x = loaded.segments[k].row((int)index);
                std::copy(x, x + 4, lines.ptr<double>(i));
            }
        }
        sequence.points.push_back(points);
        sequence.lines.push_back(lines);
    }
    sequence.points3d.create(N, 3, CV_64F);
    sequence.lines3d.create(M, 6, CV_64F);
    for (int i = 0; i < N; ++i)
    {
        const Vec3d X = toView0(loaded.p3d.row(i));
        std::copy(X.val, X.val + 3, sequence.points3d.ptr<double>(i));
    }
    for (int i = 0; i < M; ++i)
    {
        const Vec3d A = toView0(loaded.l3d.row(i)), B = toView0(loaded.l3d.row(i) + 3);
        std::copy(A.val, A.val + 3, sequence.lines3d.ptr<double>(i));
        std::copy(B.val, B.val + 3, sequence.lines3d.ptr<double>(i) + 3);
    }
    return sequence;
}

} // namespace support
} // namespace tripose
} // namespace cv
