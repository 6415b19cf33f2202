// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_pose_common.hpp"

#include <cstdio>
#include <functional>
#include <fstream>
#include <sstream>

#include "opencv2/core/utils/filesystem.hpp"

namespace opencv_test {
namespace {

using cv::tripose::support::VggTriplet;
using cv::tripose::support::loadVggTriplet;
using cv::tripose::support::vggSequenceViewCount;

//! A sequence of the bundled data (test/data/vgg, see ATTRIBUTION.md there) and the number of
//! features seen in all three views of each consecutive triplet (views i, i+1, i+2), counted from
//! its nview-corners / nview-lines files.
struct Sequence
{
    const char* name;
    const char* filePrefix; //!< of the per-sequence files: "bt.", "house." or ""
    const char* viewStem;   //!< printf pattern of a view's file stem
    int firstViewNumber;
    int numViews;
    std::vector<std::pair<int, int>> tripletCounts; //!< (points, lines) per consecutive triplet
};

const std::vector<Sequence>& sequences()
{
    static const std::vector<Sequence> all = {
        { "Corridor", "bt.", "bt.%03d", 0, 11,
          { { 409, 69 }, { 269, 66 }, { 350, 64 }, { 244, 62 }, { 338, 55 }, { 217, 49 }, { 292, 44 }, { 182, 38 }, { 260, 32 } } },
        { "Merton-College-I", "", "%03d", 1, 3, { { 241, 295 } } },
        { "Merton-College-II", "", "%03d", 1, 3, { { 167, 302 } } },
        { "Merton-College-III", "", "%03d", 1, 3, { { 137, 177 } } },
        { "Model-House", "house.", "house.%03d", 0, 10,
          { { 298, 30 }, { 182, 28 }, { 344, 26 }, { 175, 18 }, { 262, 13 }, { 43, 8 }, { 96, 6 }, { 102, 8 } } },
        { "University-Library", "", "%03d", 1, 3, { { 82, 253 } } },
        { "Wadham-College", "", "%03d", 1, 5, { { 78, 282 }, { 41, 256 }, { 22, 238 } } },
    };
    return all;
}

std::string sequenceDir(const Sequence& s)
{
    return findDataDirectory(std::string("vgg/") + s.name);
}

//! Whitespace-separated tokens of the non-blank lines of a text file (independent of the reader).
std::vector<std::vector<std::string>> readTokens(const std::string& path)
{
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line))
    {
        std::istringstream words(line);
        std::vector<std::string> row;
        std::string w;
        while (words >> w)
            row.push_back(w);
        if (!row.empty())
            rows.push_back(row);
    }
    return rows;
}

int countSeenInAll(const std::vector<std::vector<std::string>>& nview, const int views[3])
{
    int count = 0;
    for (const auto& row : nview)
        count += row.at(views[0]) != "*" && row.at(views[1]) != "*" && row.at(views[2]) != "*";
    return count;
}

//! Reprojection of the triplet's 3D structure with its decomposed cameras.
struct Reprojection
{
    std::vector<double> pointErrors[3]; //!< px, per view
    std::vector<double> lineErrors[3];  //!< px, distances of both segment end points to the projected line
    double minDepth = std::numeric_limits<double>::max();
};

