// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_stereo_chessboard: the motion of a stereo rig between two frames of a chessboard
// calibration set (OpenCV's stereo_calib.xml format: image names, left and right alternating),
// estimated from image features only and compared with the board's own geometry.
//
//   tripose_stereo_chessboard --data <folder> [--list stereo_calib.xml] [--board 9x6] [--square 1]
//                             [--pairs all|consecutive|i,j] [--features all|points|lines]
//                             [--threshold px] [--output results.yml] [--overlay out.png]
//                             [--allow-unknown-keys]
//
// The rig is calibrated from every frame (cv::calibrateCamera per camera, then cv::stereoCalibrate).
// For a frame pair (A, B) the four views are left A [I|0], right A [R12|t12], left B [R|t] and
// right B. Points are the chessboard corners (matched by their index on the board). Lines are the
// board's inner rows and columns: each is observed by the segments cv::LineSegmentDetector finds
// on it; the corners only decide which board line a segment lies on, the line's end points are
// the detector's. Distortion is passed to the module, which undistorts the observations itself.
// Ground truth: the board pose in the left camera at A and at B (cv::solvePnP on the corners with
// the board's known geometry) gives the motion. Printed per pair: the errors of the stereo RANSAC
// (with refinement) and the stereo linear solver, and those of the three-view RANSAC and linear
// solver on views 1-3 (the right image at B unused).
// --output writes the calibration and, per pair, the features, ground truth and estimates
// (FileStorage, YAML or JSON by extension); --overlay (one pair) draws the board lines moved by the
// estimated motion over the left image at B, with the detected segments.

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/tripose.hpp>

#include "tripose_support/pose_error.hpp"

#include "arguments.hpp"
#include "problem_io.hpp"

using tripose_samples::argumentError;
using tripose_samples::optionPairs;
using tripose_samples::parseInteger;
using tripose_samples::parseNumber;

namespace {

const char* kUsage =
    "usage: tripose_stereo_chessboard --data <folder> [--list stereo_calib.xml] [--board 9x6] [--square 1]\n"
    "                                 [--pairs all|consecutive|i,j] [--features all|points|lines]\n"
    "                                 [--threshold px] [--output results.yml] [--overlay out.png]\n"
    "                                 [--allow-unknown-keys]\n"
    "  --data       folder holding the list file and the images\n"
    "  --list       OpenCV FileStorage file in --data with the node 'imagelist': image names, left and\n"
    "               right alternating (default stereo_calib.xml); any other key is an error\n"
    "  --board      inner corners per row x per column (default 9x6)\n"
    "  --square     side of a board square; the unit of every translation (default 1)\n"
    "  --pairs      frame pairs (A, B): all (every A < B, default), consecutive, or one pair i,j; frames are\n"
    "               numbered from 0 in list order, counting those where both images show the whole board\n"
    "  --features   features given to the estimators: all (default), points (corners) or lines\n"
    "  --threshold  RANSAC inlier threshold in pixels (default 2)\n"
    "  --output     write calibration, features, ground truth and estimates (.yml, .yaml or .json)\n"
    "  --overlay    PNG of the left image at B with the board lines moved by the estimate (one pair)\n"
    "  --allow-unknown-keys  read a list file that carries keys other than 'imagelist'\n";

struct Options
{
    std::string data, list = "stereo_calib.xml", pairs = "all", features = "all", output, overlay;
    cv::Size board = cv::Size(9, 6);
    double square = 1.0;
    double threshold = 2.0;
    bool allowUnknownKeys = false;
};

bool hasExtension(const std::string& path, const std::string& extension)
{
    return path.size() > extension.size() &&
           path.compare(path.size() - extension.size(), extension.size(), extension) == 0;
}

Options parseArguments(int argc, char** argv)
{
    Options o;
    const std::vector<std::string> known = { "--data",     "--list",      "--board",  "--square", "--pairs",
                                             "--features", "--threshold", "--output", "--overlay" };
    for (const auto& option : optionPairs(argc, argv, kUsage, known, { "--allow-unknown-keys" }))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--allow-unknown-keys")
            o.allowUnknownKeys = true;
        else if (arg == "--data")
            o.data = value;
        else if (arg == "--list")
            o.list = value;
        else if (arg == "--board")
        {
            const size_t x = value.find('x');
            if (x == std::string::npos)
                throw argumentError(arg, "expected <corners per row>x<corners per column>, got '" + value + "'");
            o.board = cv::Size(parseInteger(arg, value.substr(0, x), 3), parseInteger(arg, value.substr(x + 1), 3));
        }
        else if (arg == "--square")
        {
            o.square = parseNumber(arg, value);
            if (!(o.square > 0))
                throw argumentError(arg, "expected a length > 0, got '" + value + "'");
        }
        else if (arg == "--pairs")
            o.pairs = value;
        else if (arg == "--features")
        {
            if (value != "all" && value != "points" && value != "lines")
                throw argumentError(arg, "expected all, points or lines, got '" + value + "'");
            o.features = value;
        }
        else if (arg == "--threshold")
        {
            o.threshold = parseNumber(arg, value);
            if (!(o.threshold > 0))
                throw argumentError(arg, "expected a threshold > 0 (px), got '" + value + "'");
        }
        else if (arg == "--output")
        {
            if (!hasExtension(value, ".yml") && !hasExtension(value, ".yaml") && !hasExtension(value, ".json"))
                throw argumentError(arg, "expected a .yml, .yaml or .json file name, got '" + value + "'");
            o.output = value;
        }
        else // --overlay
            o.overlay = value;
    }
    if (o.data.empty())
        throw std::runtime_error("argument --data is required (see --help)");
    return o;
}

