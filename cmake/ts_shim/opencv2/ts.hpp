// Standalone stand-in for the part of OpenCV's internal test module (opencv_ts) that the tripose
// tests use. Inside an OpenCV build the real opencv2/ts.hpp is used instead and this directory is
// not on the include path; keep every name here spelled exactly as in opencv_ts.
#ifndef TRIPOSE_TS_SHIM_TS_HPP
#define TRIPOSE_TS_SHIM_TS_HPP

#include <cstdlib>
#include <string>
#include <tuple>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/filesystem.hpp>

namespace cvtest {

// Resolves a test data path: $OPENCV_TEST_DATA_PATH first (as opencv_ts does), then the folder the
// standalone build was configured with. Fails the calling test if the file is missing.
inline std::string findDataFile(const std::string& relative, bool required = true)
{
    const char* env = std::getenv("OPENCV_TEST_DATA_PATH");
    std::string roots[2] = { env ? std::string(env) : std::string(),
#ifdef TRIPOSE_TEST_DATA_DIR
                             std::string(TRIPOSE_TEST_DATA_DIR)
#else
                             std::string()
#endif
    };
    for (const std::string& root : roots)
    {
        if (root.empty())
            continue;
        std::string candidate = root + "/" + relative;
        if (cv::utils::fs::exists(candidate))
            return candidate;
    }
    if (required)
        throw std::runtime_error("test data not found: " + relative +
                                 " (set OPENCV_TEST_DATA_PATH to the repository's test/data)");
    return std::string();
}

inline std::string findDataDirectory(const std::string& relative, bool required = true)
{
    return findDataFile(relative, required);
}

} // namespace cvtest

namespace opencv_test {
using namespace cvtest;
using namespace cv;
using std::get;
using std::make_tuple;
using std::tie;
using std::tuple;
using testing::Values;
using testing::ValuesIn;
using testing::Combine;
using testing::TestWithParam;

// opencv_ts shadows these cv:: functions inside opencv_test with its own reference versions, so an
// unqualified call does not compile there. Shadow them here too, with a type that names the fix,
// so that the standalone build rejects what the OpenCV build rejects.
#define TRIPOSE_TS_SHIM_QUALIFY(name) \
    struct write_cv_ ## name ## _with_its_namespace {}; \
    using name = write_cv_ ## name ## _with_its_namespace;
TRIPOSE_TS_SHIM_QUALIFY(norm)
TRIPOSE_TS_SHIM_QUALIFY(add)
TRIPOSE_TS_SHIM_QUALIFY(multiply)
TRIPOSE_TS_SHIM_QUALIFY(divide)
TRIPOSE_TS_SHIM_QUALIFY(transpose)
TRIPOSE_TS_SHIM_QUALIFY(copyMakeBorder)
TRIPOSE_TS_SHIM_QUALIFY(filter2D)
TRIPOSE_TS_SHIM_QUALIFY(compare)
TRIPOSE_TS_SHIM_QUALIFY(minMaxIdx)
TRIPOSE_TS_SHIM_QUALIFY(threshold)
#undef TRIPOSE_TS_SHIM_QUALIFY
} // namespace opencv_test

// Same spelling as opencv_ts; the argument (resource prefix) has no meaning here.
#define CV_TEST_MAIN(resourcesubdir, ...)                  \
    int main(int argc, char** argv)                        \
    {                                                      \
        ::testing::InitGoogleTest(&argc, argv);            \
        __VA_ARGS__;                                       \
        return RUN_ALL_TESTS();                            \
    }

#endif // TRIPOSE_TS_SHIM_TS_HPP
