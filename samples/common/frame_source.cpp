// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "frame_source.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>

#include <opencv2/videoio.hpp>

#include "image_input.hpp"

namespace tripose_samples {

namespace {

bool isDirectory(const std::string& path)
{
    struct stat s;
    return stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

//! Natural order: runs of digits compare by their value, so that img2 comes before img10.
bool naturalLess(const std::string& a, const std::string& b)
{
    size_t i = 0, j = 0;
    while (i < a.size() && j < b.size())
    {
        if (std::isdigit((unsigned char)a[i]) && std::isdigit((unsigned char)b[j]))
        {
            size_t ei = i, ej = j;
            while (ei < a.size() && std::isdigit((unsigned char)a[ei]))
                ++ei;
            while (ej < b.size() && std::isdigit((unsigned char)b[ej]))
                ++ej;
            const std::string na = a.substr(i, ei - i), nb = b.substr(j, ej - j);
            const size_t za = na.find_first_not_of('0'), zb = nb.find_first_not_of('0');
            const std::string va = za == std::string::npos ? "" : na.substr(za);
            const std::string vb = zb == std::string::npos ? "" : nb.substr(zb);
            if (va.size() != vb.size())
                return va.size() < vb.size();
            if (va != vb)
                return va < vb;
            i = ei;
            j = ej;
            continue;
        }
        if (a[i] != b[j])
            return a[i] < b[j];
        ++i;
        ++j;
    }
    return a.size() - i < b.size() - j;
}

bool isTextFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    char buffer[512];
    in.read(buffer, sizeof buffer);
    const std::streamsize n = in.gcount();
    for (std::streamsize k = 0; k < n; ++k)
        if (buffer[k] == 0)
            return false;
    return n > 0;
}

std::string folderOf(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

} // namespace

struct FrameSource::Impl
{
    std::vector<std::string> files;
    std::vector<double> timestamps;
    cv::VideoCapture video;
    std::string videoName;
    int index = 0;
};

FrameSource::FrameSource(const std::string& source) : impl_(new Impl)
{
    if (isDirectory(source))
    {
        impl_->files = imageFilesIn(source);
        std::sort(impl_->files.begin(), impl_->files.end(), naturalLess);
        if (impl_->files.empty())
            throw std::runtime_error(source + ": the folder holds no image (.png, .jpg, .jpeg, .pgm, .ppm, .bmp, .tif, .tiff)");
        return;
    }
    std::ifstream probe(source);
    if (!probe)
        throw std::runtime_error(source + ": cannot open (not a folder, video or list file that can be read)");
    if (isTextFile(source))
    {
        std::string line;
        int number = 0;
        while (std::getline(probe, line))
        {
            ++number;
            const size_t first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#')
                continue;
            std::istringstream fields(line.substr(first));
            std::string a, b;
            fields >> a >> b;
            double timestamp = (double)impl_->files.size();
            std::string path = a;
            if (!b.empty())
            {
                try
                {
                    size_t used = 0;
                    timestamp = std::stod(a, &used);
                    if (used != a.size())
                        throw std::invalid_argument(a);
                }
                catch (const std::exception&)
                {
                    throw std::runtime_error(source + ":" + std::to_string(number) + ": expected 'path' or "
                                             "'timestamp path', got '" + line + "'");
                }
                path = b;
            }
            if (path[0] != '/')
                path = folderOf(source) + "/" + path;
            impl_->files.push_back(path);
            impl_->timestamps.push_back(timestamp);
        }
        if (impl_->files.empty())
            throw std::runtime_error(source + ": the list names no image");
        return;
    }
    if (!impl_->video.open(source) || !impl_->video.isOpened())
        throw std::runtime_error(source + ": cannot open as a video (or as a folder or list of images)");
    impl_->videoName = source;
}

FrameSource::~FrameSource() = default;

bool FrameSource::next(SourceFrame& frame)
{
    frame = SourceFrame();
    frame.index = impl_->index;
    if (!impl_->videoName.empty())
    {
        if (!impl_->video.grab())
            return false;
        frame.timestamp = impl_->video.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
        frame.name = impl_->videoName + "#" + std::to_string(impl_->index);
        if (!impl_->video.retrieve(frame.image) || frame.image.empty())
        {
            frame.image.release();
            frame.error = "the frame cannot be decoded";
        }
        ++impl_->index;
        return true;
    }
    if (impl_->index >= (int)impl_->files.size())
        return false;
    frame.name = impl_->files[impl_->index];
    frame.timestamp = impl_->timestamps.empty() ? (double)impl_->index : impl_->timestamps[impl_->index];
    try
    {
        frame.image = readImage(frame.name);
    }
    catch (const std::exception& e)
    {
        frame.image.release();
        frame.error = e.what();
    }
    ++impl_->index;
    return true;
}

} // namespace tripose_samples