//! The (A, B) frame pairs of --pairs among @p frames frames.
std::vector<std::pair<int, int>> framePairs(const std::string& spec, int frames)
{
    std::vector<std::pair<int, int>> pairs;
    if (spec == "all")
    {
        for (int a = 0; a < frames; ++a)
            for (int b = a + 1; b < frames; ++b)
                pairs.emplace_back(a, b);
        return pairs;
    }
    if (spec == "consecutive")
    {
        for (int a = 0; a + 1 < frames; ++a)
            pairs.emplace_back(a, a + 1);
        return pairs;
    }
    const size_t comma = spec.find(',');
    if (comma == std::string::npos)
        throw argumentError("--pairs", "expected all, consecutive or i,j, got '" + spec + "'");
    const int a = parseInteger("--pairs", spec.substr(0, comma), 0);
    const int b = parseInteger("--pairs", spec.substr(comma + 1), 0);
    if (a >= frames || b >= frames || a == b)
        throw argumentError("--pairs", "expected two different frames in [0, " + std::to_string(frames - 1) +
                                           "], got '" + spec + "'");
    pairs.emplace_back(a, b);
    return pairs;
}

//! One synchronised left/right frame: images, chessboard corners and detected line segments.
struct Frame
{
    std::string name[2];
    cv::Mat image[2];
    std::vector<cv::Point2f> corners[2];
    std::vector<cv::Vec4f> segments[2];
};

//! The keys of a list file, written once: the reader reads these and rejects any other.
const char* const kListKey = "imagelist";

//! The image names of the list file, in pairs.
std::vector<Frame> readImageList(const std::string& data, const std::string& list, bool allowUnknownKeys)
{
    const std::string path = data + "/" + list;
    cv::FileStorage fs;
    try
    {
        fs.open(path, cv::FileStorage::READ);
    }
    catch (const cv::Exception& e)
    {
        throw std::runtime_error("file " + path + ": not an OpenCV FileStorage file (" + e.err + ")");
    }
    if (!fs.isOpened())
        throw std::runtime_error("file " + path + ": cannot be opened");
    // A misspelt key would otherwise be reported as a missing image list.
    if (!allowUnknownKeys)
        tripose_samples::checkKeys(fs.root().keys(), { kListKey }, path);
    const cv::FileNode node = fs[kListKey];
    if (!node.isSeq() || node.size() == 0 || node.size() % 2 != 0)
        throw std::runtime_error("file " + path +
                                 ": 'imagelist' must be a non-empty sequence of left and right image names");
    std::vector<Frame> frames(node.size() / 2);
    for (size_t i = 0; i < node.size(); ++i)
    {
        if (!node[(int)i].isString())
            throw std::runtime_error("file " + path + ": 'imagelist' entry " + std::to_string(i) + " is not a string");
        frames[i / 2].name[i % 2] = (std::string)node[(int)i];
    }
    return frames;
}

