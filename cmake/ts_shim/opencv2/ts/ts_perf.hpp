// Standalone stand-in for OpenCV's perf framework (opencv2/ts/ts_perf.hpp): PERF_TEST_P,
// TEST_CYCLE, SANITY_CHECK_NOTHING and CV_PERF_TEST_MAIN, spelled as in opencv_ts. Each test prints
// the median time of its cycles; there are no pass/fail timing thresholds (speed is reported by
// benchmarks, not asserted).
#ifndef TRIPOSE_TS_SHIM_TS_PERF_HPP
#define TRIPOSE_TS_SHIM_TS_PERF_HPP

#include <algorithm>
#include <cstdio>
#include <vector>

#include "opencv2/ts.hpp"

namespace perf {

class TestBase : public ::testing::Test
{
public:
    struct Declaration
    {
        int maxIterations = 1000;
        double maxSeconds = 2.0;
        Declaration& iterations(int n) { maxIterations = n; return *this; }
        Declaration& time(double seconds) { maxSeconds = seconds; return *this; }
    } declare;

protected:
    void startCycle()
    {
        samples_.clear();
        started_ = false;
        total_ = 0;
    }

    // Called before each cycle; records the previous cycle and decides whether to run another.
    bool nextCycle()
    {
        const int64 now = cv::getTickCount();
        if (started_)
        {
            samples_.push_back(now - last_);
            total_ += now - last_;
        }
        started_ = true;
        const double seconds = double(total_) / cv::getTickFrequency();
        if ((int)samples_.size() >= declare.maxIterations || (seconds > declare.maxSeconds && !samples_.empty()))
        {
            report();
            return false;
        }
        last_ = cv::getTickCount();
        return true;
    }

private:
    void report()
    {
        std::vector<int64> sorted = samples_;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const double medianUs = 1e6 * double(sorted[sorted.size() / 2]) / cv::getTickFrequency();
        std::printf("[ PERFSTAT ] median %.3f us over %d cycles\n", medianUs, (int)samples_.size());
        RecordProperty("median_us", cv::format("%.3f", medianUs));
        RecordProperty("samples", (int)samples_.size());
    }

    std::vector<int64> samples_;
    int64 last_ = 0, total_ = 0;
    bool started_ = false;
};

template <typename Param>
class TestBaseWithParam : public TestBase, public ::testing::WithParamInterface<Param>
{
};

} // namespace perf

namespace opencv_test {
using namespace perf;
} // namespace opencv_test

#define PERF_TEST_P(fixture, name, params)                                   \
    class fixture##_##name : public fixture                                   \
    {                                                                         \
    public:                                                                   \
        void PerfTestBody();                                                  \
    };                                                                        \
    TEST_P(fixture##_##name, name) { PerfTestBody(); }                        \
    INSTANTIATE_TEST_SUITE_P(Perf, fixture##_##name, params);                 \
    void fixture##_##name::PerfTestBody()

#define TEST_CYCLE() for (this->startCycle(); this->nextCycle();)
#define SANITY_CHECK_NOTHING() ((void)0)

#define CV_PERF_TEST_MAIN(modulename, ...)                 \
    int main(int argc, char** argv)                        \
    {                                                      \
        ::testing::InitGoogleTest(&argc, argv);            \
        __VA_ARGS__;                                       \
        return RUN_ALL_TESTS();                            \
    }

#endif // TRIPOSE_TS_SHIM_TS_PERF_HPP