Reprojection reproject(const VggTriplet& t)
{
    const Matx33d R[3] = { Matx33d::eye(), toMatx33(t.R12), toMatx33(t.R) };
    const Vec3d tr[3] = { Vec3d(0, 0, 0), toVec3(t.t12), toVec3(t.t) };
    const Mat* points[3] = { &t.points1, &t.points2, &t.points3 };
    const Mat* lines[3] = { &t.lines1, &t.lines2, &t.lines3 };
    Reprojection r;
    for (int v = 0; v < 3; ++v)
    {
        const Matx33d K = toMatx33(t.cameraMatrices[v]);
        auto project = [&](const Vec3d& X) {
            const Vec3d c = R[v] * X + tr[v];
            r.minDepth = std::min(r.minDepth, c[2]);
            return Vec3d(K * c);
        };
        for (int i = 0; i < t.points3d.rows; ++i)
        {
            const Vec3d p = project(Vec3d(t.points3d.ptr<double>(i)));
            const Point2d x(p[0] / p[2], p[1] / p[2]);
            r.pointErrors[v].push_back(cv::norm(x - Point2d(points[v]->at<double>(i, 0), points[v]->at<double>(i, 1))));
        }
        for (int i = 0; i < t.lines3d.rows; ++i)
        {
            const double* L = t.lines3d.ptr<double>(i);
            Vec3d l = project(Vec3d(L[0], L[1], L[2])).cross(project(Vec3d(L[3], L[4], L[5])));
            l *= 1.0 / std::sqrt(l[0] * l[0] + l[1] * l[1]);
            const double* s = lines[v]->ptr<double>(i);
            r.lineErrors[v].push_back(std::abs(l[0] * s[0] + l[1] * s[1] + l[2]));
            r.lineErrors[v].push_back(std::abs(l[0] * s[2] + l[1] * s[3] + l[2]));
        }
    }
    return r;
}

void expectProperRotation(const Mat& m, const std::string& what)
{
    const Matx33d R = toMatx33(m);
    EXPECT_LT(cv::norm(R.t() * R - Matx33d::eye(), NORM_INF), 1e-9) << what;
    EXPECT_NEAR(determinant(R), 1.0, 1e-9) << what;
}

void expectIntrinsic(const Mat& m, const std::string& what)
{
    const Matx33d K = toMatx33(m);
    EXPECT_GT(K(0, 0), 0) << what;
    EXPECT_GT(K(1, 1), 0) << what;
    EXPECT_EQ(K(1, 0), 0) << what;
    EXPECT_EQ(K(2, 0), 0) << what;
    EXPECT_EQ(K(2, 1), 0) << what;
    EXPECT_EQ(K(2, 2), 1) << what;
}

TEST(Tripose_VggDataset, view_counts)
{
    for (const Sequence& s : sequences())
        EXPECT_EQ(vggSequenceViewCount(sequenceDir(s)), s.numViews) << s.name;
}

// Every consecutive triplet of every sequence: documented feature counts, the count found
// independently in the nview files, proper rotations, and the sequence's own reprojection accuracy
// (PROVENANCE.txt: median 0.1-0.7 px) with the decomposed cameras.
TEST(Tripose_VggDataset, every_consecutive_triplet_reprojects_with_the_decomposed_cameras)
{
    for (const Sequence& s : sequences())
    {
        const std::string dir = sequenceDir(s);
        const auto nviewCorners = readTokens(dir + "/" + s.filePrefix + "nview-corners");
        const auto nviewLines = readTokens(dir + "/" + s.filePrefix + "nview-lines");
        ASSERT_EQ((int)s.tripletCounts.size(), s.numViews - 2) << s.name;
        for (int first = 0; first + 2 < s.numViews; ++first)
        {
            const int views[3] = { first, first + 1, first + 2 };
            const std::string where = format("%s views %d %d %d", s.name, views[0], views[1], views[2]);
            const VggTriplet t = loadVggTriplet(dir, views[0], views[1], views[2]);

            EXPECT_EQ(t.points1.rows, s.tripletCounts[first].first) << where;
            EXPECT_EQ(t.lines1.rows, s.tripletCounts[first].second) << where;
            EXPECT_EQ(t.points1.rows, countSeenInAll(nviewCorners, views)) << where;
            EXPECT_EQ(t.lines1.rows, countSeenInAll(nviewLines, views)) << where;

            expectProperRotation(t.R12, where + " R12");
            expectProperRotation(t.R, where + " R");
            ASSERT_EQ(t.cameraMatrices.size(), 3u);
            for (int v = 0; v < 3; ++v)
                expectIntrinsic(t.cameraMatrices[v], where + format(" K%d", v + 1));
            EXPECT_GT(cv::norm(toVec3(t.t12)), 0) << where;

            const Reprojection r = reproject(t);
            EXPECT_GT(r.minDepth, 0) << where << ": structure behind a camera";
            for (int v = 0; v < 3; ++v)
            {
                const double pointMedian = median(r.pointErrors[v]);
                const double lineMedian = median(r.lineErrors[v]);
                EXPECT_LT(pointMedian, 1.0) << where << " view " << v + 1 << " points";
                EXPECT_LT(lineMedian, 1.0) << where << " view " << v + 1 << " lines";
                if (first == 0)
                    std::cout << where << " view " << v + 1 << ": median reprojection " << pointMedian
                              << " px (points), " << lineMedian << " px (segment end points to lines)" << std::endl;
            }
        }
    }
}

