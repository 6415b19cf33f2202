// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The reader of problem files, in OpenCV FileStorage's YAML or JSON. Problems are read with libyaml
// (YAML and JSON alike), whose parser returns on any text.
#ifndef TRIPOSE_SAMPLES_PROBLEM_READER_HPP
#define TRIPOSE_SAMPLES_PROBLEM_READER_HPP

#include <string>

#include "problem_schema.hpp"

namespace tripose_samples {

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

/** Reads a stereo rig's calibration (StereoCalibration). Other problem keys pass; any other key, and a
missing or malformed one, throw std::runtime_error naming it (readProblem()'s messages).
*/
StereoCalibration readStereoCalibration(const std::string& path);

//! The same from text in memory (used by the fuzzer).
Problem readProblemFromString(const std::string& text, bool allowUnknownKeys = false);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_PROBLEM_READER_HPP
