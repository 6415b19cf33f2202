// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_estimate: the pose of view 3 from a problem file.
//
//   tripose_estimate --input problem.yml --output result.yml [--method linear|ransac]
//                    [--threshold px] [--confidence p] [--max-iterations n] [--refine 0|1] [--seed n]
//                    [--min-inliers n]
//                    [--allow-unknown-keys]
//
// The problem file (OpenCV FileStorage, YAML or JSON) holds K (or K1, K2, K3), optionally dist
// (or dist1..dist3), R12, t12, points1..points3 (Nx2) and lines1..lines3 (Mx4); either kind of
// feature may be absent. With points4 and/or lines4 it is a stereo rig (estimatePoseLinePointStereo):
// views 1, 2 the left and right cameras at time A, views 3, 4 at time B, R12/t12 the rig, K1..K4 and
// dist1..dist4 per view, and a row of .nan in points3/points4/lines3/lines4 a feature that view does
// not see. Any other key is an error naming it (a misspelt key would read as an absent one), apart
// from the ground truth tripose_make_scene writes, unless --allow-unknown-keys. The result holds
// num_solutions and, when a pose was found, R (3x3) and t (3x1); with --method ransac also num_inliers, point_inliers and line_inliers (one 0/1 per
// feature, in input order); when the pose is the refinement's (--refine 1, or ransac with refinement),
// covariance (6x6, for 1 px noise, doc/conventions.md) and noise_variance (px^2). Exit status: 0 on success (also when num_solutions is 0), 1 on bad arguments or input,
// 2 when the solver rejects the input (the message names the problem key). No output file is left
// behind on failure.

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

#include "arguments.hpp"
#include "problem_io.hpp"

using tripose_samples::parseInteger;
using tripose_samples::parseNumber;

namespace {

const char* kUsage =
    "usage: tripose_estimate --input problem.yml --output result.yml [--method linear|ransac]\n"
    "                        [--threshold px] [--confidence p] [--max-iterations n] [--refine 0|1] [--seed n]\n"
    "                        [--min-inliers n] [--loss squared|huber|cauchy] [--loss-scale px] [--allow-unknown-keys]\n"
    "  --input      OpenCV FileStorage problem (YAML or JSON): K or K1..K3, [dist or dist1..dist3],\n"
    "               R12, t12, points1..points3 (Nx2), lines1..lines3 (Mx4).\n"
    "               Stereo rig: with points4 and/or lines4, views 1-2 are the left and right cameras\n"
    "               at time A, views 3-4 at time B, R12/t12 the rig, K or K1..K4, [dist or dist1..dist4];\n"
    "               a row of .nan in points3/points4/lines3/lines4 marks a feature that view does not see\n"
    "  --output     result file (YAML or JSON by extension): num_solutions, R, t\n"
    "               (ransac: also num_inliers, point_inliers, line_inliers; when the pose is the\n"
    "               refinement's: covariance, 6x6 for 1 px noise, and noise_variance in px^2)\n"
    "  --method     linear (default): the unified linear solver on all features (no outlier rejection);\n"
    "               ransac: robust estimation with outlier rejection\n"
    "  --threshold  ransac inlier threshold in pixels (default 2)\n"
    "  --confidence ransac confidence, in (0, 1) (default 0.999)\n"
    "  --max-iterations  ransac upper bound on the number of samples (default 10000)\n"
    "  --refine     1: finish with maximum-likelihood refinement over all views (linear: every\n"
    "               candidate and further starts refined, the lowest cost kept; ransac: on the inliers);\n"
    "               0: no refinement.\n"
    "               Default: 0 with linear, 1 with ransac\n"
    "  --seed       ransac sampler seed (default 0)\n"
    "  --min-inliers  ransac: the fewest inliers of a pose (default 15); fewer: no pose (num_solutions 0)\n"
    "  --loss       ransac: the loss of the refinement on the inliers (default squared; tripose_images\n"
    "               refines features found in images under cauchy, 0.5 px)\n"
    "  --loss-scale scale of the huber or cauchy loss in pixels (default 1)\n"
    "  --allow-unknown-keys  read a problem file that carries other keys (by default an unknown key,\n"
    "               such as a misspelt one, is an error; the ground truth of tripose_make_scene is known)\n";

struct Options
{
    std::string input, output, method = "linear";
    int refine = -1; //!< -1: the method's default
    bool allowUnknownKeys = false;
    cv::tripose::RansacParams ransac;
};

Options parseArguments(int argc, char** argv)
{
    Options o;
    const std::vector<std::string> known = { "--input",      "--output",         "--method", "--threshold",
                                             "--confidence", "--max-iterations", "--refine", "--seed",
                                             "--loss",       "--loss-scale",     "--min-inliers" };
    for (const auto& option : tripose_samples::optionPairs(argc, argv, kUsage, known, { "--allow-unknown-keys" }))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--allow-unknown-keys")
            o.allowUnknownKeys = true;
        else if (arg == "--input")
            o.input = value;
        else if (arg == "--output")
            o.output = value;
        else if (arg == "--method")
            o.method = value;
        else if (arg == "--threshold")
        {
            o.ransac.threshold = parseNumber(arg, value);
            if (!(o.ransac.threshold > 0))
                throw std::runtime_error("argument --threshold: expected a positive number of pixels, got '" + value + "'");
        }
        else if (arg == "--confidence")
        {
            o.ransac.confidence = parseNumber(arg, value);
            if (!(o.ransac.confidence > 0 && o.ransac.confidence < 1))
                throw std::runtime_error("argument --confidence: expected a probability in (0, 1), got '" + value + "'");
        }
        else if (arg == "--max-iterations")
        {
            o.ransac.maxIterations = parseInteger(arg, value, 1.0);
        }
        else if (arg == "--refine")
        {
            if (value != "0" && value != "1")
                throw std::runtime_error("argument --refine: expected 0 or 1, got '" + value + "'");
            o.refine = value == "1" ? 1 : 0;
        }
        else if (arg == "--loss")
        {
            if (value == "squared")
                o.ransac.refineParams.loss = cv::tripose::LOSS_SQUARED;
            else if (value == "huber")
                o.ransac.refineParams.loss = cv::tripose::LOSS_HUBER;
            else if (value == "cauchy")
                o.ransac.refineParams.loss = cv::tripose::LOSS_CAUCHY;
            else
                throw std::runtime_error("argument --loss: expected squared, huber or cauchy, got '" + value + "'");
        }
        else if (arg == "--loss-scale")
        {
            o.ransac.refineParams.lossScale = parseNumber(arg, value);
            if (!(o.ransac.refineParams.lossScale > 0))
                throw std::runtime_error("argument --loss-scale: expected a positive number of pixels, got '" + value + "'");
        }
        else if (arg == "--min-inliers")
            o.ransac.minInliers = parseInteger(arg, value, 0.0);
        else // --seed
            o.ransac.seed = parseInteger(arg, value, -2147483647.0);
    }
    if (o.input.empty())
        throw std::runtime_error("argument --input is required");
    if (o.output.empty())
        throw std::runtime_error("argument --output is required");
    if (o.method != "linear" && o.method != "ransac")
        throw std::runtime_error("argument --method: expected 'linear' or 'ransac', got '" + o.method + "'");
    o.ransac.refine = o.refine != 0;
    return o;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    tripose_samples::Problem problem;
    try
    {
        options = parseArguments(argc, argv);
        tripose_samples::checkWritable(options.output, "--output");
        problem = tripose_samples::readProblem(options.input, options.allowUnknownKeys);
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_estimate: " << e.what() << "\n" << kUsage;
        return 1;
    }