// The observations and ids are the rows the nview files point to, read here independently.
TEST(Tripose_VggDataset, observations_are_the_matched_rows_of_the_feature_files)
{
    for (const Sequence& s : sequences())
    {
        const std::string dir = sequenceDir(s);
        const int views[3] = { 2, 0, 1 }; // not in image order
        const VggTriplet t = loadVggTriplet(dir, views[0], views[1], views[2]);
        const auto nviewCorners = readTokens(dir + "/" + s.filePrefix + "nview-corners");
        const auto nviewLines = readTokens(dir + "/" + s.filePrefix + "nview-lines");
        const auto p3d = readTokens(dir + "/" + s.filePrefix + "p3d");
        ASSERT_EQ(t.pointIds.type(), CV_32S);
        ASSERT_EQ(t.lineIds.type(), CV_32S);
        ASSERT_EQ(t.pointIds.rows, countSeenInAll(nviewCorners, views)) << s.name;
        ASSERT_EQ(t.lineIds.rows, countSeenInAll(nviewLines, views)) << s.name;
        const Mat* points[3] = { &t.points1, &t.points2, &t.points3 };
        const Mat* lines[3] = { &t.lines1, &t.lines2, &t.lines3 };
        for (int v = 0; v < 3; ++v)
        {
            const std::string stem = dir + "/" + format(s.viewStem, s.firstViewNumber + views[v]);
            const auto corners = readTokens(stem + ".corners");
            const auto segments = readTokens(stem + ".lines");
            for (int i = 0; i < t.pointIds.rows; ++i)
            {
                const int id = t.pointIds.at<int>(i);
                ASSERT_TRUE(i == 0 || id > t.pointIds.at<int>(i - 1)) << "ids in p3d order";
                const auto& row = corners.at(std::stoi(nviewCorners.at(id).at(views[v])));
                EXPECT_EQ(points[v]->at<double>(i, 0), std::stod(row[0])) << s.name << " point " << id;
                EXPECT_EQ(points[v]->at<double>(i, 1), std::stod(row[1])) << s.name << " point " << id;
            }
            for (int i = 0; i < t.lineIds.rows; ++i)
            {
                const int id = t.lineIds.at<int>(i);
                const auto& row = segments.at(std::stoi(nviewLines.at(id).at(views[v])));
                for (int c = 0; c < 4; ++c)
                    EXPECT_EQ(lines[v]->at<double>(i, c), std::stod(row[c])) << s.name << " line " << id;
            }
        }
        // The 3D points keep their mutual distances (a rigid change of frame, possibly mirrored).
        if (t.pointIds.rows >= 2)
        {
            const int a = t.pointIds.at<int>(0), b = t.pointIds.at<int>(t.pointIds.rows - 1);
            const Vec3d A(std::stod(p3d[a][0]), std::stod(p3d[a][1]), std::stod(p3d[a][2]));
            const Vec3d B(std::stod(p3d[b][0]), std::stod(p3d[b][1]), std::stod(p3d[b][2]));
            const double d = cv::norm(Vec3d(t.points3d.ptr<double>(0)) - Vec3d(t.points3d.ptr<double>(t.points3d.rows - 1)));
            EXPECT_NEAR(d, cv::norm(A - B), 1e-9 * (1 + cv::norm(A - B))) << s.name;
        }
        ASSERT_GT(t.pointIds.rows, 0) << s.name;
        const Reprojection r = reproject(t);
        for (int v = 0; v < 3; ++v)
            EXPECT_LT(median(r.pointErrors[v]), 1.0) << s.name << " view " << v + 1;
    }
}

