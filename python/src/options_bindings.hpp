// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_OPTIONS_BINDINGS_HPP
#define TRIPOSE_PYTHON_OPTIONS_BINDINGS_HPP

#include <string>

#include <nanobind/nanobind.h>

#include "support/options.hpp"

//! The option classes RefineOptions, RansacOptions, MatchOptions and TrackerOptions (before the
//! functions and classes that take them).
void bindOptions(nanobind::module_& m);

/** The caller's RansacOptions (the defaults for None), checked: errors name a field as
"<name>.<field>" in Python's words, or the field alone when @p name is empty (the keyword
arguments of earlier releases). */
tripose::RansacOptions checkedRansacOptions(const tripose::RansacOptions* given, const std::string& name);

//! The caller's RefineOptions (the defaults for None), checked and named as checkedRansacOptions().
tripose::RefineOptions checkedRefineOptions(const tripose::RefineOptions* given, const std::string& name);

#endif // TRIPOSE_PYTHON_OPTIONS_BINDINGS_HPP
