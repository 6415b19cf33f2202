// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "problem_io.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tripose_samples {

namespace {

std::runtime_error keyError(const std::string& key, const std::string& what)
{
    return std::runtime_error("key '" + key + "': " + what);
}

//! The number of elements a matrix node declares (rows x cols, or the product of its sizes); -1 when
//! the header is not made of non-negative integers.
double declaredElements(const cv::FileNode& node)
{
    const cv::FileNode sizes = node["sizes"];
    if (!sizes.empty())
    {
        if (!sizes.isSeq())
            return -1;
        double n = 1;
        for (const cv::FileNode& size : sizes)
        {
            if (!size.isInt() || (int)size < 0)
                return -1;
            n *= (int)size;
        }
        return n;
    }
    const cv::FileNode rows = node["rows"], cols = node["cols"];
    if (!rows.isInt() || !cols.isInt() || (int)rows < 0 || (int)cols < 0)
        return -1;
    return double((int)rows) * (int)cols;
}

//! A matrix under @p key, or an empty one when the key is absent or empty.
cv::Mat readMatrix(const cv::FileStorage& fs, const std::string& key)
{
    const cv::FileNode node = fs[key];
    if (node.empty() || node.isNone())
        return cv::Mat();
    if (!node.isMap())
        throw keyError(key, "expected an OpenCV matrix (!!opencv-matrix with rows, cols, dt, data)");
    // OpenCV allocates what the header declares before it compares that with the data (found by
    // fuzz_problem_reader: a few corrupt bytes asked for 48 GB). Every element needs at least one
    // value in data, so more declared elements than values is malformed.
    const double declared = declaredElements(node);
    if (declared < 0)
        throw keyError(key, "malformed matrix header: rows and cols (or sizes) must be non-negative integers");
    const cv::FileNode data = node["data"];
    const double values = data.isSeq() ? (double)data.size() : (data.empty() ? 0.0 : 1.0);
    if (declared > values)
        throw keyError(key, cv::format("malformed matrix: the header declares %.0f elements but data holds %.0f values",
                                       declared, values));
    cv::Mat m;
    try
    {
        node >> m;
    }
    catch (const cv::Exception& e)
    {
        throw keyError(key, "malformed matrix: " + e.msg);
    }
    if (m.empty())
        return m;
    if (m.channels() != 1)
        throw keyError(key, "expected a 1-channel matrix");
    m.convertTo(m, CV_64F);
    if (!cv::checkRange(m))
        throw keyError(key, "contains NaN or Inf values");
    return m;
}

cv::Mat requireShape(const cv::Mat& m, const std::string& key, int rows, int cols)
{
    if (m.empty())
        throw keyError(key, "missing");
    if ((rows > 0 && m.rows != rows) || (cols > 0 && m.cols != cols))
        throw keyError(key, cv::format("expected %sx%s, got %dx%d", rows > 0 ? std::to_string(rows).c_str() : "N",
                                       cols > 0 ? std::to_string(cols).c_str() : "N", m.rows, m.cols));
    return m;
}

//! One key (e.g. K) or three per-view keys (K1..K3); not both.
std::vector<cv::Mat> readShared(const cv::FileStorage& fs, const std::string& key, bool required)
{
    const cv::Mat shared = readMatrix(fs, key);
    cv::Mat perView[3];
    int present = 0;
    for (int v = 0; v < 3; ++v)
    {
        perView[v] = readMatrix(fs, key + std::to_string(v + 1));
        present += !perView[v].empty();
    }
    if (!shared.empty() && present > 0)
        throw keyError(key, "give either " + key + " or " + key + "1.." + key + "3, not both");
    if (!shared.empty())
        return { shared };
    if (present == 3)
        return { perView[0], perView[1], perView[2] };
    for (int v = 0; v < 3 && present > 0; ++v)
        if (perView[v].empty())
            throw keyError(key + std::to_string(v + 1), "missing (per-view " + key + " needs all three views)");
    if (required)
        throw keyError(key, "missing (give " + key + " or " + key + "1.." + key + "3)");
    return {};
}

//! points1..3 or lines1..3: all absent/empty, or all present with the given width and equal rows.
void readFeatures(const cv::FileStorage& fs, const std::string& prefix, int width, cv::Mat out[3])
{
    for (int v = 0; v < 3; ++v)
    {
        const std::string key = prefix + std::to_string(v + 1);
        out[v] = readMatrix(fs, key);
        if (out[v].empty())
            out[v] = cv::Mat(0, width, CV_64F);
        else if (out[v].cols != width)
            throw keyError(key, cv::format("expected %d columns, got %dx%d", width, out[v].rows, out[v].cols));
    }
    for (int v = 1; v < 3; ++v)
        if (out[v].rows != out[0].rows)
            throw keyError(prefix + std::to_string(v + 1),
                           cv::format("has %d rows but %s1 has %d", out[v].rows, prefix.c_str(), out[0].rows));
}

Problem readFromStorage(const cv::FileStorage& fs)
{
    // Looking up a key in anything but a map is an OpenCV assertion (found by fuzz_problem_reader).
    if (!fs.root().isMap())
        throw std::runtime_error("the problem must be a map of keys (K, R12, t12, points1, ...) at the top level");
    Problem p;
    p.K = readShared(fs, "K", true);
    for (size_t v = 0; v < p.K.size(); ++v)
        requireShape(p.K[v], p.K.size() == 1 ? "K" : "K" + std::to_string(v + 1), 3, 3);
    p.dist = readShared(fs, "dist", false);
    p.R12 = readMatrix(fs, "R12");
    if (p.R12.empty() || !(p.R12.total() == 9 || p.R12.total() == 3))
        throw keyError("R12", p.R12.empty() ? "missing" : "expected 3x3 rotation or 3x1 Rodrigues vector");
    p.t12 = readMatrix(fs, "t12");
    if (p.t12.total() != 3)
        throw keyError("t12", p.t12.empty() ? "missing" : "expected 3x1");
    readFeatures(fs, "points", 2, p.points);
    readFeatures(fs, "lines", 4, p.lines);
    return p;
}

/** readFromStorage, with OpenCV's own assertions on malformed content turned into parse errors:
FileStorage::operator[] searches every document of the file and asserts that each is a map (found
by fuzz_problem_reader: a second, empty document after a first that is a map).
*/
Problem readChecked(const cv::FileStorage& fs, const std::string& what)
{
    try
    {
        return readFromStorage(fs);
    }
    catch (const cv::Exception& e)
    {
        throw std::runtime_error("cannot parse " + what + ": " + e.msg);
    }
}

/** OpenCV 4.6's YAML parser never returns on some corrupt text (found by fuzz_problem_reader:
"---K1: 0" followed by a "----" line). A problem file is one document whose only line starting with
"---" is the document marker itself, so any other such line is rejected before parsing.
*/
void rejectParserTraps(const std::string& text)
{
    int line = 1;
    for (size_t at = 0; at < text.size(); ++line)
    {
        if (text.compare(at, 3, "---") == 0 && at + 3 < text.size() && !std::isspace((unsigned char)text[at + 3]))
            throw std::runtime_error(cv::format("cannot parse line %d: it starts with '---' but is not a document marker", line));
        const size_t next = text.find('\n', at);
        if (next == std::string::npos)
            break;
        at = next + 1;
    }
}

} // namespace