// Two overlapping triplets describe the same cameras: the pose of view 2 relative to view 1
// follows from the poses of views 1 and 2 relative to view 0 (also across the mirrored frames).
TEST(Tripose_VggDataset, overlapping_triplets_agree)
{
    for (const char* name : { "Corridor", "Model-House", "Wadham-College" })
    {
        const std::string dir = findDataDirectory(std::string("vgg/") + name);
        const VggTriplet a = loadVggTriplet(dir, 0, 1, 2);
        const VggTriplet b = loadVggTriplet(dir, 1, 2, 3);
        const Matx33d R01 = toMatx33(a.R12), R02 = toMatx33(a.R);
        const Vec3d t01 = toVec3(a.t12), t02 = toVec3(a.t);
        const Matx33d R12 = R02 * R01.t();
        const Vec3d t12 = t02 - R12 * t01;
        EXPECT_LT(cv::norm(R12 - toMatx33(b.R12), NORM_INF), 1e-9) << name;
        EXPECT_LT(cv::norm(t12 - toVec3(b.t12)), 1e-9 * (1 + cv::norm(t12))) << name;
        EXPECT_LT(cv::norm(a.cameraMatrices[1], b.cameraMatrices[0], NORM_INF), 1e-9) << name;
    }
}

std::string expectThrowMessage(const std::function<void()>& call)
{
    try
    {
        call();
    }
    catch (const cv::Exception& e)
    {
        return e.msg;
    }
    ADD_FAILURE() << "no cv::Exception";
    return std::string();
}

// The whole sequence says what its triplets say: the same observations of the features seen in all
// three views, and the same relative poses and intrinsics.
TEST(Tripose_VggDataset, sequence_agrees_with_its_triplets)
{
    for (const char* name : { "Corridor", "Model-House", "Wadham-College" })
    {
        const std::string dir = findDataDirectory(std::string("vgg/") + name);
        const cv::tripose::support::VggSequence seq = cv::tripose::support::loadVggSequence(dir);
        ASSERT_EQ(vggSequenceViewCount(dir), (int)seq.Rs.size()) << name;
        const int views[3] = { 0, 2, 4 };
        const VggTriplet triplet = loadVggTriplet(dir, views[0], views[1], views[2]);
        const Mat* points[3] = { &triplet.points1, &triplet.points2, &triplet.points3 };
        const Mat* lines[3] = { &triplet.lines1, &triplet.lines2, &triplet.lines3 };
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_LT(cv::norm(seq.cameraMatrices[views[k]], triplet.cameraMatrices[k], NORM_INF), 1e-12) << name;
            for (int i = 0; i < triplet.pointIds.rows; ++i)
                EXPECT_EQ(0, cv::norm(seq.points[views[k]].row(triplet.pointIds.at<int>(i)), points[k]->row(i), NORM_INF))
                    << name << " view " << views[k] << " point " << i;
            for (int i = 0; i < triplet.lineIds.rows; ++i)
                EXPECT_EQ(0, cv::norm(seq.lines[views[k]].row(triplet.lineIds.at<int>(i)), lines[k]->row(i), NORM_INF))
                    << name << " view " << views[k] << " line " << i;
        }
        // Features not seen in a view are NaN rows there; the triplet keeps those seen in all three.
        int seenInAll = 0;
        for (int i = 0; i < seq.points3d.rows; ++i)
        {
            bool all = true;
            for (int k = 0; k < 3; ++k)
                all = all && !std::isnan(seq.points[views[k]].at<double>(i, 0));
            seenInAll += all ? 1 : 0;
        }
        EXPECT_EQ(triplet.pointIds.rows, seenInAll) << name;
        // Poses relative to view 0 of the sequence, those of the triplet relative to its first view.
        const Matx33d R0 = toMatx33(seq.Rs[views[0]]), R1 = toMatx33(seq.Rs[views[1]]), R2 = toMatx33(seq.Rs[views[2]]);
        const Vec3d t0 = toVec3(seq.ts[views[0]]), t1 = toVec3(seq.ts[views[1]]), t2 = toVec3(seq.ts[views[2]]);
        EXPECT_LT(cv::norm(R0 - Matx33d::eye(), NORM_INF), 1e-12) << name;
        EXPECT_LT(cv::norm(t0), 1e-12) << name;
        EXPECT_LT(cv::norm(R1 - toMatx33(triplet.R12), NORM_INF), 1e-9) << name;
        EXPECT_LT(cv::norm(t1 - toVec3(triplet.t12)), 1e-9 * (1 + cv::norm(t1))) << name;
        EXPECT_LT(cv::norm(R2 - toMatx33(triplet.R), NORM_INF), 1e-9) << name;
        EXPECT_LT(cv::norm(t2 - toVec3(triplet.t)), 1e-9 * (1 + cv::norm(t2))) << name;
    }
}

