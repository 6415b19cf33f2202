// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "problem_reader.hpp"

#include <yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <stdexcept>

namespace tripose_samples {

namespace {

/** One node of a problem text: a scalar, a sequence or a mapping. The nodes of a text live in one
array and name each other by index, so that nothing (building, looking up, freeing) recurses as
deep as the text nests.
*/
struct Node
{
    enum Kind { Scalar, Sequence, Mapping };
    Kind kind = Scalar;
    bool plain = false;  //!< A scalar without quotes: a number, a name or null. Quoted, it is a string.
    std::string text;    //!< A scalar's value.
    int line = 0;        //!< 1-based, for messages.
    std::vector<size_t> items;                            //!< A sequence's nodes.
    std::vector<std::pair<std::string, size_t>> entries;  //!< A mapping's keys and their nodes, in order.
};

template <size_t N>
bool listed(const char* const (&names)[N], const std::string& name)
{
    return std::find(std::begin(names), std::end(names), name) != std::end(names);
}

//! A problem text: its nodes and the keys of its top level (of every document, when it has several).
struct Text
{
    std::vector<Node> nodes;
    std::map<std::string, size_t> keys;
    std::vector<std::string> keyOrder;  //!< The top-level keys as the text gives them, for messages.
    std::string what;                   //!< The file (or "the problem text"), for messages.
    bool allowUnknownKeys = false;      //!< Keys that are not in kProblemKeys, kSceneKeys (or a matrix's fields) pass.
    bool poseOptional = false;          //!< R12 and t12 may both be absent (a calibration without the pose).

    const Node* find(const std::string& key) const
    {
        if (!listed(kProblemKeys, key))
            throw std::logic_error("problem reader: key '" + key + "' is read but not listed in kProblemKeys");
        const auto it = keys.find(key);
        return it == keys.end() ? nullptr : &nodes[it->second];
    }

