// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Output files of the command-line tools, written atomically (a temporary name first, renamed when
// complete), and the check that an output can be written before a tool's work starts.
#ifndef TRIPOSE_SAMPLES_FILE_OUTPUT_HPP
#define TRIPOSE_SAMPLES_FILE_OUTPUT_HPP

#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

//! Writes a FileStorage file atomically: to a temporary name first, renamed when complete.
//! @p write fills the storage.
template <typename Writer>
void writeAtomically(const std::string& path, Writer write);

void commitAtomicWrite(const std::string& temporary, const std::string& path);

/** Throws std::runtime_error naming @p option and @p path when the file cannot be written there (no
such folder, a folder of that name, no permission): checked before a tool's work, so that a long run
does not end in "cannot write" with nothing, or part of its output, written. It creates and removes
the temporary file that writeAtomically() would write. An empty @p path (an optional output not
asked for) passes. */
void checkWritable(const std::string& path, const std::string& option);

//! Writes @p bytes (an encoded image, ...) to @p path atomically, as writeAtomically().
void writeFileAtomically(const std::string& path, const std::vector<unsigned char>& bytes);
std::string temporaryNameFor(const std::string& path);

template <typename Writer>
void writeAtomically(const std::string& path, Writer write)
{
    const std::string temporary = temporaryNameFor(path);
    {
        cv::FileStorage fs(temporary, cv::FileStorage::WRITE);
        if (!fs.isOpened())
            throw std::runtime_error("cannot write " + path);
        write(fs);
    }
    commitAtomicWrite(temporary, path);
}

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_FILE_OUTPUT_HPP
