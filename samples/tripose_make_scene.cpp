// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_make_scene: writes a synthetic three-view scene (generateSyntheticScene of the support
// library) or, with --stereo, a stereo-rig scene (generateSyntheticStereoScene) as a problem file for
// tripose_estimate, with its ground truth, so that scripts in any language use the same scenes as
// the C++ tests and benchmarks.
//
//   tripose_make_scene --output scene.yml [--points N] [--lines M] [--motion large|small]
//                      [--noise px] [--outliers ratio] [--seed k]
//                      [--baseline12 m | --baseline12-fraction f] [--planar [--plane-tilt deg]]
//   tripose_make_scene --stereo --output scene.yml [--points N] [--lines M] [--noise px]
//                      [--outliers ratio] [--missing ratio] [--seed k]
//
// The file (OpenCV FileStorage, YAML or JSON by extension) holds the problem keys K1, K2, K3,
// R12, t12, points1..points3 (Nx2), lines1..lines3 (Mx4), and the ground truth R_gt (3x3), t_gt
// (3x1), points3d (Nx3), lines3d (Mx6) in the frame of view 1, point_inliers (Nx1) and
// line_inliers (Mx1) (1 where the view-3 observation is a true match). A stereo scene adds K4,
// points4 and lines4 (rows of .nan where view 3 or 4 does not see a feature), R12/t12 being the rig,
// and point_visibility / line_visibility (1: view 3 only, 2: view 4 only, 3: both). Exit status: 0
// on success, 1 on bad arguments. No output file is left behind on failure.

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "tripose_support/synthetic_scene.hpp"
#include "tripose_support/synthetic_stereo_scene.hpp"

#include "arguments.hpp"
#include "problem_io.hpp"

using tripose_samples::argumentError;
using tripose_samples::optionPairs;
using tripose_samples::parseInteger;
using tripose_samples::parseNumber;