//! Sub-pixel chessboard corners, row by row (index r * board.width + c); false when not all found.
bool findCorners(const cv::Mat& grey, cv::Size board, std::vector<cv::Point2f>& corners)
{
    if (!cv::findChessboardCorners(grey, board, corners, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
        return false;
    cv::cornerSubPix(grey, corners, cv::Size(11, 11), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01));
    return true;
}

//! The calibrated rig: intrinsics and distortion of the left (0) and right (1) cameras, and the
//! pose of the right camera in the left camera's frame.
struct Rig
{
    cv::Mat K[2], dist[2], R12, t12;
    double rms = 0;
};

std::vector<cv::Point3f> boardPoints(cv::Size board, double square)
{
    std::vector<cv::Point3f> points;
    for (int r = 0; r < board.height; ++r)
        for (int c = 0; c < board.width; ++c)
            points.emplace_back(float(c * square), float(r * square), 0.f);
    return points;
}

Rig calibrateRig(const std::vector<Frame>& frames, cv::Size board, double square)
{
    const std::vector<std::vector<cv::Point3f>> object(frames.size(), boardPoints(board, square));
    std::vector<std::vector<cv::Point2f>> image[2];
    for (const Frame& f : frames)
        for (int s = 0; s < 2; ++s)
            image[s].push_back(f.corners[s]);
    const cv::Size size = frames[0].image[0].size();
    Rig rig;
    // Each camera alone first, then both jointly from there: started from scratch with the shared
    // focal length and rational model of OpenCV's stereo_calib sample, the joint optimisation stops
    // at a clearly higher reprojection error on this data (see doc/studies/stereo.md).
    for (int s = 0; s < 2; ++s)
    {
        std::vector<cv::Mat> rvecs, tvecs;
        cv::calibrateCamera(object, image[s], size, rig.K[s], rig.dist[s], rvecs, tvecs);
    }
    cv::Mat E, F;
    rig.rms = cv::stereoCalibrate(object, image[0], image[1], rig.K[0], rig.dist[0], rig.K[1], rig.dist[1], size,
                                  rig.R12, rig.t12, E, F, cv::CALIB_USE_INTRINSIC_GUESS,
                                  cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-6));
    return rig;
}

//! Corner indices along each inner board line: the rows, then the columns.
std::vector<std::vector<int>> boardLines(cv::Size board)
{
    std::vector<std::vector<int>> lines;
    for (int r = 0; r < board.height; ++r)
    {
        lines.emplace_back();
        for (int c = 0; c < board.width; ++c)
            lines.back().push_back(r * board.width + c);
    }
    for (int c = 0; c < board.width; ++c)
    {
        lines.emplace_back();
        for (int r = 0; r < board.height; ++r)
            lines.back().push_back(r * board.width + c);
    }
    return lines;
}

std::vector<cv::Point2d> undistortPixels(const std::vector<cv::Point2d>& pixels, const cv::Mat& K, const cv::Mat& dist)
{
    std::vector<cv::Point2d> out;
    cv::undistortPoints(pixels, out, K, dist, cv::noArray(), K);
    return out;
}

// A detected segment belongs to a board line when both its end points lie within this distance of
// the line through that row's or column's corners (after undistortion): wide enough for the
// corner and calibration errors (a few tenths of a pixel), narrow against the neighbouring line,
// which is a square away (19 px or more in OpenCV's sample images).
const double kAssociationPx = 1.5;
// Shorter segments are mostly texture at the corners; their direction is unreliable.
const double kMinSegmentPx = 8.0;

