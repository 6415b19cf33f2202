// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Problem and result files of the command-line tools, in OpenCV FileStorage's YAML or JSON. Problems
// are read with libyaml (YAML and JSON alike), whose parser returns on any text; results are written
// with cv::FileStorage (YAML or JSON, chosen by the file name's extension).
#ifndef TRIPOSE_SAMPLES_PROBLEM_IO_HPP
#define TRIPOSE_SAMPLES_PROBLEM_IO_HPP

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

//! The inputs of estimatePoseLinePoint as read from a problem file.
struct Problem
{
    std::vector<cv::Mat> K;     //!< One 3x3 matrix (key K) or three (K1, K2, K3).
    std::vector<cv::Mat> dist;  //!< Empty, one (dist) or three (dist1..dist3).
    cv::Mat R12, t12;
    cv::Mat points[3];          //!< Nx2 (0x2 when absent).
    cv::Mat lines[3];           //!< Mx4 (0x4 when absent).
};

/** Reads a problem from FileStorage text (YAML, with or without OpenCV's "%YAML:1.0" first line, or
JSON; told apart by the text itself, not the file name). Keys: K or K1..K3; optional dist or
dist1..dist3; R12 (3x3 or 3x1 Rodrigues), t12; points1..points3 (Nx2) and lines1..lines3 (Mx4), each
kind absent or empty in all views when not used; other keys are ignored. Matrices are FileStorage's
(rows, cols, dt, data). Throws std::runtime_error on text that is not YAML or JSON ("cannot parse",
with the line), and naming the key on any malformed or inconsistent entry.
*/
Problem readProblem(const std::string& path);

//! The same from text in memory (used by the fuzzer).
Problem readProblemFromString(const std::string& text);

/** The problem key behind the argument a solver message names, as " (key 'K2')", or "" when it names
none: the solver speaks of cameraMatrix[1] and distCoeffs, the file of K2 and dist.
*/
std::string problemKeyNamedBy(const std::string& solverMessage);

//! Writes a FileStorage file atomically: to a temporary name first, renamed when complete.
//! @p write fills the storage.
template <typename Writer>
void writeAtomically(const std::string& path, Writer write);

void commitAtomicWrite(const std::string& temporary, const std::string& path);
std::string temporaryNameFor(const std::string& path);

template <typename Writer>
void writeAtomically(const std::string& path, Writer write)
{
    const std::string temporary = temporaryNameFor(path);
    {
        cv::FileStorage fs(temporary, cv::FileStorage::WRITE);
        if (!fs.isOpened())
            throw std::runtime_error("cannot write " + path);
        write(fs);
    }
    commitAtomicWrite(temporary, path);
}

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_PROBLEM_IO_HPP
