// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_ARRAY_CONVERSIONS_HPP
#define TRIPOSE_PYTHON_ARRAY_CONVERSIONS_HPP

// The estimators' arrays: the caller's numpy arrays (or nested lists) read into the core's
// ArgumentMatrix, and the core's results written out as numpy arrays. Shared by the three-view,
// stereo-rig and several-views bindings; every check of a value beyond its shape is the core's.

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nanobind/nanobind.h>

#include "estimator/scored_pose.hpp"
#include "problem/problem_arguments.hpp"

namespace array_conversions {

namespace nb = nanobind;

bool isSequence(nb::handle object);

/** K (one 3x3, a sequence of one per view, or an array of shape (V, 3, 3)) and dist (None, one
vector, or a sequence of one per view) into @p args, named "K", "K[v]", "dist", "dist[v]".
*/
void readCalibration(nb::handle K, nb::handle dist, tripose::ProblemArguments& args);

//! A 3x3 rotation matrix or a rotation vector of 3 elements (the core checks the values).
tripose::ArgumentMatrix readRotation(nb::handle object, const std::string& name);

//! 3 elements, any shape.
tripose::ArgumentMatrix readTranslation(nb::handle object, const std::string& name);

//! Points (Nx2) and lines (Mx4 segments / Mx3 homogeneous) of one view; None or empty: none.
tripose::ViewArguments readView(nb::handle points, nb::handle lines, const std::string& pointsName,
                                const std::string& linesName, bool mayMiss);

//! A list of one array per view (or None: no feature of that kind in any view).
std::vector<nb::object> readViewList(nb::handle object, const char* name, size_t numViews);

//! A list of rotations (@p rotations) or translations, each named "<name>[k]".
std::vector<tripose::ArgumentMatrix> readPoseList(nb::handle object, const char* name, bool rotations);

//! A new float64 numpy array of @p shape holding @p values (row-major).
nb::object newArray(std::initializer_list<size_t> shape, const double* values);

nb::object rotationArray(const Eigen::Matrix3d& R);

nb::object vectorArray(const Eigen::Vector3d& t);

//! A bool array, true where @p mask is nonzero.
nb::object maskArray(const std::vector<unsigned char>& mask);

//! The candidates as a list of (R, t) pairs.
nb::list candidateList(const std::vector<tripose::ScoredPose>& candidates);

//! The refined structure as (points3d (N, 3), lines3d (M, 6): two points of each line).
std::pair<nb::object, nb::object> structureArrays(const std::vector<Eigen::Vector3d>& pointList,
                                                  const std::vector<Eigen::Vector3d>& lineEnds, int numPoints,
                                                  int numLines);

//! structureArrays() into @p out's "points3d" and "lines3d".
void writeStructure(const std::vector<Eigen::Vector3d>& pointList, const std::vector<Eigen::Vector3d>& lineEnds,
                    int numPoints, int numLines, nb::dict& out);

} // namespace array_conversions

#endif // TRIPOSE_PYTHON_ARRAY_CONVERSIONS_HPP