Problem readProblem(const std::string& path)
{
    const bool compressed = path.size() >= 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
    std::ifstream file(path, std::ios::binary);
    if (file && !compressed)
    {
        std::ostringstream text;
        text << file.rdbuf();
        rejectParserTraps(text.str());
    }
    cv::FileStorage fs;
    try
    {
        if (!fs.open(path, cv::FileStorage::READ))
            throw std::runtime_error("cannot open " + path);
    }
    catch (const cv::Exception& e)
    {
        throw std::runtime_error("cannot parse " + path + ": " + e.msg);
    }
    catch (const std::runtime_error&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        // OpenCV 4.6's parser lets some standard exceptions out (see readProblemFromString).
        throw std::runtime_error("cannot parse " + path + ": " + e.what());
    }
    return readChecked(fs, path);
}

Problem readProblemFromString(const std::string& text, const std::string& format)
{
    rejectParserTraps(text);
    cv::FileStorage fs;
    try
    {
        if (!fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | (format == ".json" ? cv::FileStorage::FORMAT_JSON : cv::FileStorage::FORMAT_YAML)))
            throw std::runtime_error("cannot parse the problem text");
    }
    catch (const cv::Exception& e)
    {
        throw std::runtime_error("cannot parse the problem text: " + e.msg);
    }
    catch (const std::runtime_error&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        // OpenCV 4.6's YAML parser throws std::length_error on some corrupt input (a key repeated
        // inside a matrix, found by fuzz_problem_reader): a parse error all the same.
        throw std::runtime_error(std::string("cannot parse the problem text: ") + e.what());
    }
    return readChecked(fs, "the problem text");
}

std::string problemKeyNamedBy(const std::string& solverMessage)
{
    static const char* const names[][2] = {
        { "cameraMatrix[0]", "K1" }, { "cameraMatrix[1]", "K2" }, { "cameraMatrix[2]", "K3" }, { "cameraMatrix", "K" },
        { "distCoeffs[0]", "dist1" }, { "distCoeffs[1]", "dist2" }, { "distCoeffs[2]", "dist3" }, { "distCoeffs", "dist" },
        { "points1", "points1" }, { "points2", "points2" }, { "points3", "points3" },
        { "lines1", "lines1" }, { "lines2", "lines2" }, { "lines3", "lines3" },
        { "R12", "R12" }, { "t12", "t12" },
    };
    // The subject comes first ("points3 has 2 points but points1 has 3"); at one position the
    // longer name wins ("cameraMatrix[1]" over "cameraMatrix").
    size_t bestAt = std::string::npos, bestLength = 0;
    const char* key = nullptr;
    for (const auto& name : names)
    {
        const size_t at = solverMessage.find(name[0]);
        const size_t length = std::char_traits<char>::length(name[0]);
        if (at != std::string::npos && (at < bestAt || (at == bestAt && length > bestLength)))
        {
            bestAt = at;
            bestLength = length;
            key = name[1];
        }
    }
    return key ? std::string(" (key '") + key + "')" : std::string();
}

std::string temporaryNameFor(const std::string& path)
{
    // Keep the extension: FileStorage picks YAML or JSON from it.
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return path + ".partial";
    return path.substr(0, dot) + ".partial" + path.substr(dot);
}

void commitAtomicWrite(const std::string& temporary, const std::string& path)
{
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path);
    }
}

} // namespace tripose_samples
