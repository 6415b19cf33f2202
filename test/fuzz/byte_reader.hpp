// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Fixed-size values read in order from the front of a fuzz input. Past the end every value is
// zero, so that any input decodes to some problem and a short seed stays valid.
#ifndef TRIPOSE_FUZZ_BYTE_READER_HPP
#define TRIPOSE_FUZZ_BYTE_READER_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace tripose_fuzz {

class ByteReader
{
public:
    ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

    uint8_t byte()
    {
        uint8_t b = 0;
        take(&b, 1);
        return b;
    }

    //! 8 bytes as an IEEE double in the machine's (little-endian) order: any bits, NaN and Inf included.
    double number()
    {
        double x = 0;
        take(&x, sizeof(x));
        return x;
    }

private:
    void take(void* out, size_t n)
    {
        const size_t available = offset_ < size_ ? size_ - offset_ : 0;
        const size_t copied = n < available ? n : available;
        if (copied > 0)
            std::memcpy(out, data_ + offset_, copied);
        std::memset(static_cast<uint8_t*>(out) + copied, 0, n - copied);
        offset_ += n;
    }

    const uint8_t* data_;
    size_t size_;
    size_t offset_ = 0;
};

} // namespace tripose_fuzz

#endif // TRIPOSE_FUZZ_BYTE_READER_HPP
