// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "arguments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace tripose_samples {

std::runtime_error argumentError(const std::string& arg, const std::string& what)
{
    return std::runtime_error("argument " + arg + ": " + what);
}

std::vector<std::pair<std::string, std::string>> optionPairs(int argc, char** argv, const std::string& usage,
                                                             const std::vector<std::string>& known,
                                                             const std::vector<std::string>& flags)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::cout << usage;
            std::exit(0);
        }
        if (std::find(flags.begin(), flags.end(), arg) != flags.end())
        {
            pairs.emplace_back(arg, std::string());
            continue;
        }
        if (std::find(known.begin(), known.end(), arg) == known.end())
            throw argumentError(arg, "unknown (see --help)");
        if (i + 1 >= argc)
            throw argumentError(arg, "needs a value");
        pairs.emplace_back(arg, argv[++i]);
    }
    return pairs;
}

double parseNumber(const std::string& arg, const std::string& value)
{
    size_t used = 0;
    double x = 0;
    try
    {
        x = std::stod(value, &used);
    }
    catch (const std::exception&)
    {
        used = 0;
    }
    if (used != value.size() || !std::isfinite(x))
        throw argumentError(arg, "expected a number, got '" + value + "'");
    return x;
}

int parseInteger(const std::string& arg, const std::string& value, double lowest)
{
    const double x = parseNumber(arg, value);
    if (x != std::floor(x) || x < lowest || x > 2147483647.0)
        throw argumentError(arg, lowest >= 0 ? "expected an integer >= " + std::to_string((long long)lowest) + ", got '" + value + "'"
                                             : "expected an integer, got '" + value + "'");
    return (int)x;
}

} // namespace tripose_samples