    //! The entry @p name of a mapping, or nullptr.
    const Node* field(const Node& mapping, const char* name) const
    {
        for (const auto& entry : mapping.entries)
            if (entry.first == name)
                return &nodes[entry.second];
        return nullptr;
    }
};

std::runtime_error keyError(const std::string& key, const std::string& what)
{
    return std::runtime_error("key '" + key + "': " + what);
}

std::runtime_error parseError(const std::string& what, const std::string& message)
{
    return std::runtime_error("cannot parse " + what + ": " + message);
}

const char* const kNotAMap = "the problem must be a map of keys (K, R12, t12, points1, ...) at the top level";

//! A node for a message: a scalar quoted (and cut short when long), else what it is.
std::string describe(const Node& node)
{
    if (node.kind == Node::Sequence)
        return "a list";
    if (node.kind == Node::Mapping)
        return "a map";
    return "'" + (node.text.size() > 40 ? node.text.substr(0, 40) + "..." : node.text) + "'" +
           (node.plain ? "" : " (quoted: a string)");
}

/** libyaml's account of why it stopped: where (line and column, 1-based) and what, in its words. */
std::string libyamlProblem(const yaml_parser_t& parser, const std::string& text)
{
    const std::string problem = parser.problem ? parser.problem : "malformed text";
    switch (parser.error)
    {
    case YAML_MEMORY_ERROR:
        return "out of memory";
    case YAML_READER_ERROR:
    {
        // The reader (encoding, control characters) gives a byte offset, not a line.
        const size_t offset = std::min(parser.problem_offset, text.size());
        size_t line = 1, lineStart = 0;
        for (size_t i = 0; i < offset; ++i)
            if (text[i] == '\n')
            {
                ++line;
                lineStart = i + 1;
            }
        std::string message = cv::format("line %zu, column %zu: %s", line, offset - lineStart + 1, problem.c_str());
        if (parser.problem_value >= 0)
            message += cv::format(" (character 0x%X)", (unsigned)parser.problem_value);
        return message;
    }
    default:
    {
        std::string message = cv::format("line %zu, column %zu: %s", parser.problem_mark.line + 1,
                                         parser.problem_mark.column + 1, problem.c_str());
        if (parser.context)
            message += cv::format(" (%s from line %zu)", parser.context, parser.context_mark.line + 1);
        return message;
    }
    }
}

//! Nesting deeper than this is refused; a problem file nests three levels (keys, matrix, data).
const int kMaxDepth = 32;

/** The text as libyaml is to read it, or a parseError. OpenCV writes "%YAML:1.0" as its first line,
which is not YAML ("%YAML 1.x", of which libyaml knows 1.1 and 1.2 only); FileStorage accepts
"%YAML:1.x" and "%YAML 1.x" there, and that line becomes a comment of the same length, so that lines
and columns in messages stay those of the file. Every other directive (a line starting with '%',
after any of the line breaks libyaml knows) is refused before parsing: libyaml compares each %TAG
directive with all earlier ones, time that grows with the square of their number.
*/
std::string prepareText(const std::string& text, const std::string& what)
{
    std::string out = text;
    const size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 byte order mark
    if (text.compare(start, 5, "%YAML") == 0)
    {
        if (text.compare(start, 8, "%YAML:1.") != 0 && text.compare(start, 8, "%YAML 1.") != 0)
            throw parseError(what, "line 1: unsupported YAML version (an OpenCV file starts with %YAML:1.0)");
        out[start] = '#';
    }
    int line = 1;
    for (size_t i = start; i < out.size(); ++i)
    {
        if (out[i] == '%')
            throw parseError(what, cv::format("line %d: directives (lines starting with %%) are not read, "
                                              "apart from OpenCV's %%YAML:1.0 first line", line));
        // Skip to the next line: \n, \r, \r\n, and NEL, LS, PS in UTF-8.
        for (; i < out.size(); ++i)
        {
            if (out[i] == '\r' || out[i] == '\n')
            {
                i += out[i] == '\r' && i + 1 < out.size() && out[i + 1] == '\n';
                break;
            }
            if (out.compare(i, 2, "\xC2\x85") == 0)
            {
                i += 1;
                break;
            }
            if (out.compare(i, 3, "\xE2\x80\xA8") == 0 || out.compare(i, 3, "\xE2\x80\xA9") == 0)
            {
                i += 2;
                break;
            }
        }
        ++line;
    }
    return out;
}

/** Parses YAML or JSON (which libyaml reads as YAML) into a Text. libyaml turns the text into
events and says where it is malformed; the nodes are built from the events with a stack of the open
collections, one step per event. What would make the work grow faster than the text is refused:
aliases (*name: a node met twice), directives (see prepareText) and nesting deeper than kMaxDepth
(libyaml's scanner checks every open flow collection at every token; it reads at most a line or
1024 characters ahead of the events, so stopping at the first event too deep bounds that check).
*/
Text parseText(const std::string& original, const std::string& what)
{
    // gzip's magic number: FileStorage reads compressed files, this reader does not.
    if (original.size() >= 2 && (unsigned char)original[0] == 0x1F && (unsigned char)original[1] == 0x8B)
        throw parseError(what, "it is gzip-compressed; decompress it first");
    if (original.compare(0, 5, "<?xml") == 0)
        throw parseError(what, "XML problem files are not read; write YAML or JSON");
    const std::string text = prepareText(original, what);

    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser))
        throw parseError(what, "out of memory");
    const std::unique_ptr<yaml_parser_t, void (*)(yaml_parser_t*)> parserOwner(&parser, yaml_parser_delete);
    yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
    // UTF-8 only (as FileStorage): prepareText looked for directives in UTF-8.
    yaml_parser_set_encoding(&parser, YAML_UTF8_ENCODING);

