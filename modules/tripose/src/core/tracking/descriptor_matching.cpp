// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "descriptor_matching.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Eigen/Core>

namespace tripose {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

int hamming(const uint8_t* x, const uint8_t* y, int bytes)
{
    int d = 0, c = 0;
    for (; c + 8 <= bytes; c += 8)
    {
        uint64_t u, v;
        std::memcpy(&u, x + c, 8);
        std::memcpy(&v, y + c, 8);
        d += __builtin_popcountll(u ^ v);
    }
    for (; c < bytes; ++c)
        d += __builtin_popcount((unsigned)(x[c] ^ y[c]));
    return d;
}

using RowMatrixf = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

} // namespace

double Descriptors::distance(int i, const Descriptors& other, int j) const
{
    if (binary)
        return hamming(bits.data() + (size_t)i * cols, other.bits.data() + (size_t)j * cols, cols);
    const float* x = real.data() + (size_t)i * cols;
    const float* y = other.real.data() + (size_t)j * cols;
    double d = 0;
    for (int c = 0; c < cols; ++c)
    {
        const double e = (double)x[c] - (double)y[c];
        d += e * e;
    }
    return std::sqrt(d);
}

Descriptors Descriptors::subset(const std::vector<int>& rowsKept) const
{
    Descriptors out;
    out.rows = (int)rowsKept.size();
    out.cols = cols;
    out.binary = binary;
    for (int r : rowsKept)
    {
        if (binary)
            out.bits.insert(out.bits.end(), bits.begin() + (size_t)r * cols, bits.begin() + (size_t)(r + 1) * cols);
        else
            out.real.insert(out.real.end(), real.begin() + (size_t)r * cols, real.begin() + (size_t)(r + 1) * cols);
    }
    return out;
}

MutualBest::MutualBest(int rowsA, int rowsB)
    : bestOfA_(rowsA, -1), bestOfB_(rowsB, -1), bestDistanceOfA_(rowsA, kInf), secondOfA_(rowsA, kInf),
      bestDistanceOfB_(rowsB, kInf)
{
}

void MutualBest::add(int a, int b, double distance)
{
    if (distance < bestDistanceOfA_[a])
    {
        secondOfA_[a] = bestDistanceOfA_[a];
        bestDistanceOfA_[a] = distance;
        bestOfA_[a] = b;
    }
    else if (distance < secondOfA_[a])
        secondOfA_[a] = distance;
    if (distance < bestDistanceOfB_[b])
    {
        bestDistanceOfB_[b] = distance;
        bestOfB_[b] = a;
    }
}

Matches MutualBest::result(double ratio) const
{
    Matches matches;
    for (int a = 0; a < (int)bestOfA_.size(); ++a)
    {
        const int b = bestOfA_[a];
        if (b < 0 || bestOfB_[b] != a)
            continue;
        if (std::isfinite(secondOfA_[a]) && !(bestDistanceOfA_[a] < ratio * secondOfA_[a]))
            continue;
        matches.emplace_back(a, b);
    }
    return matches;
}

Matches matchByDescriptor(const Descriptors& a, const Descriptors& b, double ratio, double maxDistance)
{
    if (a.empty() || b.empty() || a.binary != b.binary || a.cols != b.cols)
        return {};
    MutualBest best(a.rows, b.rows);
    if (a.binary)
    {
        for (int i = 0; i < a.rows; ++i)
            for (int j = 0; j < b.rows; ++j)
            {
                const double d = a.distance(i, b, j);
                if (d <= maxDistance)
                    best.add(i, j, d);
            }
        return best.result(ratio);
    }
    // Squared L2 distances as |x|^2 + |y|^2 - 2 x.y: one matrix product over blocks of rows of a.
    const Eigen::Map<const RowMatrixf> A(a.real.data(), a.rows, a.cols), B(b.real.data(), b.rows, b.cols);
    const Eigen::VectorXf normsB = B.rowwise().squaredNorm();
    const int block = 512;
    for (int start = 0; start < a.rows; start += block)
    {
        const int n = std::min(block, a.rows - start);
        const RowMatrixf products = A.middleRows(start, n) * B.transpose();
        for (int i = 0; i < n; ++i)
        {
            const float normA = A.row(start + i).squaredNorm();
            for (int j = 0; j < b.rows; ++j)
            {
                const double d = std::sqrt(std::max(0.0f, normA + normsB[j] - 2 * products(i, j)));
                if (d <= maxDistance)
                    best.add(start + i, j, d);
            }
        }
    }
    return best.result(ratio);
}

} // namespace tripose