TEST(Tripose_VggDataset, sequence_folder_errors_are_named)
{
    const std::string message = expectThrowMessage([] { cv::tripose::support::loadVggSequence("/nonexistent-sequence"); });
    EXPECT_NE(std::string::npos, message.find("/nonexistent-sequence")) << message;
}

TEST(Tripose_VggDataset, bad_arguments_are_named)
{
    const std::string dir = findDataDirectory("vgg/Merton-College-III");
    std::string msg = expectThrowMessage([&] { loadVggTriplet(dir, 0, 1, 3); });
    EXPECT_NE(msg.find("view3"), std::string::npos) << msg;
    msg = expectThrowMessage([&] { loadVggTriplet(dir, -1, 1, 2); });
    EXPECT_NE(msg.find("view1"), std::string::npos) << msg;
    msg = expectThrowMessage([&] { loadVggTriplet(dir, 0, 1, 1); });
    EXPECT_NE(msg.find("view2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("view3"), std::string::npos) << msg;

    const std::string missing = dir + "-does-not-exist";
    msg = expectThrowMessage([&] { loadVggTriplet(missing, 0, 1, 2); });
    EXPECT_NE(msg.find(missing), std::string::npos) << msg;
    msg = expectThrowMessage([&] { vggSequenceViewCount(missing); });
    EXPECT_NE(msg.find(missing), std::string::npos) << msg;
}

//! A writable copy of a bundled sequence (text files only), removed at the end of the test.
class SequenceCopy
{
public:
    explicit SequenceCopy(const std::string& name)
    {
        const std::string source = findDataDirectory("vgg/" + name);
        dir_ = cv::tempfile("_tripose_vgg");
        CV_Assert(utils::fs::createDirectories(dir_));
        std::vector<String> files;
        utils::fs::glob_relative(source, "", files, false, false);
        for (const String& f : files)
            if (f.size() < 4 || f.compare(f.size() - 4, 4, ".jpg") != 0)
                write(f, readFile(utils::fs::join(source, f)));
    }
    ~SequenceCopy() { utils::fs::remove_all(dir_); }
    std::string dir() const { return dir_; }
    std::string file(const std::string& name) const { return utils::fs::join(dir_, name); }
    void write(const std::string& name, const std::string& text) const
    {
        std::ofstream out(file(name), std::ios::binary | std::ios::trunc);
        out << text;
        CV_Assert(out.good());
    }
    std::string read(const std::string& name) const { return readFile(file(name)); }
    void remove(const std::string& name) const { CV_Assert(std::remove(file(name).c_str()) == 0); }

private:
    static std::string readFile(const std::string& path)
    {
        std::ifstream in(path, std::ios::binary);
        CV_Assert(in.good());
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    std::string dir_;
};

std::string replaceAll(std::string text, const std::string& from, const std::string& to)
{
    for (size_t pos = text.find(from); pos != std::string::npos; pos = text.find(from, pos + to.size()))
        text.replace(pos, from.size(), to);
    return text;
}

//! The text with line @p index (0-based) replaced.
std::string replaceLine(const std::string& text, int index, const std::string& line)
{
    std::istringstream in(text);
    std::string out, current;
    for (int i = 0; std::getline(in, current); ++i)
        out += (i == index ? line : current) + "\n";
    return out;
}

void expectSameTriplet(const VggTriplet& a, const VggTriplet& b)
{
    for (const auto& pair : { std::make_pair(&a.points1, &b.points1), std::make_pair(&a.lines3, &b.lines3),
                              std::make_pair(&a.points3d, &b.points3d), std::make_pair(&a.lines3d, &b.lines3d),
                              std::make_pair(&a.R, &b.R), std::make_pair(&a.t, &b.t), std::make_pair(&a.R12, &b.R12) })
    {
        ASSERT_EQ(pair.first->size(), pair.second->size());
        EXPECT_LT(cv::norm(*pair.first, *pair.second, NORM_INF), 1e-9);
    }
}

void expectNamed(const std::string& dir, const std::vector<std::string>& names)
{
    const std::string msg = expectThrowMessage([&] { loadVggTriplet(dir, 0, 1, 2); });
    for (const std::string& name : names)
        EXPECT_NE(msg.find(name), std::string::npos) << "message does not name '" << name << "': " << msg;
}

TEST(Tripose_VggDataset, missing_or_malformed_files_are_named)
{
    const std::string name = "Merton-College-III";
    {
        SequenceCopy copy(name);
        copy.remove("002.lines");
        expectNamed(copy.dir(), { "002.lines" });
    }
    {
        SequenceCopy copy(name);
        copy.remove("nview-corners");
        expectNamed(copy.dir(), { "nview-corners" });
    }
    {
        SequenceCopy copy(name);
        copy.write("p3d", replaceLine(copy.read("p3d"), 4, "1.0 abc 3.0"));
        expectNamed(copy.dir(), { "p3d", "line 5" });
    }
    {
        SequenceCopy copy(name);
        copy.write("l3d", replaceLine(copy.read("l3d"), 0, "1 2 3 4 5"));
        expectNamed(copy.dir(), { "l3d", "line 1" });
    }
    {
        SequenceCopy copy(name);
        copy.write("nview-corners", replaceLine(copy.read("nview-corners"), 2, "0 99999 *"));
        expectNamed(copy.dir(), { "nview-corners", "002.corners" });
    }
    {
        SequenceCopy copy(name);
        copy.write("nview-lines", replaceLine(copy.read("nview-lines"), 2, "0 1"));
        expectNamed(copy.dir(), { "nview-lines", "line 3" });
    }
    {
        SequenceCopy copy(name);
        const std::string p3d = copy.read("p3d");
        copy.write("p3d", p3d.substr(0, p3d.rfind('\n', p3d.size() - 2) + 1)); // one point fewer
        expectNamed(copy.dir(), { "nview-corners", "p3d" });
    }
    {
        SequenceCopy copy(name);
        const std::string P = copy.read("003.P");
        copy.write("003.P", P.substr(0, P.rfind('\n', P.size() - 2) + 1)); // two rows
        expectNamed(copy.dir(), { "003.P" });
    }
}

// Variants of the same data read identically: Windows line ends and blank lines, '-1' for unseen
// (as in other copies of the data set), a camera matrix of the opposite overall sign.
TEST(Tripose_VggDataset, equivalent_spellings_read_the_same)
{
    for (const char* name : { "Merton-College-III", "Model-House" })
    {
        const VggTriplet reference = loadVggTriplet(findDataDirectory(std::string("vgg/") + name), 0, 1, 2);
        const std::string prefix = std::string(name) == "Model-House" ? "house." : "";
        const std::string secondView = std::string(name) == "Model-House" ? "house.001" : "002";
        SequenceCopy copy(name);
        copy.write(prefix + "p3d", "\n" + replaceAll(copy.read(prefix + "p3d"), "\n", "\r\n") + "\n\n");
        copy.write(prefix + "nview-corners", replaceAll(copy.read(prefix + "nview-corners"), "*", "-1"));
        copy.write(prefix + "nview-lines", replaceAll(copy.read(prefix + "nview-lines"), "*", "-1"));
        double P[12];
        std::istringstream in(copy.read(secondView + ".P"));
        for (double& p : P)
            ASSERT_TRUE(static_cast<bool>(in >> p));
        std::ostringstream negated;
        negated.precision(17);
        for (int i = 0; i < 12; ++i)
            negated << -P[i] << (i % 4 == 3 ? "\n" : " ");
        copy.write(secondView + ".P", negated.str());
        SCOPED_TRACE(name);
        expectSameTriplet(reference, loadVggTriplet(copy.dir(), 0, 1, 2));
    }
}

}} // namespace opencv_test::namespace
