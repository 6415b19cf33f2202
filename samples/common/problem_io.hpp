// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Problem and result files of the command-line tools: the problem schema (problem_schema.hpp), its
// reader (problem_reader.hpp; YAML and JSON read with libyaml) and the atomic writing of output files
// (file_output.hpp). Results are written with cv::FileStorage (YAML or JSON, chosen by the file name's
// extension).
#ifndef TRIPOSE_SAMPLES_PROBLEM_IO_HPP
#define TRIPOSE_SAMPLES_PROBLEM_IO_HPP

#include "file_output.hpp"
#include "problem_reader.hpp"
#include "problem_schema.hpp"

#endif // TRIPOSE_SAMPLES_PROBLEM_IO_HPP