    struct Open
    {
        size_t node;
        std::string name;               //!< Where it is, for messages: the key it is under.
        bool keyNext = true;            //!< A mapping expects a key (else the value of key).
        std::string key;
        std::map<std::string, int> seen;  //!< A mapping's keys so far, with their lines.
    };
    Text out;
    std::vector<size_t> documents;
    std::vector<Open> open;
    // Places node @p index (just created) in the collection being read, or as a document.
    auto place = [&](size_t index) {
        if (open.empty())
            documents.push_back(index);
        else if (out.nodes[open.back().node].kind == Node::Sequence)
            out.nodes[open.back().node].items.push_back(index);
        else
        {
            out.nodes[open.back().node].entries.emplace_back(std::move(open.back().key), index);
            open.back().keyNext = true;
        }
    };
    for (bool done = false; !done;)
    {
        yaml_event_t event;
        if (!yaml_parser_parse(&parser, &event))
            throw parseError(what, libyamlProblem(parser, text));
        const std::unique_ptr<yaml_event_t, void (*)(yaml_event_t*)> eventOwner(&event, yaml_event_delete);
        const int line = (int)event.start_mark.line + 1;
        const bool atKey = !open.empty() && out.nodes[open.back().node].kind == Node::Mapping && open.back().keyNext;
        switch (event.type)
        {
        case YAML_STREAM_END_EVENT:
            done = true;
            break;
        case YAML_ALIAS_EVENT:
            throw parseError(what, cv::format("line %d: aliases (*name) are not supported; write the value out", line));
        case YAML_SCALAR_EVENT:
        {
            std::string value(reinterpret_cast<const char*>(event.data.scalar.value), event.data.scalar.length);
            if (atKey)
            {
                Open& mapping = open.back();
                const auto previous = mapping.seen.emplace(value, line);
                if (!previous.second)
                    throw parseError(what, cv::format("key '%s'%s is given twice (lines %d and %d)",
                                                      value.c_str(),
                                                      mapping.name.empty() ? "" : (" of '" + mapping.name + "'").c_str(),
                                                      previous.first->second, line));
                mapping.key = std::move(value);
                mapping.keyNext = false;
                break;
            }
            Node node;
            node.kind = Node::Scalar;
            node.plain = event.data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
            node.text = std::move(value);
            node.line = line;
            out.nodes.push_back(std::move(node));
            place(out.nodes.size() - 1);
            break;
        }
        case YAML_SEQUENCE_START_EVENT:
        case YAML_MAPPING_START_EVENT:
        {
            if (atKey)
                throw parseError(what, cv::format("line %d: a key must be a name, not a list or a map", line));
            if ((int)open.size() >= kMaxDepth)
                throw parseError(what, cv::format("line %d: nested deeper than %d levels", line, kMaxDepth));
            Node node;
            node.kind = event.type == YAML_SEQUENCE_START_EVENT ? Node::Sequence : Node::Mapping;
            node.line = line;
            out.nodes.push_back(std::move(node));
            Open collection;
            collection.node = out.nodes.size() - 1;
            if (!open.empty())
                collection.name = out.nodes[open.back().node].kind == Node::Mapping ? open.back().key : open.back().name;
            place(collection.node);
            open.push_back(std::move(collection));
            break;
        }
        case YAML_SEQUENCE_END_EVENT:
        case YAML_MAPPING_END_EVENT:
            open.pop_back();
            break;
        default:  // stream and document start, document end: nothing to build
            break;
        }
    }

    // The top level: one map; several documents (FileStorage's append mode) read as one map.
    if (documents.empty())
        throw std::runtime_error(kNotAMap);
    for (size_t document : documents)
    {
        const Node& root = out.nodes[document];
        if (root.kind != Node::Mapping)
            throw std::runtime_error(kNotAMap);
        for (const auto& entry : root.entries)
        {
            if (!out.keys.emplace(entry.first, entry.second).second)
                throw parseError(what, cv::format("key '%s' is given twice (lines %d and %d)", entry.first.c_str(),
                                                  out.nodes[out.keys[entry.first]].line, out.nodes[entry.second].line));
            out.keyOrder.push_back(entry.first);
        }
    }
    out.what = what;
    return out;
}

bool isNull(const Node& node)
{
    return node.kind == Node::Scalar && node.plain &&
           (node.text.empty() || node.text == "~" || node.text == "null" || node.text == "Null" || node.text == "NULL");
}

//! A whole number in [0, 2^31 - 1] written as such (no quotes, no fraction), else -1.
int toCount(const Node* node)
{
    if (!node || node->kind != Node::Scalar || !node->plain || node->text.empty())
        return -1;
    const char* begin = node->text.data() + (node->text[0] == '+');
    const char* end = node->text.data() + node->text.size();
    long long value = -1;
    const auto parsed = std::from_chars(begin, end, value);
    return parsed.ec == std::errc() && parsed.ptr == end && value >= 0 && value <= INT_MAX ? (int)value : -1;
}

