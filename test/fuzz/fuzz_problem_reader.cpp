// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// libFuzzer target over the problem reader of the command-line tools (samples/common/problem_reader):
// the input is the problem text (YAML or JSON), read strictly and with unknown keys allowed. The
// reader's contract is a Problem or a std::runtime_error naming the key or the line; any other
// exception, a crash, a sanitizer report or a timeout is a bug. What it returns is checked against
// the shapes it promises, and a text both readings accept must give the same problem.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "problem_reader.hpp"

namespace {

[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "tripose fuzz: %s\n", what);
    std::abort();
}

void checkShapes(const tripose_samples::Problem& p)
{
    const size_t views = (size_t)p.numViews();
    if (!(p.K.size() == 1 || p.K.size() == views) || !(p.dist.empty() || p.dist.size() == 1 || p.dist.size() == views))
        fail("readProblemFromString: wrong number of K or dist");
    for (const cv::Mat& K : p.K)
        if (K.rows != 3 || K.cols != 3 || K.type() != CV_64F)
            fail("readProblemFromString: K is not 3x3 CV_64F");
    if (p.R12.total() != 9 && p.R12.total() != 3)
        fail("readProblemFromString: R12 has neither 9 nor 3 elements");
    if (p.t12.total() != 3)
        fail("readProblemFromString: t12 does not have 3 elements");
    for (int v = 0; v < (int)views; ++v)
    {
        // A time-B view of a rig may be empty (it sees none of that kind); every other view has the
        // rows of view 1. Only those time-B views may hold NaN (features they do not see).
        const bool mayMiss = p.stereo && v >= 2;
        const bool pointRows = p.points[v].rows == p.points[0].rows || (mayMiss && p.points[v].rows == 0);
        const bool lineRows = p.lines[v].rows == p.lines[0].rows || (mayMiss && p.lines[v].rows == 0);
        if (p.points[v].cols != 2 || p.lines[v].cols != 4 || !pointRows || !lineRows)
            fail("readProblemFromString: features of inconsistent shape");
        if (!mayMiss && !(cv::checkRange(p.points[v]) && cv::checkRange(p.lines[v])))
            fail("readProblemFromString: NaN or Inf outside the time-B views of a rig");
    }
}

//! The same values in both problems (NaN equal to NaN): the two readings of one text.
bool sameProblem(const tripose_samples::Problem& a, const tripose_samples::Problem& b)
{
    auto same = [](const cv::Mat& x, const cv::Mat& y) {
        if (x.size() != y.size() || x.type() != y.type())
            return false;
        return x.empty() || std::memcmp(x.clone().data, y.clone().data, x.total() * x.elemSize()) == 0;
    };
    if (a.stereo != b.stereo || a.K.size() != b.K.size() || a.dist.size() != b.dist.size() || !same(a.R12, b.R12) ||
        !same(a.t12, b.t12))
        return false;
    for (size_t i = 0; i < a.K.size(); ++i)
        if (!same(a.K[i], b.K[i]))
            return false;
    for (size_t i = 0; i < a.dist.size(); ++i)
        if (!same(a.dist[i], b.dist[i]))
            return false;
    for (int v = 0; v < 4; ++v)
        if (!same(a.points[v], b.points[v]) || !same(a.lines[v], b.lines[v]))
            return false;
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    // Both readings: strict (an unknown key is an error) and with --allow-unknown-keys. A text the
    // strict reader accepts holds no unknown key, so the permissive one must read it the same.
    bool strictRead = false;
    tripose_samples::Problem strict;
    try
    {
        strict = tripose_samples::readProblemFromString(text);
        checkShapes(strict);
        strictRead = true;
    }
    catch (const std::runtime_error&)
    {
    }
    try
    {
        const tripose_samples::Problem permissive = tripose_samples::readProblemFromString(text, true);
        checkShapes(permissive);
        if (strictRead && !sameProblem(strict, permissive))
            fail("readProblemFromString: the strict and the permissive readings differ");
    }
    catch (const std::runtime_error&)
    {
        if (strictRead)
            fail("readProblemFromString: a text read strictly is rejected with --allow-unknown-keys");
    }
    return 0;
}
