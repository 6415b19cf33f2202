// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_images_report: the image front end (tripose_images' steps) on every run of three consecutive
// frames of a VGG multi-view sequence that comes with its images, beside other ways to the same pose,
// against the sequence's cameras. Prints Markdown tables (doc/studies/real_images.md is made of them):
//  - tripose, points and lines: estimatePoseLinePointRansac (refined under the front end's Cauchy loss,
//    image_estimation.hpp) on the point tracks and segment triplets;
//  - tripose, points only: the same on the point tracks alone;
//  - triangulation + PnP: the point tracks triangulated from views 1-2 (DLT), then
//    cv::solvePnPRansac (SOLVEPNP_SQPNP) in view 3 at the same threshold;
//  - tripose on the sequence's own correspondences (its hand-checked corners and segments; least squares).
// With --calib-output, writes instead the calibration of three views (K1..K3, R12, t12 relative to
// the first; the ground truth as R_gt, t_gt) in the form tripose_images reads.
//
// With --dump-inputs, also writes each triplet's matches and their structure from views 1-2 as one
// JSON line (the form of tripose_evaluate --dump-inputs), for the peers run from Python
// (test/evaluation/images_vs_poselib.py).
//
//   tripose_images_report --data <VGG folder with images> [--threshold px] [--seed n] [--dump-inputs file.jsonl]
//   tripose_images_report --data <VGG folder> --calib-output calib.yml [--views i j k]

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

#include "arguments.hpp"
#include "feature_matching.hpp"
#include "image_estimation.hpp"
#include "image_features.hpp"
#include "image_input.hpp"
#include "problem_io.hpp"
#include "tripose_support/json_writing.hpp"
#include "tripose_support/known_pair_structure.hpp"
#include "tripose_support/pose_error.hpp"
#include "tripose_support/vgg_dataset.hpp"
#include "two_view_geometry.hpp"

using namespace tripose_samples;
namespace support = cv::tripose::support;

namespace {

const char* kUsage =
    "usage: tripose_images_report --data <VGG sequence folder with images> [--threshold px] [--seed n]\n"
    "                             [--dump-inputs file.jsonl]\n"
    "       tripose_images_report --data <VGG sequence folder> --calib-output calib.yml [--views i j k]\n"
    "  Every three consecutive frames (images in name order, one per camera of the sequence): the image\n"
    "  front end, tripose (points and lines; points only), triangulation + solvePnPRansac (SQPNP), and\n"
    "  tripose on the sequence's own correspondences; errors against the sequence's cameras, as Markdown.\n"
    "  --dump-inputs   also write each triplet's matches and their structure from views 1-2, one JSON line each\n"
    "  --calib-output  write the calibration of views i j k (default 0 1 2) for tripose_images, and exit\n";

struct Options
{
    std::string data, calibOutput, dumpInputs;
    FeatureOptions features;
    int views[3] = { 0, 1, 2 };
    cv::tripose::RansacParams ransac = imageRansacParams();
};

Options parseArguments(int argc, char** argv)
{
    Options o;
    std::vector<char*> rest = { argv[0] };
    for (int i = 1; i < argc; ++i)
    {
        if (std::string(argv[i]) != "--views")
        {
            rest.push_back(argv[i]);
            continue;
        }
        for (int k = 0; k < 3; ++k)
        {
            if (i + 1 >= argc)
                throw argumentError("--views", "expected three view indices");
            o.views[k] = parseInteger("--views", argv[++i], 0.0);
        }
    }
    for (const auto& option : optionPairs((int)rest.size(), rest.data(), kUsage,
                                          { "--data", "--calib-output", "--threshold", "--seed",
                                            "--dump-inputs" }))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--data")
            o.data = value;
        else if (arg == "--calib-output")
            o.calibOutput = value;
        else if (arg == "--dump-inputs")
            o.dumpInputs = value;
        else if (arg == "--threshold")
        {
            o.ransac.threshold = parseNumber(arg, value);
            if (!(o.ransac.threshold > 0))
                throw argumentError(arg, "expected a positive number of pixels, got '" + value + "'");
        }
        else
            o.ransac.seed = parseInteger(arg, value, -2147483647.0);
    }
    if (o.data.empty())
        throw std::runtime_error("argument --data is required");
    o.ransac.refine = true;
    return o;
}

