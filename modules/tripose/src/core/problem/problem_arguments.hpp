// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_PROBLEM_PROBLEM_ARGUMENTS_HPP
#define TRIPOSE_CORE_PROBLEM_PROBLEM_ARGUMENTS_HPP

#include <string>
#include <vector>

namespace tripose {

/** One argument of the caller as an adapter read it: a matrix of doubles in row-major order
(whatever its type and layout were), with the name the caller knows it by, for errors. Values are
copied as given: NaN and Inf are the core's to judge.
*/
struct ArgumentMatrix
{
    std::string name;
    int rows = 0, cols = 0;
    std::vector<double> values;

    bool empty() const { return rows == 0 || cols == 0; }
    int size() const { return rows * cols; }
};

//! A @p rows x @p cols argument named @p name holding @p values (row-major).
inline ArgumentMatrix matrixArgument(const std::string& name, int rows, int cols, const double* values)
{
    ArgumentMatrix m;
    m.name = name;
    m.rows = rows;
    m.cols = cols;
    m.values.assign(values, values + rows * cols);
    return m;
}

/** The observations of one view: points (Nx2 pixels) and lines (Mx4 segments x0 y0 x1 y1 or Mx3
homogeneous lines a b c); an empty matrix is none of that kind. The adapter has checked the widths.
*/
struct ViewArguments
{
    ArgumentMatrix points, lines;
    bool mayMiss = false; //!< Rows of NaN mark features this view does not see; an empty matrix: sees none.
};

/** The observation and calibration arguments shared by every entry point. Camera matrices and
distortion coefficients are given once for every view or once per view (distortion may also be
absent); @p cameraMatrixName and @p distortionName are the caller's names for them.
*/
struct ProblemArguments
{
    std::vector<ViewArguments> views;
    std::vector<ArgumentMatrix> cameraMatrices; //!< 3x3 each (checked by the adapter).
    std::vector<ArgumentMatrix> distortions;    //!< Vectors (1xK or Kx1).
    std::string cameraMatrixName = "cameraMatrix";
    std::string distortionName = "distCoeffs";
};

} // namespace tripose

#endif // TRIPOSE_CORE_PROBLEM_PROBLEM_ARGUMENTS_HPP