/** The detector's observation of each board line in one image: the segment from the first to the
last end point, along the line, of the detected segments that lie on it (the board's squares break
a line into one segment per square, since the edge changes polarity at every corner). Both end
points are the detector's, in the raw image. A board line whose segments cover less than half of
the corners' span is not observed: a NaN row.
*/
cv::Mat observeBoardLines(const std::vector<cv::Vec4f>& segments, const std::vector<cv::Point2f>& corners,
                          const std::vector<std::vector<int>>& lines, const cv::Mat& K, const cv::Mat& dist,
                          std::vector<std::vector<int>>* members = nullptr)
{
    std::vector<cv::Point2d> raw;
    for (const cv::Point2f& c : corners)
        raw.emplace_back(c);
    const std::vector<cv::Point2d> flatCorners = undistortPixels(raw, K, dist);
    raw.clear();
    for (const cv::Vec4f& s : segments)
    {
        raw.emplace_back(s[0], s[1]);
        raw.emplace_back(s[2], s[3]);
    }
    const std::vector<cv::Point2d> flatEnds = raw.empty() ? raw : undistortPixels(raw, K, dist);

    // Each board line predicted from its corners (association only): centre, unit direction,
    // and the range along it that the board covers (one square beyond the outer corners).
    struct Predicted
    {
        cv::Point2d centre, direction;
        double low, high, span;
    };
    std::vector<Predicted> predicted;
    for (const std::vector<int>& line : lines)
    {
        std::vector<cv::Point2f> pts;
        for (int i : line)
            pts.emplace_back(flatCorners[i]);
        cv::Vec4f fit;
        cv::fitLine(pts, fit, cv::DIST_L2, 0, 0.01, 0.01);
        Predicted p;
        p.direction = cv::Point2d(fit[0], fit[1]);
        p.centre = cv::Point2d(fit[2], fit[3]);
        const double first = (flatCorners[line.front()] - p.centre).dot(p.direction);
        const double last = (flatCorners[line.back()] - p.centre).dot(p.direction);
        p.span = std::abs(last - first);
        const double square = p.span / double(line.size() - 1);
        p.low = std::min(first, last) - 1.1 * square;
        p.high = std::max(first, last) + 1.1 * square;
        predicted.push_back(p);
    }

    std::vector<std::vector<int>> assigned(lines.size());
    for (size_t s = 0; s < segments.size(); ++s)
    {
        const cv::Point2d& a = flatEnds[2 * s];
        const cv::Point2d& b = flatEnds[2 * s + 1];
        if (cv::norm(a - b) < kMinSegmentPx)
            continue;
        int best = -1;
        double bestDistance = kAssociationPx;
        for (size_t l = 0; l < predicted.size(); ++l)
        {
            const Predicted& p = predicted[l];
            const cv::Point2d normal(-p.direction.y, p.direction.x);
            const double distance = std::max(std::abs((a - p.centre).dot(normal)), std::abs((b - p.centre).dot(normal)));
            const double sa = (a - p.centre).dot(p.direction), sb = (b - p.centre).dot(p.direction);
            if (distance <= bestDistance && std::min(sa, sb) >= p.low && std::max(sa, sb) <= p.high)
            {
                best = int(l);
                bestDistance = distance;
            }
        }
        if (best >= 0)
            assigned[best].push_back(int(s));
    }

    const double nan = std::numeric_limits<double>::quiet_NaN();
    cv::Mat observed((int)lines.size(), 4, CV_64F, cv::Scalar(nan));
    for (size_t l = 0; l < lines.size(); ++l)
    {
        const Predicted& p = predicted[l];
        int firstEnd = -1, lastEnd = -1;
        double first = std::numeric_limits<double>::infinity(), last = -first;
        for (int s : assigned[l])
            for (int e = 2 * s; e < 2 * s + 2; ++e)
            {
                const double along = (flatEnds[e] - p.centre).dot(p.direction);
                if (along < first)
                {
                    first = along;
                    firstEnd = e;
                }
                if (along > last)
                {
                    last = along;
                    lastEnd = e;
                }
            }
        if (firstEnd < 0 || last - first < 0.5 * p.span)
            continue;
        const cv::Vec4f& a = segments[firstEnd / 2];
        const cv::Vec4f& b = segments[lastEnd / 2];
        observed.at<double>((int)l, 0) = a[2 * (firstEnd % 2)];
        observed.at<double>((int)l, 1) = a[2 * (firstEnd % 2) + 1];
        observed.at<double>((int)l, 2) = b[2 * (lastEnd % 2)];
        observed.at<double>((int)l, 3) = b[2 * (lastEnd % 2) + 1];
    }
    if (members)
        *members = assigned;
    return observed;
}

