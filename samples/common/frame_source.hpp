// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The frames of a sequence as users keep them: a folder of images, a video file, or a text file
// listing image paths.
#ifndef TRIPOSE_SAMPLES_FRAME_SOURCE_HPP
#define TRIPOSE_SAMPLES_FRAME_SOURCE_HPP

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

struct SourceFrame
{
    int index = 0;
    double timestamp = 0; //!< Seconds: the video's position, the list's first column, else the index.
    std::string name;     //!< The file, or "<video>#<index>".
    cv::Mat image;        //!< 8-bit, grey or colour; empty when it could not be read or decoded.
    std::string error;    //!< Why the image is empty.
};

/** Opens @p source: a folder (its image files in natural name order: img2 before img10), a video file
(any container OpenCV's videoio decodes), or a list file (one image path per line, relative to the
list's folder, optionally preceded by a timestamp; blank lines and lines starting with # skipped).
Throws std::runtime_error naming @p source when it cannot be opened or holds no frame. */
class FrameSource
{
public:
    explicit FrameSource(const std::string& source);
    ~FrameSource();
    //! The next frame; false after the last.
    bool next(SourceFrame& frame);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_FRAME_SOURCE_HPP
