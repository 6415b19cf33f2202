// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "image_input.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace tripose_samples {

namespace {

/** @p image, of more than 8 bits per channel, in 8 bits: its values from @p lowest to @p highest
stretched linearly onto 0-255. The detectors take 8-bit images, and keeping the top byte alone (as
OpenCV's own conversion to 8 bits does) would leave a camera's 12 bits stored in 16 (0-4095) with 16
grey levels, too few for SIFT's contrast threshold. */
cv::Mat stretchedToEightBits(const cv::Mat& image, double lowest, double highest)
{
    const double scale = 255.0 / (highest - lowest);
    cv::Mat out;
    image.convertTo(out, CV_8U, scale, -lowest * scale);
    return out;
}

} // namespace

cv::Mat readImage(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw std::runtime_error("image " + path + ": no such file");
    if (!std::ifstream(path, std::ios::binary))
        throw std::runtime_error("image " + path + ": cannot be opened for reading");
    // Not IMREAD_UNCHANGED, which also ignores the EXIF orientation: a phone stores a portrait photo
    // as a landscape image with a tag to turn it, and its calibration (with OpenCV's imread, or the
    // Python sample's) is of the image turned. Depth and colour stay as stored; alpha is dropped.
    const cv::Mat image = cv::imread(path, cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
    if (image.empty())
        throw std::runtime_error("image " + path + ": cannot be decoded (not an image OpenCV reads)");
    if (!cv::checkRange(image))
        throw std::runtime_error("image " + path + ": holds values that are not finite numbers");
    double lowest = 0, highest = 0;
    cv::minMaxLoc(image.reshape(1), &lowest, &highest);
    if (lowest == highest)
        throw std::runtime_error("image " + path + ": blank (every pixel has the value " +
                                 cv::format("%g", lowest) + ")");
    return image.depth() == CV_8U ? image : stretchedToEightBits(image, lowest, highest);
}

void checkImageFitsCalibration(const cv::Mat& image, const std::string& path, const cv::Matx33d& K,
                               const std::string& key)
{
    const double cx = K(0, 2) / K(2, 2), cy = K(1, 2) / K(2, 2);
    const double w = image.cols, h = image.rows;
    if (std::abs(cx - 0.5 * w) > 0.2 * w || std::abs(cy - 0.5 * h) > 0.2 * h)
        throw std::runtime_error(cv::format("image %s is %dx%d but the principal point of %s is (%.1f, %.1f), "
                                            "far from its centre: the calibration is for another image size",
                                            path.c_str(), image.cols, image.rows, key.c_str(), cx, cy));
}

std::vector<std::string> imageFilesIn(const std::string& folder)
{
    static const char* const extensions[] = { ".png", ".jpg", ".jpeg", ".pgm", ".ppm", ".bmp", ".tif", ".tiff" };
    std::vector<std::string> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    {
        if (!entry.is_regular_file())
            continue;
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return (char)std::tolower(c); });
        if (std::find(std::begin(extensions), std::end(extensions), extension) != std::end(extensions))
            files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace tripose_samples