double millisecondsSince(int64 start)
{
    return 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
}

//! One method's result on one triplet.
struct Outcome
{
    bool registered = false;
    double rotationDeg = NAN, translationPercent = NAN, milliseconds = 0;
    int inliers = 0, features = 0;
};

Outcome scored(const cv::Mat& R, const cv::Mat& t, const cv::Mat& Rref, const cv::Mat& tref)
{
    Outcome o;
    if (R.empty() || !cv::checkRange(R) || !cv::checkRange(t))
        return o;
    const support::PoseError e = support::poseError(R, t, Rref, tref);
    o.registered = true;
    o.rotationDeg = e.rotationDeg;
    o.translationPercent = 100 * e.relativeTranslation;
    return o;
}

Outcome runTripose(const cv::Mat points[3], const cv::Mat lines[3], const std::vector<cv::Mat>& K, const cv::Mat& R12,
                   const cv::Mat& t12, const cv::Mat& Rref, const cv::Mat& tref, const cv::tripose::RansacParams& params)
{
    const int features = points[0].rows + lines[0].rows;
    if (features < 4)
        return Outcome();
    cv::Mat R, t;
    const int64 start = cv::getTickCount();
    const int inliers = cv::tripose::estimatePoseLinePointRansac(points[0], points[1], points[2], lines[0], lines[1],
                                                                 lines[2], K, cv::noArray(), R12, t12, R, t, params);
    const double ms = millisecondsSince(start);
    Outcome o = inliers > 0 ? scored(R, t, Rref, tref) : Outcome();
    o.inliers = inliers;
    o.features = features;
    o.milliseconds = ms;
    return o;
}

//! The point tracks triangulated from views 1-2, then solvePnPRansac (SQPNP) in view 3.
Outcome runTriangulationPnp(const cv::Mat points[3], const std::vector<cv::Mat>& K, const cv::Mat& R12,
                            const cv::Mat& t12, const cv::Mat& Rref, const cv::Mat& tref,
                            const cv::tripose::RansacParams& params)
{
    if (points[0].rows < 4)
        return Outcome();
    const int64 start = cv::getTickCount();
    const cv::Mat X = cv::tripose::support::triangulateKnownPair(cv::Matx33d(K[0]), cv::Matx33d(K[1]), cv::Matx33d(R12),
                                                                 cv::Vec3d(t12), points[0], points[1]);
    cv::Mat rvec, t, inliers;
    const bool found = cv::solvePnPRansac(X.reshape(3), points[2].reshape(2), K[2], cv::noArray(), rvec, t, false,
                                          params.maxIterations, (float)params.threshold, params.confidence, inliers,
                                          cv::SOLVEPNP_SQPNP);
    const double ms = millisecondsSince(start);
    Outcome o;
    if (found)
    {
        cv::Mat R;
        cv::Rodrigues(rvec, R);
        o = scored(R, t, Rref, tref);
        o.inliers = inliers.rows;
    }
    o.features = points[0].rows;
    o.milliseconds = ms;
    return o;
}

std::string cell(const Outcome& o)
{
    if (!o.registered)
        return "not registered | - | -";
    return cv::format("%.3f | %.2f | %d/%d", o.rotationDeg, o.translationPercent, o.inliers, o.features);
}

