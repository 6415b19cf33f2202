// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_SAMPLE_GENERATOR_HPP
#define OPENCV_TRIPOSE_SAMPLE_GENERATOR_HPP

#include <vector>

#include <cstdint>

#include "../support/random.hpp"

namespace tripose {

/** Minimal samples for the robust estimator: sets of distinct feature indices.

When the features allow only a few distinct samples (at most kEnumerationLimit and at most the
iteration budget), every one of them is drawn once, in an order shuffled by the seed, and the
generator then runs dry: drawing them at random would repeat some and miss others, and with
exactly four features the one possible sample would be solved again until the budget runs out.
Otherwise samples are drawn at random (distinct indices within a sample).
*/
class SampleGenerator
{
public:
    static const int kEnumerationLimit = 1024;

    SampleGenerator(int numFeatures, int sampleSize, long maxDraws, uint64_t seed);

    //! The next sample into @p sample (resized to the sample size); false when none is left.
    bool next(std::vector<int>& sample);

    //! True when every distinct sample is drawn once (see the class description).
    bool enumerates() const { return !samples_.empty(); }

private:
    int numFeatures_, sampleSize_;
    Random rng_;
    std::vector<int> samples_; //!< Enumerated samples, sampleSize_ indices each, in drawing order.
    size_t position_ = 0;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_SAMPLE_GENERATOR_HPP
