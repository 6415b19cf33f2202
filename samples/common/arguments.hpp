// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Command-line values of the tools: parsed whole or rejected with a message naming the argument.
#ifndef TRIPOSE_SAMPLES_ARGUMENTS_HPP
#define TRIPOSE_SAMPLES_ARGUMENTS_HPP

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tripose_samples {

/** The command line as (option, value) pairs, in order. --help or -h prints @p usage and exits; an
option not in @p known or @p flags, or one of @p known without a value, is an argumentError naming
it. A flag (an option of @p flags) takes no value: its pair has an empty value.
*/
std::vector<std::pair<std::string, std::string>> optionPairs(int argc, char** argv, const std::string& usage,
                                                             const std::vector<std::string>& known,
                                                             const std::vector<std::string>& flags = {});

//! "argument <arg>: <what>".
std::runtime_error argumentError(const std::string& arg, const std::string& what);

//! A finite number spanning all of @p value, else argumentError.
double parseNumber(const std::string& arg, const std::string& value);

//! A whole number in [lowest, 2^31 - 1], else argumentError.
int parseInteger(const std::string& arg, const std::string& value, double lowest);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_ARGUMENTS_HPP