//! A number as OpenCV writes it (also .Nan, .Inf and -.Inf), without quotes.
bool toReal(const Node& node, double& value)
{
    if (node.kind != Node::Scalar || !node.plain || node.text.empty())
        return false;
    std::string text = node.text;
    for (char& c : text)
        c = (char)std::tolower((unsigned char)c);
    if (text == ".nan")
        text = "nan";
    else if (text == ".inf" || text == "+.inf")
        text = "inf";
    else if (text == "-.inf")
        text = "-inf";
    const char* begin = text.data() + (text[0] == '+');
    const char* end = text.data() + text.size();
    const auto parsed = std::from_chars(begin, end, value);
    if (parsed.ec == std::errc::result_out_of_range && parsed.ptr == end)
    {
        // Beyond double's range (e.g. 1e400, 1e-400): what strtod gives, an infinity or a tiny
        // number, through the wider type.
        long double wide = 0;
        const auto again = std::from_chars(begin, end, wide);
        value = (double)wide;
        return again.ec == std::errc() && again.ptr == end;
    }
    return parsed.ec == std::errc() && parsed.ptr == end;
}

/** The element type under dt ("d", "f", "3d", ...: an optional channel count and one of OpenCV's
type letters), or false.
*/
bool toElementType(const Node* node, int& depth, int& channels)
{
    if (!node || node->kind != Node::Scalar || node->text.empty())
        return false;
    const std::string& dt = node->text;
    static const char letters[] = "ucwsifdh";
    static const int depths[] = { CV_8U, CV_8S, CV_16U, CV_16S, CV_32S, CV_32F, CV_64F, CV_16F };
    const char* letter = std::strchr(letters, dt.back());
    if (!letter || !*letter)
        return false;
    depth = depths[letter - letters];
    channels = 1;
    if (dt.size() == 1)
        return true;
    const auto parsed = std::from_chars(dt.data(), dt.data() + dt.size() - 1, channels);
    return parsed.ec == std::errc() && parsed.ptr == dt.data() + dt.size() - 1 && channels >= 1 && channels <= CV_CN_MAX;
}

//! True when every value is finite, or NaN where @p nanAllowed.
bool finiteOrMissing(const cv::Mat& m, bool nanAllowed)
{
    const double* p = m.ptr<double>();
    for (size_t i = 0, n = m.total(); i < n; ++i)
        if (!std::isfinite(p[i]) && !(nanAllowed && std::isnan(p[i])))
            return false;
    return true;
}

