// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_SCORING_SEQUENTIAL_TEST_HPP
#define OPENCV_TRIPOSE_SCORING_SEQUENTIAL_TEST_HPP

namespace tripose {

/** Wald's sequential probability ratio test of a robust estimator's hypotheses (Matas and Chum,
"Randomized RANSAC with Sequential Probability Ratio Test", ICCV 2005; Chum and Matas, "Optimal
Randomized RANSAC", PAMI 2008), which PoseScorer::score() runs on a random order of the
observations before it scores a pose in full.

Two hypotheses about a pose: it is good, and each observation is consistent with it (within the
threshold) with probability epsilon, the rate of the best pose so far; or it is bad, and an
observation is consistent with probability delta, the rate measured on the poses the test
rejected. Points and lines have their own rates (a wrong pose is consistent with far more image
lines than image points: a line constrains one direction of the image, a point two). After each
observation the log of the likelihood ratio bad / good grows by log((1 - delta) / (1 - epsilon))
for an inconsistent one and by log(delta / epsilon) for a consistent one; the pose is rejected as
soon as it exceeds log(kThreshold). Whatever delta is, a pose whose observations are consistent at
the rate epsilon or more is rejected with probability at most 1 / kThreshold (Wald's bound on the
ratio, a martingale under the good hypothesis): a pose that would beat the best one is lost once in
a thousand, and a wrong one is rejected after a handful of observations instead of being scored up
to the best cost (the MSAC bound: at half outliers, more than half of the observations).

The threshold is fixed rather than Chum and Matas' optimum for speed (A = 1 + K + log A, K the
solve time in observation checks times the information per observation over the poses per
sample), which for solves as cheap as a three-feature sample's is in the tens: it would lose a good
pose in a few per cent of the samples, costing samples and changing results. At 1000 a wrong pose
takes about 11 observations instead of 5 (epsilon 0.5, delta 0.01, against A = 20), a small part
of its solve.
*/
class SequentialTest
{
public:
    enum Kind
    {
        Point = 0,
        Line = 1,
    };
    static constexpr double kThreshold = 1000.0;

    //! Inactive until setGoodRates() gives the rates of a best pose.
    SequentialTest();

    /** The rates of consistent observations of points and of lines of the best pose so far (each in
    [0, 1]; a kind the set lacks: any). Capped at kMaxGoodRate: a lower epsilon only makes the test
    more cautious, and a pose with every observation consistent would otherwise make the first
    inconsistent one of any pose reject it. */
    void setGoodRates(double pointRate, double lineRate);

    /** Adds what the test saw of a pose it rejected: per kind, the observations tested and those of
    them consistent; the bad rates are their running ratio, from a prior of kPriorBadRate. */
    void addRejected(const int tested[2], const int consistent[2]);

    //! True when some kind tells good poses from bad ones (epsilon well above delta).
    bool active() const { return active_; }
    double logThreshold() const { return logThreshold_; }
    //! The growth of the log-likelihood ratio for one observation of @p kind.
    double step(int kind, bool consistent) const { return consistent ? consistentStep_[kind] : inconsistentStep_[kind]; }

    double goodRate(int kind) const { return good_[kind]; }
    double badRate(int kind) const { return bad_[kind]; }

    static constexpr double kMaxGoodRate = 0.95;
    static constexpr double kPriorBadRate = 0.05;
    //! Weight of the prior, in observations.
    static constexpr double kPriorObservations = 20.0;
    static constexpr double kMinBadRate = 0.005;
    //! A kind takes part when epsilon exceeds delta by this factor (else its steps are 0).
    static constexpr double kMinRateRatio = 1.5;

private:
    void updateSteps();

    double good_[2], bad_[2];
    double tested_[2], consistent_[2];
    //! The bad rates the steps were computed from (they are recomputed when delta moves by 5 %).
    double stepBad_[2];
    double consistentStep_[2], inconsistentStep_[2];
    double logThreshold_;
    bool haveGood_ = false, active_ = false;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_SCORING_SEQUENTIAL_TEST_HPP
