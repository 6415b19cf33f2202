// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "problem_schema.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace tripose_samples {

std::vector<std::string> problemFileKeys()
{
    std::vector<std::string> keys(std::begin(kProblemKeys), std::end(kProblemKeys));
    keys.insert(keys.end(), std::begin(kSceneKeys), std::end(kSceneKeys));
    return keys;
}

size_t editDistance(const std::string& a, const std::string& b)
{
    // Insertions, deletions, substitutions and swaps of two neighbours (R21 for R12), each one edit:
    // the optimal string alignment distance, over the whole table (keys are short).
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j)
        {
            d[i][j] = std::min({ d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1) });
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

std::string closestKey(const std::string& key, const std::vector<std::string>& valid)
{
    // Near enough to be a slip of the keyboard: a third of the key's length, at least one edit.
    const size_t limit = std::max<size_t>(1, key.size() / 3);
    std::string best;
    size_t bestDistance = limit + 1;
    for (const std::string& candidate : valid)
    {
        const size_t d = editDistance(key, candidate);
        if (d < bestDistance)
        {
            bestDistance = d;
            best = candidate;
        }
    }
    return best;
}

void checkKeys(const std::vector<std::string>& keys, const std::vector<std::string>& valid, const std::string& file,
               const std::string& parent)
{
    for (const std::string& key : keys)
    {
        if (std::find(valid.begin(), valid.end(), key) != valid.end())
            continue;
        std::string message = "unknown key '" + key + "'" + (parent.empty() ? "" : " of '" + parent + "'") + " in " + file;
        const std::string suggestion = closestKey(key, valid);
        if (!suggestion.empty())
            message += " (did you mean '" + suggestion + "'?)";
        else
        {
            message += " (known keys:";
            for (size_t i = 0; i < valid.size(); ++i)
                message += (i ? ", " : " ") + valid[i];
            message += "; --allow-unknown-keys reads a file that carries other data)";
        }
        throw std::runtime_error(message);
    }
}

std::string problemKeyNamedBy(const std::string& solverMessage)
{
    static const char* const names[][2] = {
        { "cameraMatrix[0]", "K1" }, { "cameraMatrix[1]", "K2" }, { "cameraMatrix[2]", "K3" },
        { "cameraMatrix[3]", "K4" }, { "cameraMatrix", "K" },
        { "distCoeffs[0]", "dist1" }, { "distCoeffs[1]", "dist2" }, { "distCoeffs[2]", "dist3" },
        { "distCoeffs[3]", "dist4" }, { "distCoeffs", "dist" },
        { "points1", "points1" }, { "points2", "points2" }, { "points3", "points3" }, { "points4", "points4" },
        { "lines1", "lines1" }, { "lines2", "lines2" }, { "lines3", "lines3" }, { "lines4", "lines4" },
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

void writeProblem(cv::FileStorage& fs, const Problem& problem)
{
    CV_Assert(!problem.stereo);
    const auto writeShared = [&](const std::string& key, const std::vector<cv::Mat>& perView) {
        if (perView.size() == 1)
            fs << key << perView[0];
        else
            for (size_t v = 0; v < perView.size(); ++v)
                fs << key + std::to_string(v + 1) << perView[v];
    };
    writeShared("K", problem.K);
    writeShared("dist", problem.dist);
    fs << "R12" << problem.R12 << "t12" << problem.t12;
    for (int v = 0; v < 3; ++v)
        if (problem.points[0].rows > 0)
            fs << "points" + std::to_string(v + 1) << problem.points[v];
    for (int v = 0; v < 3; ++v)
        if (problem.lines[0].rows > 0)
            fs << "lines" + std::to_string(v + 1) << problem.lines[v];
}

cv::Mat inlierColumn(const cv::Mat& mask)
{
    cv::Mat column = mask.empty() ? cv::Mat(0, 1, CV_32S) : cv::Mat(mask.reshape(1, (int)mask.total()));
    column.convertTo(column, CV_32S);
    return column;
}

} // namespace tripose_samples
