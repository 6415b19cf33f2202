// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_SUPPORT_RANDOM_HPP
#define TRIPOSE_CORE_SUPPORT_RANDOM_HPP

#include <cstdint>

namespace tripose {

/** The sampler's random numbers: a 64-bit multiply-with-carry generator (multiplier 4164903690).

A seeded run must give the same result on every platform, compiler and standard library, and
the same as the OpenCV-based releases did for a seed; the <random> engines' distributions are
not specified bit for bit, and this generator is the one those releases drew from.
*/
class Random
{
public:
    explicit Random(uint64_t seed) : state_(seed ? seed : 0xffffffffu) {}

    //! The next 32 random bits.
    uint32_t next()
    {
        state_ = (uint64_t)(uint32_t)state_ * kMultiplier + (uint32_t)(state_ >> 32);
        return (uint32_t)state_;
    }

    //! An integer uniformly distributed in [@p low, @p high) (@p low when the range is empty).
    int uniform(int low, int high)
    {
        return low == high ? low : (int)(next() % (uint32_t)(high - low) + (uint32_t)low);
    }

private:
    static constexpr uint64_t kMultiplier = 4164903690u;
    uint64_t state_;
};

} // namespace tripose

#endif // TRIPOSE_CORE_SUPPORT_RANDOM_HPP
