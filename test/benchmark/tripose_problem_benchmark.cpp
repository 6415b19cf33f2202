// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_problem_benchmark: median time per call of the C++ API on one three-view problem file,
// the counterpart of the Python package's calls on the same arrays (test/benchmark/python_overhead.py
// writes the file, runs this program and times the package between its runs). The inputs are
// cv::Mat in the form a C++ caller has them (CV_64F, Nx2 and Mx4), read before the clock starts; the
// outputs are what the package returns (linear: every candidate; ransac: the pose and the masks).
//
//   tripose_problem_benchmark --input problem.yml --method linear|ransac [--runs 2000]
//                             [--threshold 2] [--refine 0|1] [--seed 0]
//
// Prints "median_us <value>" and the pose of the last call ("R" 9 values, "t" 3 values), so that the
// caller can check that both sides solved the same problem the same way; "no pose" and exit status 1
// when the last call found none.

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

#include "../../samples/common/arguments.hpp"
#include "../../samples/common/problem_io.hpp"
#include "benchmark_common.hpp"

namespace {

const char* const kUsage =
    "usage: tripose_problem_benchmark --input problem.yml --method linear|ransac [--runs 2000]\n"
    "                                 [--threshold 2] [--refine 0|1] [--seed 0]\n";

} // namespace

int main(int argc, char** argv)
{
    try
    {
        std::string input, method = "linear";
        int runs = 2000, seed = 0;
        bool refine = true;
        double threshold = 2.0;
        for (const auto& option : tripose_samples::optionPairs(
                 argc, argv, kUsage, { "--input", "--method", "--runs", "--threshold", "--refine", "--seed" }))
        {
            if (option.first == "--input")
                input = option.second;
            else if (option.first == "--method")
                method = option.second;
            else if (option.first == "--runs")
                runs = tripose_samples::parseInteger(option.first, option.second, 1);
            else if (option.first == "--threshold")
                threshold = tripose_samples::parseNumber(option.first, option.second);
            else if (option.first == "--refine")
                refine = tripose_samples::parseInteger(option.first, option.second, 0) != 0;
            else if (option.first == "--seed")
                seed = tripose_samples::parseInteger(option.first, option.second, 0);
        }
        if (input.empty())
            throw tripose_samples::argumentError("--input", "missing");
        if (method != "linear" && method != "ransac")
            throw tripose_samples::argumentError("--method", "expected linear or ransac, got '" + method + "'");
        const tripose_samples::Problem p = tripose_samples::readProblem(input);
        if (p.stereo)
            throw tripose_samples::argumentError("--input", "a three-view problem is expected, not a stereo rig");

        cv::tripose::RansacParams params;
        params.threshold = threshold;
        params.refine = refine;
        params.seed = seed;
        params.minInliers = 0; // the estimator's time is measured, whatever its support
        cv::Mat R, t;
        std::vector<cv::Mat> candidateRs, candidateTs;
        cv::Mat pointInliers, lineInliers;
        auto call = [&]() {
            // Every candidate, as the package's estimate_pose_line_point returns them.
            if (method == "linear")
                return cv::tripose::estimatePoseLinePoint(p.points[0], p.points[1], p.points[2], p.lines[0],
                                                          p.lines[1], p.lines[2], p.K, p.dist, p.R12, p.t12, R, t,
                                                          cv::tripose::POSE_LINEAR, candidateRs, candidateTs);
            return cv::tripose::estimatePoseLinePointRansac(p.points[0], p.points[1], p.points[2], p.lines[0],
                                                            p.lines[1], p.lines[2], p.K, p.dist, p.R12, p.t12, R, t,
                                                            params, pointInliers, lineInliers);
        };
        call(); // warm-up: first-touch allocations are not the steady state a caller sees
        std::vector<double> seconds;
        seconds.reserve(runs);
        for (int r = 0; r < runs; ++r)
        {
            const auto start = std::chrono::steady_clock::now();
            call();
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::printf("median_us %.4f\n", 1e6 * tripose_benchmark::median(seconds));
        std::printf("candidates %d\n", (int)candidateRs.size());
        if (R.empty())
        {
            std::printf("no pose\n");
            return 1; // a time of a call that found nothing is not a time to report
        }
        std::printf("R");
        for (int i = 0; i < 9; ++i)
            std::printf(" %.17g", R.at<double>(i / 3, i % 3));
        std::printf("\nt");
        for (int i = 0; i < 3; ++i)
            std::printf(" %.17g", t.at<double>(i));
        std::printf("\n");
        return 0;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "tripose_problem_benchmark: %s\n", e.what());
        return 1;
    }
}
