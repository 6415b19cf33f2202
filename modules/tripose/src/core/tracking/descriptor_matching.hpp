// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_DESCRIPTOR_MATCHING_HPP
#define TRIPOSE_CORE_TRACKING_DESCRIPTOR_MATCHING_HPP

#include <limits>
#include <utility>
#include <vector>

#include "frame_features.hpp"

namespace tripose {

//! (row in the first set of features, row in the second).
using Matches = std::vector<std::pair<int, int>>;

/** Keeps the mutual best pairs of a list of candidate pairs: (a, b) when b is a's best candidate, a
is b's best, and a's best distance is below a ratio of a's second best (a lone candidate passes:
something other than the descriptor, the geometry, singled it out).
*/
class MutualBest
{
public:
    MutualBest(int rowsA, int rowsB);
    void add(int a, int b, double distance);
    Matches result(double ratio) const;

private:
    std::vector<int> bestOfA_, bestOfB_;
    std::vector<double> bestDistanceOfA_, secondOfA_, bestDistanceOfB_;
};

/** Rows of @p a and @p b matched by descriptor alone: mutual best over every row of the other with
the ratio test @p ratio, at most @p maxDistance apart. */
Matches matchByDescriptor(const Descriptors& a, const Descriptors& b, double ratio,
                          double maxDistance = std::numeric_limits<double>::infinity());

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_DESCRIPTOR_MATCHING_HPP