    cv::Mat R, t, pointInliers, lineInliers, covariance, noiseVariance;
    int n = 0, inliers = 0;
    const bool robust = options.method == "ransac";
    try
    {
        const tripose_samples::Problem& p = problem;
        const int method = options.refine == 1 ? cv::tripose::POSE_LINEAR_REFINE : cv::tripose::POSE_LINEAR;
        if (robust && p.stereo)
            inliers = cv::tripose::estimatePoseLinePointStereoRansac(
                p.points[0], p.points[1], p.points[2], p.points[3], p.lines[0], p.lines[1], p.lines[2], p.lines[3],
                p.K, p.dist, p.R12, p.t12, R, t, options.ransac, pointInliers, lineInliers, cv::noArray(),
                cv::noArray(), cv::noArray(), covariance, noiseVariance);
        else if (robust)
            inliers = cv::tripose::estimatePoseLinePointRansac(p.points[0], p.points[1], p.points[2], p.lines[0],
                                                               p.lines[1], p.lines[2], p.K, p.dist, p.R12, p.t12, R, t,
                                                               options.ransac, pointInliers, lineInliers, cv::noArray(),
                                                               cv::noArray(), cv::noArray(), covariance, noiseVariance);
        else if (p.stereo)
            n = cv::tripose::estimatePoseLinePointStereo(p.points[0], p.points[1], p.points[2], p.points[3],
                                                         p.lines[0], p.lines[1], p.lines[2], p.lines[3], p.K, p.dist,
                                                         p.R12, p.t12, R, t, method, cv::noArray(), cv::noArray(),
                                                         cv::noArray(), covariance, noiseVariance);
        else
            n = cv::tripose::estimatePoseLinePoint(p.points[0], p.points[1], p.points[2], p.lines[0], p.lines[1],
                                                   p.lines[2], p.K, p.dist, p.R12, p.t12, R, t, method, cv::noArray(),
                                                   cv::noArray(), cv::noArray(), covariance, noiseVariance);
        if (robust)
            n = inliers > 0 ? 1 : 0;
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_estimate: the solver rejected the input"
                  << tripose_samples::problemKeyNamedBy(e.err) << ": " << e.err << "\n";
        return 2;
    }

    try
    {
        tripose_samples::writeAtomically(options.output, [&](cv::FileStorage& fs) {
            fs << "num_solutions" << n;
            if (n > 0)
                fs << "R" << R << "t" << t;
            if (n > 0 && !covariance.empty())
                fs << "covariance" << covariance << "noise_variance" << noiseVariance.at<double>(0);
            if (robust)
            {
                fs << "num_inliers" << inliers << "point_inliers" << tripose_samples::inlierColumn(pointInliers)
                   << "line_inliers" << tripose_samples::inlierColumn(lineInliers);
            }
        });
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_estimate: " << e.what() << "\n";
        return 1;
    }
    std::cout << "tripose_estimate: " << n << " solution(s); result written to " << options.output << "\n";
    return 0;
}
