// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_FRAME_FEATURES_HPP
#define TRIPOSE_CORE_TRACKING_FRAME_FEATURES_HPP

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace tripose {

/** Descriptors of one kind of feature, one row each: real-valued rows compared by L2 distance (SIFT,
learned descriptors) or bit strings compared by Hamming distance (ORB, AKAZE, LBD).
*/
struct Descriptors
{
    int rows = 0, cols = 0;      //!< cols: values per row (real) or bytes per row (binary).
    bool binary = false;
    std::vector<float> real;     //!< rows * cols values, row-major (binary == false).
    std::vector<uint8_t> bits;   //!< rows * cols bytes, row-major (binary == true).

    bool empty() const { return rows == 0; }
    //! The L2 (real) or Hamming (binary) distance between row @p i and row @p j of @p other.
    double distance(int i, const Descriptors& other, int j) const;
    //! Rows @p rows, in their order.
    Descriptors subset(const std::vector<int>& rows) const;
};

/** What a front end found in one image: points and line segments in the image's pixels (undistorted:
those of an ideal pinhole camera with the frame's K), each with a descriptor row. Segments are
oriented: a view of an edge sees its brighter side on the same hand, so that matching can tell an
edge from its reverse; a front end without that convention orients them arbitrarily and loses
nothing but that test.
*/
struct FrameFeatures
{
    std::vector<Eigen::Vector2d> points;
    Descriptors pointDescriptors;
    std::vector<Eigen::Vector4d> segments; //!< x0 y0 x1 y1
    Descriptors lineDescriptors;
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_FRAME_FEATURES_HPP
