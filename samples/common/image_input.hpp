// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Reading the images of the front end, with the checks that keep a wrong file from reaching the
// matcher: present and decodable, not blank, and of the size the calibration was made for.
#ifndef TRIPOSE_SAMPLES_IMAGE_INPUT_HPP
#define TRIPOSE_SAMPLES_IMAGE_INPUT_HPP

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

/** The image in @p path (grey or colour as stored) in 8 bits per channel, turned as its EXIF
orientation says. An image of more bits (16-bit PNG or TIFF, 32-bit float TIFF) has its values
stretched from its lowest to its highest onto 0-255. Throws std::runtime_error naming the file when
it is missing, cannot be decoded, holds values that are not finite, or is blank (every pixel the
same value). */
cv::Mat readImage(const std::string& path);

/** Throws std::runtime_error naming the file and @p key when the principal point of @p K is far from
the middle of @p image: more than a fifth of the width or height away. Real principal points lie
within a few percent of the centre; an image scaled by two or more against the calibration (or a
calibration made for another camera size) puts it a quarter of the image or more away.
*/
void checkImageFitsCalibration(const cv::Mat& image, const std::string& path, const cv::Matx33d& K,
                               const std::string& key);

//! The image files of a folder (.png, .jpg, .jpeg, .pgm, .ppm, .bmp, .tif, .tiff; any case), sorted by name.
std::vector<std::string> imageFilesIn(const std::string& folder);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_IMAGE_INPUT_HPP