namespace {

const char* kUsage =
    "usage: tripose_make_scene --output scene.yml [--points N] [--lines M] [--motion large|small]\n"
    "                          [--noise px] [--outliers ratio] [--seed k]\n"
    "                          [--baseline12 m | --baseline12-fraction f] [--planar [--plane-tilt deg]]\n"
    "       tripose_make_scene --stereo --output scene.yml [--points N] [--lines M] [--noise px]\n"
    "                          [--outliers ratio] [--missing ratio] [--seed k]\n"
    "  --output    problem file to write (.yml, .yaml or .json)\n"
    "  --points    number of point triplets (default 4)\n"
    "  --lines     number of line-segment triplets (default 4)\n"
    "  --motion    large (default): views 2, 3 at 20 m from the cube centre like view 1;\n"
    "              small: views 2, 3 within 5 m of view 1\n"
    "  --noise     standard deviation of the Gaussian pixel noise (default 0)\n"
    "  --outliers  fraction in [0, 1) of points and of lines with a wrong view-3 match (default 0)\n"
    "  --seed      integer seed; the same seed writes the same scene (default 0)\n"
    "  --baseline12           distance (m) of view 2 from view 1 in a random direction, view 3\n"
    "                         still placed by --motion (default: view 2 placed by --motion)\n"
    "  --baseline12-fraction  the same as a fraction of the 20 m depth (0.01: a 1 % baseline)\n"
    "  --planar               every point and segment on one plane through the cube centre\n"
    "  --plane-tilt           angle (degrees, [0, 90)) between the plane's normal and the direction\n"
    "                         to view 1 (default 30; needs --planar)\n"
    "  --stereo    a stereo-rig scene instead (no value): views 1-2 a rig at time A, views 3-4 at time B\n"
    "              (baseline 0.1-0.5 m, structure 5-30 m ahead, motion 0.3-3 m, turn up to 20 deg);\n"
    "              --outliers are wrong matches at time B; --motion does not apply\n"
    "  --missing   stereo: fraction in [0, 1] of points and of lines seen by view 3 or view 4 only (default 0)\n"
    "The three-view scene follows Qadir & Neubert, Sec. IV-A: 10 m cube, 640x480 cameras with f = 800 px.\n";

struct Options
{
    std::string output;
    bool stereo = false;
    cv::tripose::support::SyntheticSceneParams scene;
    cv::tripose::support::SyntheticStereoParams stereoScene;
};

bool hasExtension(const std::string& path, const std::string& extension)
{
    return path.size() > extension.size() &&
           path.compare(path.size() - extension.size(), extension.size(), extension) == 0;
}

Options parseArguments(int argc, char** argv)
{
    Options o;
    const std::vector<std::string> known = { "--output", "--points",     "--lines",    "--motion",
                                             "--noise",  "--outliers",   "--missing",  "--seed",
                                             "--baseline12", "--baseline12-fraction", "--plane-tilt" };
    bool tiltGiven = false, missingGiven = false, motionGiven = false;
    for (const auto& option : optionPairs(argc, argv, kUsage, known, { "--planar", "--stereo" }))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--output")
            o.output = value;
        else if (arg == "--points")
            o.scene.numPoints = parseInteger(arg, value, 0);
        else if (arg == "--lines")
            o.scene.numLines = parseInteger(arg, value, 0);
        else if (arg == "--motion")
        {
            motionGiven = true;
            if (value == "large")
                o.scene.motion = cv::tripose::support::MOTION_LARGE;
            else if (value == "small")
                o.scene.motion = cv::tripose::support::MOTION_SMALL;
            else
                throw argumentError(arg, "expected 'large' or 'small', got '" + value + "'");
        }
        else if (arg == "--noise")
        {
            o.scene.noiseSigma = parseNumber(arg, value);
            if (o.scene.noiseSigma < 0)
                throw argumentError(arg, "expected a standard deviation >= 0 (px), got '" + value + "'");
        }
        else if (arg == "--outliers")
        {
            o.scene.outlierRatio = parseNumber(arg, value);
            if (!(o.scene.outlierRatio >= 0 && o.scene.outlierRatio < 1))
                throw argumentError(arg, "expected a fraction in [0, 1), got '" + value + "'");
        }
        else if (arg == "--missing")
        {
            missingGiven = true;
            o.stereoScene.missingRatio = parseNumber(arg, value);
            if (!(o.stereoScene.missingRatio >= 0 && o.stereoScene.missingRatio <= 1))
                throw argumentError(arg, "expected a fraction in [0, 1], got '" + value + "'");
        }
        else if (arg == "--baseline12")
        {
            o.scene.baseline12 = parseNumber(arg, value);
            if (!(o.scene.baseline12 > 0))
                throw argumentError(arg, "expected a distance > 0 (m), got '" + value + "'");
        }
        else if (arg == "--baseline12-fraction")
        {
            o.scene.baseline12Fraction = parseNumber(arg, value);
            if (!(o.scene.baseline12Fraction > 0))
                throw argumentError(arg, "expected a fraction > 0, got '" + value + "'");
        }
        else if (arg == "--planar")
            o.scene.planar = true;
        else if (arg == "--plane-tilt")
        {
            o.scene.planeTilt = parseNumber(arg, value);
            if (!(o.scene.planeTilt >= 0 && o.scene.planeTilt < 90))
                throw argumentError(arg, "expected an angle in [0, 90) degrees, got '" + value + "'");
            tiltGiven = true;
        }
        else if (arg == "--stereo")
        {
            o.stereo = true;
        }
        else // --seed
            o.scene.seed = parseInteger(arg, value, -2147483648.0);
    }
    if (o.scene.baseline12 > 0 && o.scene.baseline12Fraction > 0)
        throw argumentError("--baseline12", "give either --baseline12 or --baseline12-fraction, not both");
    if (tiltGiven && !o.scene.planar)
        throw argumentError("--plane-tilt", "needs --planar");
    if (o.output.empty())
        throw std::runtime_error("argument --output is required (see --help)");
    if (!hasExtension(o.output, ".yml") && !hasExtension(o.output, ".yaml") && !hasExtension(o.output, ".json"))
        throw argumentError("--output", "expected a .yml, .yaml or .json file name, got '" + o.output + "'");
    if (o.stereo && motionGiven)
        throw argumentError("--motion", "applies to three-view scenes, not with --stereo");
    if (o.stereo && (o.scene.baseline12 > 0 || o.scene.baseline12Fraction > 0 || o.scene.planar))
        throw argumentError(o.scene.planar ? "--planar" : "--baseline12", "applies to three-view scenes, not with --stereo");
    if (!o.stereo && missingGiven)
        throw argumentError("--missing", "applies to stereo-rig scenes only (add --stereo)");
    o.stereoScene.numPoints = o.scene.numPoints;
    o.stereoScene.numLines = o.scene.numLines;
    o.stereoScene.noiseSigma = o.scene.noiseSigma;
    o.stereoScene.outlierRatio = o.scene.outlierRatio;
    o.stereoScene.seed = o.scene.seed;
    return o;
}