/** A matrix under @p key, as FileStorage writes one (YAML: a !!opencv-matrix mapping; JSON: an
object with "type_id": "opencv-matrix"; both with rows, cols, dt, data, or sizes for rows and cols),
converted to CV_64F; an empty one when the key is absent, null or has no elements. NaN (.nan) is
accepted where @p nanMarksMissing (the time-B observations of a rig, where a row of NaN marks a
feature the view does not see; the solver checks that rows are whole), Inf nowhere.
*/
cv::Mat readMatrix(const Text& text, const std::string& key, bool nanMarksMissing = false)
{
    const Node* node = text.find(key);
    if (!node || isNull(*node))
        return cv::Mat();
    if (node->kind != Node::Mapping)
        throw keyError(key, "expected an OpenCV matrix (!!opencv-matrix with rows, cols, dt, data)");
    if (!text.allowUnknownKeys)
    {
        // A misspelt field (row, date) would otherwise read as a missing one.
        std::vector<std::string> fields;
        for (const auto& entry : node->entries)
            fields.push_back(entry.first);
        checkKeys(fields, std::vector<std::string>(std::begin(kMatrixFields), std::end(kMatrixFields)), text.what, key);
    }
    int rows = -1, cols = -1;
    const Node* sizes = text.field(*node, "sizes");
    if (sizes && !isNull(*sizes))
    {
        if (sizes->kind != Node::Sequence || sizes->items.empty() || sizes->items.size() > 2)
            throw keyError(key, "malformed matrix header: sizes must list one or two non-negative integers");
        rows = toCount(&text.nodes[sizes->items[0]]);
        cols = sizes->items.size() == 2 ? toCount(&text.nodes[sizes->items[1]]) : 1;
    }
    else
    {
        rows = toCount(text.field(*node, "rows"));
        cols = toCount(text.field(*node, "cols"));
    }
    if (rows < 0 || cols < 0)
        throw keyError(key, "malformed matrix header: rows and cols (or sizes) must be non-negative integers");
    int depth = CV_64F, channels = 1;
    if (!toElementType(text.field(*node, "dt"), depth, channels))
        throw keyError(key, "malformed matrix header: dt must name the element type (d for double, f for float, ...)");

    // data: a list of numbers, or one number alone (as FileStorage reads it).
    std::vector<const Node*> values;
    const Node* data = text.field(*node, "data");
    if (data && data->kind == Node::Sequence)
        for (size_t item : data->items)
            values.push_back(&text.nodes[item]);
    else if (data && data->kind == Node::Scalar && !isNull(*data))
        values.push_back(data);
    else if (data && data->kind == Node::Mapping)
        throw keyError(key, "malformed matrix: data must be a list of numbers");
    const double declared = double(rows) * cols * channels;
    if (declared != (double)values.size())
        throw keyError(key, cv::format("malformed matrix: the header declares %.0f elements but data holds %zu values",
                                       declared, values.size()));
    if (declared == 0)
        return cv::Mat();
    if (channels != 1)
        throw keyError(key, "expected a 1-channel matrix");

    cv::Mat m(rows, cols, CV_64F);
    double* out = m.ptr<double>();
    for (size_t i = 0; i < values.size(); ++i)
        if (!toReal(*values[i], out[i]))
            throw keyError(key, cv::format("malformed matrix: data value %zu is not a number: %s", i + 1,
                                           describe(*values[i]).c_str()));
    if (!finiteOrMissing(m, nanMarksMissing))
        throw keyError(key, nanMarksMissing ? "contains Inf values" : "contains NaN or Inf values");
    if (depth != CV_64F)
    {
        // The values a matrix of the declared type holds (rounded, saturated), as FileStorage reads them.
        cv::Mat declaredType;
        m.convertTo(declaredType, depth);
        declaredType.convertTo(m, CV_64F);
        if (!finiteOrMissing(m, nanMarksMissing))
            throw keyError(key, nanMarksMissing ? "contains Inf values" : "contains NaN or Inf values");
    }
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

//! One key (e.g. K) or one per view (K1..K3, or K1..K4 for a rig); not both.
std::vector<cv::Mat> readShared(const Text& text, const std::string& key, bool required, int numViews)
{
    const cv::Mat shared = readMatrix(text, key);
    cv::Mat perView[4];
    int present = 0;
    for (int v = 0; v < numViews; ++v)
    {
        perView[v] = readMatrix(text, key + std::to_string(v + 1));
        present += !perView[v].empty();
    }
    const std::string range = key + "1.." + key + std::to_string(numViews);
    const char* const views = numViews == 4 ? "four" : "three";
    if (!shared.empty() && present > 0)
        throw keyError(key, "give either " + key + " or " + range + ", not both");
    if (!shared.empty())
        return { shared };
    if (present == numViews)
        return std::vector<cv::Mat>(perView, perView + numViews);
    for (int v = 0; v < numViews && present > 0; ++v)
        if (perView[v].empty())
            throw keyError(key + std::to_string(v + 1),
                           std::string("missing (per-view ") + key + " needs all " + views + " views)");
    if (required)
        throw keyError(key, "missing (give " + key + " or " + range + ")");
    return {};
}

/** points1..points<numViews> or lines1..: each absent/empty (no features of that kind in that view)
or with the given width, and the same rows as in view 1. Views 1 and 2 see every feature: for
three views (and for views 1-2 of a rig) a kind is absent in all views or present in all. In the
time-B views of a rig, rows of NaN are accepted (features not seen) and an absent key is a view
that sees none of that kind.
*/
void readFeatures(const Text& text, const std::string& prefix, int width, int numViews, cv::Mat out[4])
{
    for (int v = 0; v < numViews; ++v)
    {
        const std::string key = prefix + std::to_string(v + 1);
        const bool mayMiss = numViews == 4 && v >= 2;
        out[v] = readMatrix(text, key, mayMiss);
        if (out[v].empty())
            out[v] = cv::Mat(0, width, CV_64F);
        else if (out[v].cols != width)
            throw keyError(key, cv::format("expected %d columns, got %dx%d", width, out[v].rows, out[v].cols));
    }
    for (int v = 1; v < numViews; ++v)
    {
        const bool mayMiss = numViews == 4 && v >= 2;
        if (out[v].rows != out[0].rows && !(mayMiss && out[v].rows == 0))
            throw keyError(prefix + std::to_string(v + 1),
                           cv::format("has %d rows but %s1 has %d", out[v].rows, prefix.c_str(), out[0].rows));
    }
}

bool hasMatrix(const Text& text, const std::string& key)
{
    const Node* node = text.find(key);
    return node && !isNull(*node);
}

Problem readFromText(const Text& text)
{
    // Unknown keys first: a misspelt key (point1) would otherwise read as an absent one and be
    // reported, if at all, as a count or shape of the keys around it.
    if (!text.allowUnknownKeys)
        checkKeys(text.keyOrder, problemFileKeys(), text.what);
    Problem p;
    p.stereo = hasMatrix(text, "points4") || hasMatrix(text, "lines4");
    const int numViews = p.numViews();
    p.K = readShared(text, "K", true, numViews);
    for (size_t v = 0; v < p.K.size(); ++v)
        requireShape(p.K[v], p.K.size() == 1 ? "K" : "K" + std::to_string(v + 1), 3, 3);
    p.dist = readShared(text, "dist", false, numViews);
    p.R12 = readMatrix(text, "R12");
    if (text.poseOptional && p.R12.empty() && !hasMatrix(text, "t12"))
    {
        readFeatures(text, "points", 2, numViews, p.points);
        readFeatures(text, "lines", 4, numViews, p.lines);
        return p;
    }
    if (p.R12.empty() || !(p.R12.total() == 9 || p.R12.total() == 3))
        throw keyError("R12", p.R12.empty() ? "missing" : "expected 3x3 rotation or 3x1 Rodrigues vector");
    p.t12 = readMatrix(text, "t12");
    if (p.t12.total() != 3)
        throw keyError("t12", p.t12.empty() ? "missing" : "expected 3x1");
    readFeatures(text, "points", 2, numViews, p.points);
    readFeatures(text, "lines", 4, numViews, p.lines);
    return p;
}

} // namespace