double median(std::vector<double> v)
{
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

//! Median and maximum rotation error and the number registered, over the triplets.
std::string summary(const std::vector<Outcome>& outcomes)
{
    std::vector<double> rotations, translations;
    for (const Outcome& o : outcomes)
        if (o.registered)
        {
            rotations.push_back(o.rotationDeg);
            translations.push_back(o.translationPercent);
        }
    const double worst = rotations.empty() ? NAN : *std::max_element(rotations.begin(), rotations.end());
    return cv::format("%zu/%zu | %.3f | %.3f | %.2f", rotations.size(), outcomes.size(), median(rotations), worst,
                      median(translations));
}

//! Each image's features computed once, as a tracker would: a third of the three images' feature work.
double sequenceTime(const StageTimes& t)
{
    return (t.points + t.segmentDetection + t.segmentDescription) / 3 + t.matching + t.estimation;
}

//! The dump's numbers read back as the doubles written.
const int kDumpDigits = 17;

std::string jsonNumber(double x)
{
    return support::jsonNumber(x, kDumpDigits);
}

std::string jsonMatrix(const cv::Mat& m)
{
    return support::jsonMatrix(m, kDumpDigits);
}

std::string jsonOutcome(const Outcome& o)
{
    return cv::format("{\"ok\":%s,\"rot_deg\":%s,\"t_percent\":%s,\"inliers\":%d,\"features\":%d}",
                      o.registered ? "true" : "false", jsonNumber(o.rotationDeg).c_str(),
                      jsonNumber(o.translationPercent).c_str(), o.inliers, o.features);
}

/** One triplet as a JSON object, in the form of tripose_evaluate --dump-inputs (K, R12, t12, R_gt,
t_gt, points1..3, lines1..3, and the structure of views 1-2: points3d_12, lines3d_12), for peers run
from Python on the same matches; with the views and two of this report's results. */
std::string inputsJson(const int v[3], const std::vector<cv::Mat>& K, const cv::Mat& R12, const cv::Mat& t12,
                       const cv::Mat& Rref, const cv::Mat& tref, const cv::tripose::FeatureTriplets& triplets, const Outcome& all,
                       const Outcome& pnp)
{
    const cv::Matx33d K1(K[0]), K2(K[1]), R(R12);
    const cv::Vec3d t(t12);
    const int64 start = cv::getTickCount();
    const cv::Mat X = support::triangulateKnownPair(K1, K2, R, t, triplets.points[0], triplets.points[1]);
    // As the overlay of tripose_images: an end point whose ray runs within about a degree of view 2's
    // plane through the segment has no depth from views 1-2.
    const cv::Mat L = support::liftSegmentsKnownPair(K1, K2, R, t, triplets.lines[0], triplets.lines[1], 1e-2);
    const double triangulationUs = 1e3 * millisecondsSince(start);
    std::string s = cv::format("{\"views\":[%d,%d,%d],\"K\":[", v[0], v[1], v[2]);
    for (int k = 0; k < 3; ++k)
        s += (k ? "," : "") + jsonMatrix(K[k]);
    s += "],\"R12\":" + jsonMatrix(R12) + ",\"t12\":" + jsonMatrix(t12.reshape(1, 1)) + ",\"R_gt\":" + jsonMatrix(Rref) +
         ",\"t_gt\":" + jsonMatrix(tref.reshape(1, 1));
    for (int k = 0; k < 3; ++k)
        s += cv::format(",\"points%d\":", k + 1) + jsonMatrix(triplets.points[k]) + cv::format(",\"lines%d\":", k + 1) +
             jsonMatrix(triplets.lines[k]);
    s += ",\"points3d_12\":" + jsonMatrix(X) + ",\"lines3d_12\":" + jsonMatrix(L) +
         ",\"triangulation_us\":" + jsonNumber(triangulationUs);
    s += ",\"tripose\":" + jsonOutcome(all) + ",\"tri_sqpnp\":" + jsonOutcome(pnp) + "}";
    return s;
}

//! View @p b's pose relative to view @p a (both relative to a common world).
void relativePose(const support::VggSequence& s, int a, int b, cv::Mat& R, cv::Mat& t)
{
    R = s.Rs[b] * s.Rs[a].t();
    t = s.ts[b] - R * s.ts[a];
}

int writeCalibration(const Options& options, const support::VggSequence& sequence)
{
    const int F = (int)sequence.Rs.size();
    for (int k = 0; k < 3; ++k)
        if (options.views[k] >= F)
        {
            std::cerr << "tripose_images_report: argument --views: " << options.data << " has " << F << " views\n";
            return 1;
        }
    cv::Mat R12, t12, R, t;
    relativePose(sequence, options.views[0], options.views[1], R12, t12);
    relativePose(sequence, options.views[0], options.views[2], R, t);
    writeAtomically(options.calibOutput, [&](cv::FileStorage& fs) {
        for (int k = 0; k < 3; ++k)
            fs << "K" + std::to_string(k + 1) << sequence.cameraMatrices[options.views[k]];
        fs << "R12" << R12 << "t12" << t12 << "R_gt" << R << "t_gt" << t;
    });
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    support::VggSequence sequence;
    try
    {
        options = parseArguments(argc, argv);
        sequence = support::loadVggSequence(options.data);
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_images_report: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_images_report: " << e.what() << "\n" << kUsage;
        return 1;
    }
    if (!options.calibOutput.empty())
        return writeCalibration(options, sequence);

    const int F = (int)sequence.Rs.size();
    const std::vector<std::string> files = imageFilesIn(options.data);
    if ((int)files.size() != F)
    {
        std::cerr << "tripose_images_report: " << options.data << " holds " << files.size() << " images for " << F
                  << " cameras\n";
        return 1;
    }

    std::vector<cv::Mat> images(F);
    try
    {
        for (int k = 0; k < F; ++k)
        {
            images[k] = readImage(files[k]);
            checkImageFitsCalibration(images[k], files[k], cv::Matx33d(sequence.cameraMatrices[k]),
                                      "camera " + std::to_string(k));
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_images_report: " << e.what() << "\n";
        return 1;
    }
    std::ofstream dump;
    if (!options.dumpInputs.empty())
    {
        dump.open(options.dumpInputs);
        if (!dump)
        {
            std::cerr << "tripose_images_report: argument --dump-inputs: cannot write " << options.dumpInputs << "\n";
            return 1;
        }
    }

    // Features of images larger than --max-image-size's default are detected reduced: the pixel
    // tolerances of the matching and of the estimates on them grow by the reduction.
    const double pixelScale = detectionScale(images, options.features.maxImageSize);
    const cv::tripose::MatchParams matching = withPixelScale(cv::tripose::MatchParams(), pixelScale);
    const cv::tripose::RansacParams imageRansac = withPixelScale(options.ransac, pixelScale);
    std::vector<Outcome> all, pointsOnly, pnp, ownCorrespondences;
    std::vector<StageTimes> tripletTimes;
    std::vector<std::string> rows, timeRows;
    for (int k = 0; k + 2 < F; ++k)
    {
        const int v[3] = { k, k + 1, k + 2 };
        cv::Mat R12, t12, Rref, tref;
        relativePose(sequence, v[0], v[1], R12, t12);
        relativePose(sequence, v[0], v[2], Rref, tref);
        std::vector<cv::Mat> K = { sequence.cameraMatrices[v[0]], sequence.cameraMatrices[v[1]],
                                   sequence.cameraMatrices[v[2]] };
        const cv::Matx33d Kx[3] = { cv::Matx33d(K[0]), cv::Matx33d(K[1]), cv::Matx33d(K[2]) };
        // The whole pipeline from three fresh images, as tripose_images runs it, timed per stage.
        StageTimes times;
        const std::vector<ImageFeatures> features = extractFeaturesOfImages(
            { images[v[0]], images[v[1]], images[v[2]] }, { Kx[0], Kx[1], Kx[2] }, {}, options.features, times);
        const ImageFeatures views[3] = { features[0], features[1], features[2] };
        const int64 matchingStart = cv::getTickCount();
        const cv::tripose::FeatureTriplets triplets =
            cv::tripose::matchFeatureTriplets(views[0], views[1], views[2], K, R12, t12, matching);
        times.matching += 1e3 * double(cv::getTickCount() - matchingStart) / cv::getTickFrequency();

        all.push_back(runTripose(triplets.points, triplets.lines, K, R12, t12, Rref, tref, imageRansac));
        times.estimation = all.back().milliseconds;
        const cv::Mat noLines[3] = { cv::Mat(0, 4, CV_64F), cv::Mat(0, 4, CV_64F), cv::Mat(0, 4, CV_64F) };
        pointsOnly.push_back(runTripose(triplets.points, noLines, K, R12, t12, Rref, tref, imageRansac));
        pnp.push_back(runTriangulationPnp(triplets.points, K, R12, t12, Rref, tref, imageRansac));

        const support::VggTriplet own = support::loadVggTriplet(options.data, v[0], v[1], v[2]);
        const cv::Mat ownPoints[3] = { own.points1, own.points2, own.points3 };
        const cv::Mat ownLines[3] = { own.lines1, own.lines2, own.lines3 };
        // The sequence's hand-checked correspondences under least squares, as tripose_vgg_report.
        cv::tripose::RansacParams ownParams;
        ownParams.threshold = options.ransac.threshold;
        ownParams.seed = options.ransac.seed;
        ownParams.refine = true;
        ownCorrespondences.push_back(
            runTripose(ownPoints, ownLines, own.cameraMatrices, own.R12, own.t12, own.R, own.t, ownParams));
        tripletTimes.push_back(times);

        rows.push_back(cv::format("| %d-%d-%d | %d | %d | %s | %s | %s | %s |", v[0], v[1], v[2], triplets.points[0].rows,
                                  triplets.lines[0].rows, cell(all.back()).c_str(), cell(pointsOnly.back()).c_str(),
                                  cell(pnp.back()).c_str(), cell(ownCorrespondences.back()).c_str()));
        timeRows.push_back(cv::format("| %d-%d-%d | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f | %.0f | %.0f | %.0f | %.1f | %.1f |",
                                      v[0], v[1], v[2], times.points, times.segmentDetection, times.segmentDescription,
                                      times.featuresWall, times.matching, times.estimation, times.total(),
                                      times.wallTotal(), sequenceTime(times), pointsOnly.back().milliseconds,
                                      pnp.back().milliseconds));
        if (dump.is_open())
            dump << inputsJson(v, K, R12, t12, Rref, tref, triplets, all.back(), pnp.back()) << "\n";
    }

    std::cout << "Sequence " << options.data << ": " << F << " frames; RANSAC threshold " << options.ransac.threshold
              << " px, seed " << options.ransac.seed << "\n\n";
    std::cout << "Per triplet: rotation error (deg), translation error (% of |t|), inliers/features of tripose points "
                 "and lines (P+L), tripose points only (P), triangulation + solvePnPRansac SQPNP (PnP), and tripose on the "
                 "sequence's own correspondences (own)\n\n";
    std::cout << "| views | point tracks | segment triplets | P+L rot | P+L t | P+L inliers | P rot | P t | P inliers | "
                 "PnP rot | PnP t | PnP inliers | own rot | own t | own inliers |\n";
    std::cout << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const std::string& row : rows)
        std::cout << row << "\n";
    std::cout << "\nSummary: registered | median rotation (deg) | max rotation (deg) | median translation (%)\n\n";
    std::cout << "| method | registered | median rot (deg) | max rot (deg) | median t (%) |\n| --- | --- | --- | --- | --- |\n";
    std::cout << "| tripose points+lines | " << summary(all) << " |\n";
    std::cout << "| tripose points only | " << summary(pointsOnly) << " |\n";
    std::cout << "| triangulation + PnP (SQPNP) | " << summary(pnp) << " |\n";
    std::cout << "| tripose, sequence's correspondences | " << summary(ownCorrespondences) << " |\n";
    std::cout << "\nTime per triplet (ms), from three fresh images: each feature stage summed over the three images "
                 "(SIFT; EDLines; LBD), the feature stages' wall-clock time (the images in parallel), matching, tripose "
                 "points+lines estimation; the work (sum of the stages), the wall-clock total, the total with each "
                 "image's features computed once in a sequence (a third of the feature work); the estimation of points "
                 "only and of triangulation + PnP\n\n";
    std::cout << "| views | SIFT | EDLines | LBD | features, wall | matching | estimation | work | total, wall | "
                 "total, sequence | points-only est. | triangulation + PnP |\n";
    std::cout << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const std::string& row : timeRows)
        std::cout << row << "\n";
    std::vector<double> columns[8];
    for (const StageTimes& t : tripletTimes)
    {
        const double values[8] = { t.points, t.segmentDetection, t.segmentDescription, t.featuresWall,
                                   t.matching, t.estimation, t.wallTotal(), sequenceTime(t) };
        for (int c = 0; c < 8; ++c)
            columns[c].push_back(values[c]);
    }
    std::cout << cv::format("| median | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f | - | %.0f | %.0f | - | - |\n",
                            median(columns[0]), median(columns[1]), median(columns[2]), median(columns[3]),
                            median(columns[4]), median(columns[5]), median(columns[6]), median(columns[7]));
    std::cout << cv::format("\nMedian time per triplet: %.0f ms wall-clock from three fresh images, %.0f ms in a "
                            "sequence\n", median(columns[6]), median(columns[7]));
    return 0;
}