void writeScene(cv::FileStorage& fs, const cv::tripose::support::SyntheticScene& s)
{
    for (int v = 0; v < 3; ++v)
        fs << "K" + std::to_string(v + 1) << s.cameraMatrices[v];
    fs << "R12" << s.R12 << "t12" << s.t12;
    fs << "points1" << s.points1 << "points2" << s.points2 << "points3" << s.points3;
    fs << "lines1" << s.lines1 << "lines2" << s.lines2 << "lines3" << s.lines3;
    fs << "R_gt" << s.R << "t_gt" << s.t;
    fs << "points3d" << s.points3d << "lines3d" << s.lines3d;
    fs << "point_inliers" << s.pointInliers << "line_inliers" << s.lineInliers;
}

void writeStereoScene(cv::FileStorage& fs, const cv::tripose::support::SyntheticStereoScene& s)
{
    for (int v = 0; v < 4; ++v)
        fs << "K" + std::to_string(v + 1) << s.cameraMatrices[v];
    fs << "R12" << s.R12 << "t12" << s.t12;
    fs << "points1" << s.points1 << "points2" << s.points2 << "points3" << s.points3 << "points4" << s.points4;
    fs << "lines1" << s.lines1 << "lines2" << s.lines2 << "lines3" << s.lines3 << "lines4" << s.lines4;
    fs << "R_gt" << s.R << "t_gt" << s.t;
    fs << "points3d" << s.points3d << "lines3d" << s.lines3d;
    fs << "point_inliers" << s.pointInliers << "line_inliers" << s.lineInliers;
    fs << "point_visibility" << s.pointVisibility << "line_visibility" << s.lineVisibility;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    try
    {
        options = parseArguments(argc, argv);
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_make_scene: " << e.what() << "\n" << kUsage;
        return 1;
    }
    try
    {
        if (options.stereo)
        {
            const cv::tripose::support::SyntheticStereoScene scene =
                cv::tripose::support::generateSyntheticStereoScene(options.stereoScene);
            tripose_samples::writeAtomically(options.output, [&](cv::FileStorage& fs) { writeStereoScene(fs, scene); });
        }
        else
        {
            const cv::tripose::support::SyntheticScene scene = cv::tripose::support::generateSyntheticScene(options.scene);
            tripose_samples::writeAtomically(options.output, [&](cv::FileStorage& fs) { writeScene(fs, scene); });
        }
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_make_scene: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_make_scene: " << e.what() << "\n";
        return 1;
    }
    std::cout << "wrote " << options.output << ": " << options.scene.numPoints << " points, "
              << options.scene.numLines << " lines, seed " << options.scene.seed << (options.stereo ? ", stereo rig" : "")
              << "\n";
    return 0;
}
