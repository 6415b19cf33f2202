// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detected segments moved onto the image's edges with sub-pixel precision, and oriented by the
// edge's polarity.
#ifndef TRIPOSE_SAMPLES_SEGMENT_EDGE_FIT_HPP
#define TRIPOSE_SAMPLES_SEGMENT_EDGE_FIT_HPP

#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

/** Fits each segment (x0, y0, x1, y1) of the 8-bit grey @p image to its edge: at every pixel row
the segment crosses (column, for segments closer to horizontal), the peak of the image's gradient
across the segment (Gaussian sigma 1, Sobel), placed between pixels by a parabola through three,
within 1 px of the segment and of the segment's dominant polarity; then the total-least-squares line
through those peaks, the end points projected onto it. The result is oriented with the brighter side
on its right as drawn (x right, y down), so that a segment and its match in another view are
described (LBD) in the same direction. A segment with fewer than five peaks keeps its position and
only gets the orientation; one of zero length is dropped.

Why: edge chaining detectors (EDLines) fit their lines to whole pixels, so a segment nearly along
an image axis comes out up to half a pixel off its edge; the fit places it on the edge's sub-pixel
position at every slope (doc/studies/real_images.md).
*/
std::vector<cv::Vec4f> fitSegmentsToEdges(const cv::Mat& image, const std::vector<cv::Vec4f>& segments);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_SEGMENT_EDGE_FIT_HPP
