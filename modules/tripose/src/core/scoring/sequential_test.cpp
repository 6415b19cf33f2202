// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include <algorithm>
#include <cmath>

#include "sequential_test.hpp"

namespace tripose {

namespace {

// The steps are recomputed when a bad rate moves by more than this share of itself.
constexpr double kBadRateChange = 0.05;

} // namespace

SequentialTest::SequentialTest() : logThreshold_(std::log(kThreshold))
{
    for (int k = 0; k < 2; ++k)
    {
        good_[k] = 0;
        bad_[k] = stepBad_[k] = kPriorBadRate;
        tested_[k] = consistent_[k] = 0;
        consistentStep_[k] = inconsistentStep_[k] = 0;
    }
}

void SequentialTest::setGoodRates(double pointRate, double lineRate)
{
    good_[Point] = std::min(std::max(pointRate, 0.0), kMaxGoodRate);
    good_[Line] = std::min(std::max(lineRate, 0.0), kMaxGoodRate);
    haveGood_ = true;
    updateSteps();
}

void SequentialTest::addRejected(const int tested[2], const int consistent[2])
{
    bool moved = false;
    for (int k = 0; k < 2; ++k)
    {
        tested_[k] += tested[k];
        consistent_[k] += consistent[k];
        bad_[k] = std::max(kMinBadRate, (consistent_[k] + kPriorBadRate * kPriorObservations) /
                                            (tested_[k] + kPriorObservations));
        moved = moved || std::abs(bad_[k] - stepBad_[k]) > kBadRateChange * stepBad_[k];
    }
    if (moved && haveGood_)
        updateSteps();
}

void SequentialTest::updateSteps()
{
    active_ = false;
    for (int k = 0; k < 2; ++k)
    {
        stepBad_[k] = bad_[k];
        const double epsilon = good_[k], delta = bad_[k];
        if (epsilon > kMinRateRatio * delta)
        {
            consistentStep_[k] = std::log(delta / epsilon);
            inconsistentStep_[k] = std::log((1 - delta) / (1 - epsilon));
            active_ = true;
        }
        else
            consistentStep_[k] = inconsistentStep_[k] = 0;
    }
}

} // namespace tripose