cv::Mat pointsMat(const std::vector<cv::Point2f>& points)
{
    cv::Mat m((int)points.size(), 2, CV_64F);
    for (int i = 0; i < m.rows; ++i)
    {
        m.at<double>(i, 0) = points[i].x;
        m.at<double>(i, 1) = points[i].y;
    }
    return m;
}

bool finiteRow(const cv::Mat& m, int row)
{
    return cv::checkRange(m.row(row));
}

//! The four-view problem of a frame pair, with the three-view problem of its views 1-3.
struct PairProblem
{
    cv::Mat points[4], lines[4];   // views: left A, right A, left B, right B
    cv::Mat lines3View[3];         // the lines seen in view 3
    int linesSeenBy3 = 0, linesSeenBy4 = 0;
};

PairProblem buildProblem(const Frame& a, const Frame& b, const cv::Mat observed[4], const std::string& features)
{
    PairProblem p;
    if (features != "lines")
    {
        const std::vector<cv::Point2f>* corners[4] = { &a.corners[0], &a.corners[1], &b.corners[0], &b.corners[1] };
        for (int v = 0; v < 4; ++v)
            p.points[v] = pointsMat(*corners[v]);
    }
    for (int v = 0; v < 4; ++v)
        p.lines[v] = cv::Mat(0, 4, CV_64F);
    for (int v = 0; v < 3; ++v)
        p.lines3View[v] = cv::Mat(0, 4, CV_64F);
    if (features == "points")
        return p;
    for (int l = 0; l < observed[0].rows; ++l)
    {
        const bool seen3 = finiteRow(observed[2], l), seen4 = finiteRow(observed[3], l);
        if (!finiteRow(observed[0], l) || !finiteRow(observed[1], l) || !(seen3 || seen4))
            continue;
        for (int v = 0; v < 4; ++v)
            p.lines[v].push_back(observed[v].row(l));
        p.linesSeenBy3 += seen3;
        p.linesSeenBy4 += seen4;
        if (seen3)
            for (int v = 0; v < 3; ++v)
                p.lines3View[v].push_back(observed[v].row(l));
    }
    return p;
}

//! One method's estimate of a pair's motion.
struct Estimate
{
    bool ok = false;
    cv::Mat R, t;
    int inliers = -1; // RANSAC only
    cv::tripose::support::PoseError error{};
};

void score(Estimate& e, const cv::Mat& Rgt, const cv::Mat& tgt)
{
    if (e.ok)
        e.error = cv::tripose::support::poseError(e.R, e.t, Rgt, tgt);
}

//! Board pose in a camera (board frame -> camera frame) from its corners: the ground truth.
void boardPose(const std::vector<cv::Point2f>& corners, cv::Size board, double square, const cv::Mat& K,
               const cv::Mat& dist, cv::Mat& R, cv::Mat& t)
{
    cv::Mat rvec;
    cv::solvePnP(boardPoints(board, square), corners, K, dist, rvec, t);
    cv::Rodrigues(rvec, R);
}

//! Draws a 3D segment (camera frame of the image) as the curve the distorted camera sees.
void drawCurve(cv::Mat& image, const cv::Point3d& p, const cv::Point3d& q, const cv::Mat& K, const cv::Mat& dist,
               const cv::Scalar& colour)
{
    const int steps = 32;
    std::vector<cv::Point3d> samples;
    for (int i = 0; i <= steps; ++i)
        samples.push_back(p + (q - p) * (double(i) / steps));
    for (const cv::Point3d& s : samples)
        if (s.z <= 0)
            return;
    std::vector<cv::Point2d> pixels;
    cv::projectPoints(samples, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, dist, pixels);
    std::vector<cv::Point> polyline;
    for (const cv::Point2d& x : pixels)
        polyline.emplace_back(cvRound(x.x * 16), cvRound(x.y * 16));
    cv::polylines(image, polyline, false, colour, 1, cv::LINE_AA, 4);
}