namespace {

std::string readFileText(const std::string& path)
{
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file)
        throw std::runtime_error("cannot open " + path);
    std::string text;
    char buffer[65536];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;)
        text.append(buffer, n);
    if (std::ferror(file.get()))
        throw std::runtime_error("cannot read " + path);
    return text;
}

//! K (dist) for both cameras, or K1 and K2 (dist1 and dist2); empty where optional and absent.
void readRigShared(const Text& text, const std::string& key, bool required, cv::Mat out[2])
{
    const cv::Mat shared = readMatrix(text, key);
    const cv::Mat first = readMatrix(text, key + "1"), second = readMatrix(text, key + "2");
    if (!shared.empty() && (!first.empty() || !second.empty()))
        throw keyError(key, "give either " + key + " (both cameras) or " + key + "1 and " + key + "2, not both");
    if (!shared.empty())
    {
        out[0] = out[1] = shared;
        return;
    }
    if (first.empty() != second.empty() || (required && first.empty()))
        throw keyError(first.empty() ? key + "1" : key + "2",
                       "missing (the " + std::string(first.empty() ? "left" : "right") + " camera's; give " + key +
                           "1 and " + key + "2, or " + key + " for both)");
    out[0] = first;
    out[1] = second;
}

} // namespace

StereoCalibration readStereoCalibration(const std::string& path)
{
    const Text text = parseText(readFileText(path), path);
    checkKeys(text.keyOrder, problemFileKeys(), text.what);
    StereoCalibration c;
    readRigShared(text, "K", true, c.K);
    for (int v = 0; v < 2; ++v)
        requireShape(c.K[v], "K" + std::to_string(v + 1), 3, 3);
    readRigShared(text, "dist", false, c.dist);
    c.R12 = readMatrix(text, "R12");
    if (c.R12.empty() || !(c.R12.total() == 9 || c.R12.total() == 3))
        throw keyError("R12", c.R12.empty() ? "missing (the rig: the right camera's rotation relative to the left)"
                                            : "expected 3x3 rotation or 3x1 Rodrigues vector");
    c.t12 = readMatrix(text, "t12");
    if (c.t12.total() != 3)
        throw keyError("t12", c.t12.empty() ? "missing (the rig: the right camera's translation relative to the left)"
                                            : "expected 3x1");
    if (cv::norm(c.t12) == 0)
        throw keyError("t12", "zero: the rig's baseline fixes the scale");
    return c;
}

Problem readProblem(const std::string& path, bool allowUnknownKeys, bool poseOptional)
{
    Text parsed = parseText(readFileText(path), path);
    parsed.allowUnknownKeys = allowUnknownKeys;
    parsed.poseOptional = poseOptional;
    return readFromText(parsed);
}

Problem readProblemFromString(const std::string& text, bool allowUnknownKeys)
{
    Text parsed = parseText(text, "the problem text");
    parsed.allowUnknownKeys = allowUnknownKeys;
    return readFromText(parsed);
}

} // namespace tripose_samples
