// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_TRACKING_CONVERSIONS_HPP
#define TRIPOSE_PYTHON_TRACKING_CONVERSIONS_HPP

// The arrays of python/tripose/tracking.py (bytes and shapes it has checked) to the core's types and
// back, shared by the trackers' bindings.

#include <cstring>
#include <initializer_list>
#include <vector>

#include <Eigen/Core>
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include "tracking/frame_features.hpp"

namespace tracking_conversions {

namespace nb = nanobind;

/** A C-contiguous array of the caller's as python/tripose/tracking.py passes it: its bytes and its
shape (that layer has checked both). */
struct Block
{
    const char* data;
    size_t rows, cols;

    Block(const nb::bytes& bytes, size_t rows, size_t cols, size_t itemSize)
        : data(bytes.c_str()), rows(rows), cols(cols)
    {
        if (bytes.size() != rows * cols * itemSize)
            throw nb::value_error("array bytes do not match their shape");
    }
    template <class T>
    T at(size_t r, size_t c) const
    {
        T value;
        std::memcpy(&value, data + (r * cols + c) * sizeof(T), sizeof(T));
        return value;
    }
};

inline nb::object array(const double* values, std::initializer_list<size_t> shape)
{
    size_t n = 1;
    for (size_t s : shape)
        n *= s;
    double* data = new double[n];
    std::memcpy(data, values, n * sizeof(double));
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<double*>(p); });
    return nb::cast(nb::ndarray<nb::numpy, double>(data, shape, owner));
}

inline nb::object intArray(const std::vector<int>& values)
{
    int64_t* data = new int64_t[values.size() ? values.size() : 1];
    for (size_t i = 0; i < values.size(); ++i)
        data[i] = values[i];
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<int64_t*>(p); });
    return nb::cast(nb::ndarray<nb::numpy, int64_t>(data, { values.size() }, owner));
}

inline nb::object rotation(const Eigen::Matrix3d& R)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMajor = R;
    return array(rowMajor.data(), { 3, 3 });
}

//! Float64 rows of width @p W.
template <int W>
inline std::vector<Eigen::Matrix<double, W, 1>> vectors(const nb::bytes& bytes, size_t rows)
{
    const Block block(bytes, rows, W, sizeof(double));
    std::vector<Eigen::Matrix<double, W, 1>> out(rows);
    for (size_t i = 0; i < rows; ++i)
        for (int c = 0; c < W; ++c)
            out[i][c] = block.at<double>(i, c);
    return out;
}

//! Float32 rows, or uint8 rows when @p binary.
inline tripose::Descriptors descriptors(const nb::bytes& bytes, size_t rows, size_t cols, bool binary)
{
    const Block block(bytes, rows, cols, binary ? 1 : sizeof(float));
    tripose::Descriptors d;
    d.rows = (int)rows;
    d.cols = (int)cols;
    d.binary = binary;
    if (binary)
        d.bits.assign(block.data, block.data + rows * cols);
    else
    {
        d.real.resize(rows * cols);
        std::memcpy(d.real.data(), block.data, rows * cols * sizeof(float));
    }
    return d;
}

//! A 3x3 float64 matrix.
inline Eigen::Matrix3d matrix3(const nb::bytes& bytes)
{
    const Block block(bytes, 3, 3, sizeof(double));
    Eigen::Matrix3d M;
    for (int i = 0; i < 9; ++i)
        M(i / 3, i % 3) = block.at<double>(i / 3, i % 3);
    return M;
}

} // namespace tracking_conversions

#endif // TRIPOSE_PYTHON_TRACKING_CONVERSIONS_HPP