void writeOverlay(const std::string& path, const Frame& b, const std::vector<int>& assignedSegments,
                  const cv::Mat& observedLeftB, const Rig& rig, cv::Size board, double square,
                  const cv::Mat& RboardA, const cv::Mat& tboardA, const Estimate& e)
{
    cv::Mat image;
    cv::cvtColor(b.image[0], image, cv::COLOR_GRAY2BGR);
    for (const cv::Vec4f& s : b.segments[0]) // every detected segment, thin grey
        cv::line(image, cv::Point2f(s[0], s[1]), cv::Point2f(s[2], s[3]), cv::Scalar(160, 160, 160), 1, cv::LINE_AA);
    for (int s : assignedSegments) // those on a board line, red
        cv::line(image, cv::Point2f(b.segments[0][s][0], b.segments[0][s][1]),
                 cv::Point2f(b.segments[0][s][2], b.segments[0][s][3]), cv::Scalar(0, 0, 255), 3, cv::LINE_AA);
    if (e.ok)
    {
        // The board lines, one square beyond the outer corners, placed by the board pose at A and
        // moved into the left camera at B by the estimated motion.
        const cv::Mat R = e.R * RboardA, t = e.R * tboardA + e.t;
        auto toCamera = [&](double x, double y) {
            const cv::Mat X = R * (cv::Mat_<double>(3, 1) << x * square, y * square, 0) + t;
            return cv::Point3d(X.at<double>(0), X.at<double>(1), X.at<double>(2));
        };
        for (int r = 0; r < board.height; ++r)
            drawCurve(image, toCamera(-1, r), toCamera(board.width, r), rig.K[0], rig.dist[0], cv::Scalar(0, 220, 0));
        for (int c = 0; c < board.width; ++c)
            drawCurve(image, toCamera(c, -1), toCamera(c, board.height), rig.K[0], rig.dist[0], cv::Scalar(0, 220, 0));
    }
    for (int l = 0; l < observedLeftB.rows; ++l) // each line's observation: its two end points
        if (finiteRow(observedLeftB, l))
            for (int e2 = 0; e2 < 2; ++e2)
                cv::circle(image, cv::Point2d(observedLeftB.at<double>(l, 2 * e2), observedLeftB.at<double>(l, 2 * e2 + 1)),
                           3, cv::Scalar(255, 128, 0), 1, cv::LINE_AA);
    const std::string caption = "green: board lines moved by the estimate; red: detected segments on them";
    int baseline = 0;
    const cv::Size text = cv::getTextSize(caption, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline);
    cv::rectangle(image, cv::Rect(0, 0, text.width + 12, text.height + baseline + 10), cv::Scalar(0, 0, 0), cv::FILLED);
    cv::putText(image, caption, cv::Point(6, text.height + 5), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    if (!cv::imwrite(path, image))
        throw argumentError("--overlay", "cannot write '" + path + "'");
}

void writeEstimate(cv::FileStorage& fs, const std::string& name, const Estimate& e)
{
    fs << name << "{" << "ok" << int(e.ok);
    if (e.ok)
    {
        fs << "R" << e.R << "t" << e.t << "rot_deg" << e.error.rotationDeg << "t_rel" << e.error.relativeTranslation;
        if (e.inliers >= 0)
            fs << "inliers" << e.inliers;
    }
    fs << "}";
}

std::string formatError(const Estimate& e)
{
    return e.ok ? cv::format("%8.3f %7.2f", e.error.rotationDeg, 100 * e.error.relativeTranslation)
                : std::string("  failed        ");
}

int run(const Options& o)
{
    std::vector<Frame> frames = readImageList(o.data, o.list, o.allowUnknownKeys);
    std::vector<Frame> usable;
    cv::Ptr<cv::LineSegmentDetector> detector = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
    for (Frame& f : frames)
    {
        bool found = true;
        for (int s = 0; s < 2; ++s)
        {
            const std::string path = o.data + "/" + f.name[s];
            f.image[s] = cv::imread(path, cv::IMREAD_GRAYSCALE);
            if (f.image[s].empty())
                throw std::runtime_error("file " + path + ": cannot be read as an image");
            if (!usable.empty() && f.image[s].size() != usable[0].image[0].size())
                throw std::runtime_error("file " + path + ": its size differs from the first image's");
            found = found && findCorners(f.image[s], o.board, f.corners[s]);
            detector->detect(f.image[s], f.segments[s]);
        }
        if (found)
            usable.push_back(f);
        else
            std::cout << "Frame " << f.name[0] << " / " << f.name[1] << ": board not found in both images, skipped\n";
    }
    if (usable.size() < 2)
        throw std::runtime_error("file " + o.data + "/" + o.list + ": fewer than two frames show the whole " +
                                 std::to_string(o.board.width) + "x" + std::to_string(o.board.height) +
                                 " board in both images");
    const std::vector<std::pair<int, int>> pairs = framePairs(o.pairs, (int)usable.size());
    if (!o.overlay.empty() && pairs.size() != 1)
        throw argumentError("--overlay", "needs a single pair (--pairs i,j)");

    const Rig rig = calibrateRig(usable, o.board, o.square);
    std::cout << usable.size() << " frames; rig calibrated, RMS reprojection error " << cv::format("%.3f", rig.rms)
              << " px, baseline " << cv::format("%.3f", cv::norm(rig.t12)) << " squares of side " << o.square << "\n";

    const std::vector<std::vector<int>> lines = boardLines(o.board);
    std::vector<cv::Mat> observed[2];                   // per frame and camera
    std::vector<std::vector<std::vector<int>>> members; // per frame, left camera: segments per board line
    for (const Frame& f : usable)
    {
        std::vector<std::vector<int>> m;
        for (int s = 0; s < 2; ++s)
            observed[s].push_back(observeBoardLines(f.segments[s], f.corners[s], lines, rig.K[s], rig.dist[s],
                                                    s == 0 ? &m : nullptr));
        members.push_back(m);
    }

    cv::FileStorage out;
    if (!o.output.empty())
    {
        out.open(o.output, cv::FileStorage::WRITE);
        if (!out.isOpened())
            throw argumentError("--output", "cannot write '" + o.output + "'");
        out << "board_width" << o.board.width << "board_height" << o.board.height << "square" << o.square;
        out << "calibration_rms" << rig.rms << "K1" << rig.K[0] << "K2" << rig.K[1] << "dist1" << rig.dist[0]
            << "dist2" << rig.dist[1] << "R12" << rig.R12 << "t12" << rig.t12;
        out << "pairs" << "[";
    }

    const std::vector<cv::Mat> K4 = { rig.K[0], rig.K[1], rig.K[0], rig.K[1] };
    const std::vector<cv::Mat> dist4 = { rig.dist[0], rig.dist[1], rig.dist[0], rig.dist[1] };
    cv::tripose::RansacParams params;
    params.threshold = o.threshold;
    // The board's corners and lines are identified by the pattern, not matched between images: no
    // chance correspondences, which the estimators' inlier floor guards against, reach them.
    params.minInliers = 0;
    const char* methodKeys[] = { "stereo_ransac", "stereo_linear", "three_view_ransac", "three_view_linear" };
    std::cout << "Rotation error (deg) and translation error (% of |t|) of each method against the board's ground truth\n"
              << cv::format("%-6s  %-22s %6s %-12s", "pair", "images (left)", "points", "lines at B")
              << "|  stereo RANSAC   |  stereo linear   |  3-view RANSAC   |  3-view linear\n";
    for (const auto& ab : pairs)
    {
        const Frame& A = usable[ab.first];
        const Frame& B = usable[ab.second];
        const cv::Mat obs[4] = { observed[0][ab.first], observed[1][ab.first], observed[0][ab.second],
                                 observed[1][ab.second] };
        const PairProblem p = buildProblem(A, B, obs, o.features);

        cv::Mat RA, tA, RB, tB;
        boardPose(A.corners[0], o.board, o.square, rig.K[0], rig.dist[0], RA, tA);
        boardPose(B.corners[0], o.board, o.square, rig.K[0], rig.dist[0], RB, tB);
        const cv::Mat Rgt = RB * RA.t(), tgt = tB - Rgt * tA;

        // In methodKeys' order. A method that throws (too few features of the kinds it uses) has
        // failed on this pair.
        Estimate estimates[4];
        auto attempt = [&](Estimate& e, const std::function<void()>& call) {
            try
            {
                call();
            }
            catch (const cv::Exception&)
            {
                e = Estimate();
            }
            score(e, Rgt, tgt);
        };
        Estimate& ransac = estimates[0];
        attempt(ransac, [&] {
            ransac.inliers = cv::tripose::estimatePoseLinePointStereoRansac(
                p.points[0], p.points[1], p.points[2], p.points[3], p.lines[0], p.lines[1], p.lines[2], p.lines[3],
                K4, dist4, rig.R12, rig.t12, ransac.R, ransac.t, params);
            ransac.ok = !ransac.R.empty();
        });
        attempt(estimates[1], [&] {
            estimates[1].ok = cv::tripose::estimatePoseLinePointStereo(
                p.points[0], p.points[1], p.points[2], p.points[3], p.lines[0], p.lines[1], p.lines[2], p.lines[3],
                K4, dist4, rig.R12, rig.t12, estimates[1].R, estimates[1].t) > 0;
        });
        const std::vector<cv::Mat> K3(K4.begin(), K4.begin() + 3), dist3(dist4.begin(), dist4.begin() + 3);
        attempt(estimates[2], [&] {
            estimates[2].inliers = cv::tripose::estimatePoseLinePointRansac(
                p.points[0], p.points[1], p.points[2], p.lines3View[0], p.lines3View[1], p.lines3View[2], K3, dist3,
                rig.R12, rig.t12, estimates[2].R, estimates[2].t, params);
            estimates[2].ok = !estimates[2].R.empty();
        });
        attempt(estimates[3], [&] {
            estimates[3].ok = cv::tripose::estimatePoseLinePoint(p.points[0], p.points[1], p.points[2],
                                                                 p.lines3View[0], p.lines3View[1], p.lines3View[2],
                                                                 K3, dist3, rig.R12, rig.t12, estimates[3].R,
                                                                 estimates[3].t) > 0;
        });

        const std::string names = A.name[0] + " " + B.name[0];
        std::cout << cv::format("%2d,%-3d  %-22s %6d %3d/%-8d", ab.first, ab.second, names.c_str(),
                                p.points[0].rows, p.linesSeenBy3, p.linesSeenBy4);
        for (const Estimate& e : estimates)
            std::cout << "| " << formatError(e) << " ";
        std::cout << "\n";

        if (out.isOpened())
        {
            out << "{" << "frame_a" << ab.first << "frame_b" << ab.second << "left_a" << A.name[0] << "left_b"
                << B.name[0];
            for (int v = 0; v < 4; ++v)
                out << "points" + std::to_string(v + 1) << (p.points[v].empty() ? cv::Mat(0, 2, CV_64F) : p.points[v])
                    << "lines" + std::to_string(v + 1) << p.lines[v];
            out << "R_gt" << Rgt << "t_gt" << tgt;
            for (int m = 0; m < 4; ++m)
                writeEstimate(out, methodKeys[m], estimates[m]);
            out << "}";
        }
        if (!o.overlay.empty())
        {
            std::vector<int> assigned;
            for (const std::vector<int>& m : members[ab.second])
                assigned.insert(assigned.end(), m.begin(), m.end());
            writeOverlay(o.overlay, B, assigned, obs[2], rig, o.board, o.square, RA, tA, ransac);
            std::cout << "Overlay written to " << o.overlay << "\n";
        }
    }
    if (out.isOpened())
    {
        out << "]";
        out.release();
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        return run(parseArguments(argc, argv));
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_stereo_chessboard: " << e.what() << "\n";
        return 1;
    }
}
