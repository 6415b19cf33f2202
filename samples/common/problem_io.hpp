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

//! The inputs of estimatePoseLinePoint (three views) or estimatePoseLinePointStereo (a stereo rig,
//! four views) as read from a problem file.
struct Problem
{
    bool stereo = false;        //!< points4 or lines4 given: views 1-2 and 3-4 are a rig at two times.
    std::vector<cv::Mat> K;     //!< One 3x3 matrix (key K) or one per view (K1..K3, rig: K1..K4).
    std::vector<cv::Mat> dist;  //!< Empty, one (dist) or one per view (dist1..dist3, rig: dist1..dist4).
    cv::Mat R12, t12;           //!< Pose of view 2; for a rig, the rig (right camera w.r.t. left).
    cv::Mat points[4];          //!< Nx2 (0x2 when absent); [3] only for a rig.
    cv::Mat lines[4];           //!< Mx4 (0x4 when absent); [3] only for a rig.
    int numViews() const { return stereo ? 4 : 3; }
};

/** Reads a problem from FileStorage text (YAML, with or without OpenCV's "%YAML:1.0" first line, or
JSON; told apart by the text itself, not the file name). Keys: K or K1..K3; optional dist or
dist1..dist3; R12 (3x3 or 3x1 Rodrigues), t12; points1..points3 (Nx2) and lines1..lines3 (Mx4), each
kind absent or empty in all views when not used. With points4 and/or lines4
the problem is a stereo rig (see estimatePoseLinePointStereo): K1..K4 and dist1..dist4 per view,
and in points3, points4, lines3 and lines4 a row of NaN (.nan) marks a feature that view does not
see (an absent key: the view sees none of that kind); every row count equals points1's or lines1's.
Matrices are FileStorage's (rows, cols, dt, data). Any other key (at the top level: not one of
problemFileKeys(); in a matrix: not one of FileStorage's fields) is an error naming it and the
nearest known key, unless @p allowUnknownKeys (a file that carries other data). With @p poseOptional,
R12 and t12 may both be absent (a calibration whose poses come from elsewhere; both left empty). Throws
std::runtime_error on text that is not YAML or JSON ("cannot parse", with the line), and naming the
key on any unknown, malformed or inconsistent entry.
*/
Problem readProblem(const std::string& path, bool allowUnknownKeys = false, bool poseOptional = false);

/** A stereo rig's calibration: the left camera K1 (optional dist1), the right camera K2 (dist2), or
K and dist shared by both, and the rig R12 (3x3 or 3x1 Rodrigues), t12: the right camera's pose
relative to the left (x_2 = R12 x_1 + t12). Other problem keys pass; any other key, and a missing or
malformed one, throw std::runtime_error naming it (readProblem()'s messages).
*/
struct StereoCalibration
{
    cv::Mat K[2], dist[2]; //!< Left, right; dist empty when not given.
    cv::Mat R12, t12;
};
StereoCalibration readStereoCalibration(const std::string& path);

//! The same from text in memory (used by the fuzzer).
Problem readProblemFromString(const std::string& text, bool allowUnknownKeys = false);

//! The top-level keys a problem file may hold: those readProblem reads, and the ground truth
//! tripose_make_scene writes beside them (R_gt, t_gt, points3d, ...).
std::vector<std::string> problemFileKeys();

//! The key of @p valid nearest to @p key in edits (insertions, deletions, substitutions, swaps of
//! neighbours) when it is near enough to be a typo (a third of the key's length, at least one), else "".
std::string closestKey(const std::string& key, const std::vector<std::string>& valid);

/** Throws std::runtime_error "unknown key 'point1' in <file> (did you mean 'points1'?)" for the first
of @p keys not in @p valid; with @p parent, "unknown key 'row' of 'K1' in <file> ...". Without a near
key the message lists the valid ones.
*/
void checkKeys(const std::vector<std::string>& keys, const std::vector<std::string>& valid, const std::string& file,
               const std::string& parent = "");

/** Writes the keys of a three-view problem (K or K1..K3, dist or dist1..dist3 when given, R12, t12,
points1..points3 and lines1..lines3, a kind left out when it has no rows), as readProblem() reads them.
*/
void writeProblem(cv::FileStorage& fs, const Problem& problem);

//! An inlier mask of the robust estimators as an Nx1 CV_32S column (0x1 when empty), as the result files hold it.
cv::Mat inlierColumn(const cv::Mat& mask);

/** The problem key behind the argument a solver message names, as " (key 'K2')", or "" when it names
none: the solver speaks of cameraMatrix[1] and distCoeffs, the file of K2 and dist.
*/
std::string problemKeyNamedBy(const std::string& solverMessage);

//! Writes a FileStorage file atomically: to a temporary name first, renamed when complete.
//! @p write fills the storage.
template <typename Writer>
void writeAtomically(const std::string& path, Writer write);

void commitAtomicWrite(const std::string& temporary, const std::string& path);

/** Throws std::runtime_error naming @p option and @p path when the file cannot be written there (no
such folder, a folder of that name, no permission): checked before a tool's work, so that a long run
does not end in "cannot write" with nothing, or part of its output, written. It creates and removes
the temporary file that writeAtomically() would write. An empty @p path (an optional output not
asked for) passes. */
void checkWritable(const std::string& path, const std::string& option);

//! Writes @p bytes (an encoded image, ...) to @p path atomically, as writeAtomically().
void writeFileAtomically(const std::string& path, const std::vector<unsigned char>& bytes);
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
