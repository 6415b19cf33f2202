// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_images: the pose of view 3 straight from three images. Finds SIFT points and EDLines
// segments fitted to their edges (LBD descriptors) in each, matches views 1-2 under their known
// relative pose and view 3 under the geometry of its descriptor matches with view 2, and runs
// cv::tripose::estimatePoseLinePointRansac with refinement (Cauchy loss,
// samples/common/image_estimation.hpp) on the triplets.
//
//   tripose_images --calib calib.yml --images a.png b.png c.png --output result.yml
//                  [--overlay overlay.png] [--matches matches.png] [--features points|lines|all] [--threshold px] [--seed n]
//                  [--max-image-size px]
//
// The result holds what tripose_estimate --method ransac writes, the numbers of point tracks and
// segment triplets, the time per stage, and the matched features as a problem file (K.., R12, t12,
// points1..3, lines1..3), so that tripose_estimate runs on it again. Exit status: 0 on success, 1 on
// bad arguments or input, the solver's rejection of the calibration among them (the message names
// the file, key or argument), 3 when no reliable pose is found (fewer inliers than
// RansacParams::minInliers); no output is written on 1 or 3.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/tripose.hpp>

#include "arguments.hpp"
#include "feature_matching.hpp"
#include "image_estimation.hpp"
#include "image_features.hpp"
#include "image_input.hpp"
#include "problem_io.hpp"
#include "two_view_geometry.hpp"
#include "tripose_support/known_pair_structure.hpp"

using namespace tripose_samples;

namespace {

const char* kUsage =
    "usage: tripose_images --calib calib.yml --images a.png b.png c.png --output result.yml\n"
    "                      [--overlay overlay.png] [--matches matches.png] [--features points|lines|all]\n"
    "                      [--threshold px] [--seed n] [--max-image-size px]\n"
    "  --calib     calibration (OpenCV FileStorage, YAML or JSON; the calibration keys of a problem file):\n"
    "              K or K1..K3, [dist or dist1..dist3], R12, t12 (view 2's pose; view 1 is the world frame)\n"
    "  --images    the three images, views 1, 2 and 3\n"
    "  --output    result: num_solutions, R, t, num_inliers, point_inliers, line_inliers,\n"
    "              num_point_tracks, num_segment_triplets, pixel_scale, threshold and loss_scale (the\n"
    "              estimate's, in the images' pixels), ms_* (time per stage), and the matched features\n"
    "              as a problem\n"
    "              (K.., R12, t12, points1..3, lines1..3; undistorted pixels, so no dist)\n"
    "  --matches   the three images side by side, each point track and segment triplet drawn in all three:\n"
    "              inliers of the estimate green, the rest red\n"
    "  --overlay   the third image with the inlier features (red) and the structure of views 1-2\n"
    "              reprojected by the estimate (green)\n"
    "  --features  points (SIFT), lines (EDLines + LBD) or all (default)\n"
    "  --threshold RANSAC inlier threshold in pixels of the images as detected (default 2)\n"
    "  --seed      RANSAC sampler seed (default 0)\n"
    "  --max-image-size  detect the features in images reduced to this longer side (px; default 1600,\n"
    "              0: full size); positions are mapped back to the images' pixels and the pixel\n"
    "              tolerances (matching, --threshold) grow by the reduction\n"
    "exit status: 0 pose written, 1 bad arguments or input (nothing written), 3 no reliable pose: fewer\n"
    "              inliers than the floor of 15 (nothing written)\n";

// The estimators need four features.
const int kMinFeatures = 4;

struct Options
{
    std::string calib, output, overlay, matches;
    std::vector<std::string> images;
    FeatureOptions features;
    cv::tripose::RansacParams ransac = imageRansacParams();
};

Options parseArguments(int argc, char** argv)
{
    // --images takes three values: set them aside, the rest are (option, value) pairs.
    Options o;
    std::vector<char*> rest = { argv[0] };
    for (int i = 1; i < argc; ++i)
    {
        if (std::string(argv[i]) != "--images")
        {
            rest.push_back(argv[i]);
            continue;
        }
        if (!o.images.empty())
            throw argumentError("--images", "given twice");
        while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0)
            o.images.push_back(argv[++i]);
        if (o.images.size() != 3)
            throw argumentError("--images", "expected three image files, got " + std::to_string(o.images.size()));
    }
    const std::vector<std::string> known = { "--calib",    "--output",    "--overlay", "--matches",
                                               "--features", "--threshold", "--seed", "--max-image-size" };
    for (const auto& option : optionPairs((int)rest.size(), rest.data(), kUsage, known))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--calib")
            o.calib = value;
        else if (arg == "--output")
            o.output = value;
        else if (arg == "--overlay")
            o.overlay = value;
        else if (arg == "--matches")
            o.matches = value;
        else if (arg == "--features")
        {
            if (!parseFeatureKinds(value, o.features.kinds))
                throw argumentError(arg, "expected points, lines or all, got '" + value + "'");
        }
        else if (arg == "--threshold")
        {
            o.ransac.threshold = parseNumber(arg, value);
            if (!(o.ransac.threshold > 0))
                throw argumentError(arg, "expected a positive number of pixels, got '" + value + "'");
        }
        else if (arg == "--max-image-size")
            o.features.maxImageSize = parseInteger(arg, value, 0.0);
        else // --seed
            o.ransac.seed = parseInteger(arg, value, -2147483647.0);
    }
    if (o.calib.empty())
        throw std::runtime_error("argument --calib is required");
    if (o.images.empty())
        throw std::runtime_error("argument --images is required");
    if (o.output.empty())
        throw std::runtime_error("argument --output is required");
    o.ransac.refine = true;
    return o;
}

//! The calibration keys of a problem file; errors name the file.
Problem readCalibration(const std::string& path)
{
    Problem calibration;
    try
    {
        calibration = readProblem(path);
    }
    catch (const std::exception& e)
    {
        throw std::runtime_error("calibration " + path + ": " + e.what());
    }
    if (calibration.stereo)
        throw std::runtime_error("calibration " + path + ": holds a stereo rig (points4/lines4); three views expected");
    // Views 1 and 2 are matched under their epipolar geometry and the structure is triangulated
    // between them: checked here, before the features' time is spent, as the solver would after it.
    if (!(cv::norm(calibration.t12) > 0))
        throw std::runtime_error("calibration " + path + ": key 't12': must be non-zero (views 1 and 2 need a baseline)");
    return calibration;
}

cv::Matx33d cameraMatrixOf(const Problem& p, int view)
{
    return cv::Matx33d(p.K[p.K.size() == 1 ? 0 : view]);
}

cv::Mat distortionOf(const Problem& p, int view)
{
    return p.dist.empty() ? cv::Mat() : p.dist[p.dist.size() == 1 ? 0 : view];
}

std::string cameraKey(const Problem& p, int view)
{
    return p.K.size() == 1 ? "K" : "K" + std::to_string(view + 1);
}

//! @p image as 8-bit BGR.
cv::Mat colourCopy(const cv::Mat& image)
{
    cv::Mat canvas;
    if (image.channels() == 1)
        cv::cvtColor(image, canvas, cv::COLOR_GRAY2BGR);
    else if (image.channels() == 4)
        cv::cvtColor(image, canvas, cv::COLOR_BGRA2BGR);
    else
        canvas = image.clone();
    return canvas;
}

/** The third image with the inlier observations (red) and, in green, the points and segments of views
1-2 triangulated with the known pose and projected by the estimated one. */
cv::Mat drawOverlay(const cv::Mat& image, const Problem& matched, const cv::Mat& R, const cv::Mat& t,
                    const cv::Mat& pointInliers, const cv::Mat& lineInliers)
{
    cv::Mat canvas = colourCopy(image);
    const cv::Scalar red(40, 40, 230), green(40, 200, 40);
    using namespace cv::tripose::support;
    const cv::Matx33d K1 = cameraMatrixOf(matched, 0), K2 = cameraMatrixOf(matched, 1);
    const cv::Matx33d R12(matched.R12);
    const cv::Vec3d t12(matched.t12);
    const cv::Matx34d P3 = projectionMatrix(cameraMatrixOf(matched, 2), cv::Matx33d(R), cv::Vec3d(t));
    const cv::Mat points3d = triangulateKnownPair(K1, K2, R12, t12, matched.points[0], matched.points[1]);
    // A ray within a degree or so of view 2's plane: those views do not fix the end point's depth.
    const cv::Mat segments3d = liftSegmentsKnownPair(K1, K2, R12, t12, matched.lines[0], matched.lines[1], 1e-2);
    for (int i = 0; i < matched.points[2].rows; ++i)
    {
        if (!pointInliers.at<uchar>(i))
            continue;
        const cv::Point2d observed(matched.points[2].at<double>(i, 0), matched.points[2].at<double>(i, 1));
        cv::circle(canvas, observed, 4, red, 1, cv::LINE_AA);
        cv::Point2d projected;
        if (projectPoint(P3, cv::Vec3d(points3d.ptr<double>(i)), projected))
            cv::drawMarker(canvas, projected, green, cv::MARKER_CROSS, 7, 1, cv::LINE_AA);
    }
    for (int i = 0; i < matched.lines[2].rows; ++i)
    {
        if (!lineInliers.at<uchar>(i))
            continue;
        const double* s = matched.lines[2].ptr<double>(i);
        cv::line(canvas, cv::Point2d(s[0], s[1]), cv::Point2d(s[2], s[3]), red, 3, cv::LINE_AA);
        const double* X = segments3d.ptr<double>(i);
        cv::Point2d a, b;
        if (projectPoint(P3, cv::Vec3d(X), a) && projectPoint(P3, cv::Vec3d(X + 3), b))
            cv::line(canvas, a, b, green, 1, cv::LINE_AA);
    }
    return canvas;
}

/** The three images side by side (at the height of the first, at most 1800 px wide in all), each point
track as a circle in every view with a line from its position in the view before, each segment
triplet as its three segments; green for the estimate's inliers, red for the rest (all red when no
pose was found). */
cv::Mat drawMatches(const std::vector<cv::Mat>& images, const Problem& matched, const cv::Mat& pointInliers,
                    const cv::Mat& lineInliers)
{
    double width = 0;
    for (const cv::Mat& image : images)
        width += image.cols * double(images[0].rows) / image.rows;
    const int height = (int)std::lround(images[0].rows * std::min(1.0, 1800.0 / width));
    std::vector<cv::Mat> panels;
    std::vector<double> scale;
    std::vector<double> offset;
    double x = 0;
    for (const cv::Mat& image : images)
    {
        scale.push_back(double(height) / image.rows);
        offset.push_back(x);
        cv::Mat panel;
        cv::resize(colourCopy(image), panel, cv::Size(), scale.back(), scale.back(), cv::INTER_AREA);
        x += panel.cols;
        panels.push_back(panel);
    }
    cv::Mat canvas;
    cv::hconcat(panels, canvas);
    // Dimmed, so that thin lines show on any texture.
    canvas.convertTo(canvas, -1, 0.6, 40);
    const cv::Scalar green(40, 200, 40), red(40, 40, 230);
    auto at = [&](int view, double u, double v) { return cv::Point2d(offset[view] + scale[view] * u, scale[view] * v); };
    auto inlier = [](const cv::Mat& mask, int i) { return !mask.empty() && mask.at<uchar>(i) != 0; };
    for (int i = 0; i < matched.points[0].rows; ++i)
    {
        const cv::Scalar colour = inlier(pointInliers, i) ? green : red;
        for (int v = 0; v < 3; ++v)
        {
            const double* p = matched.points[v].ptr<double>(i);
            cv::circle(canvas, at(v, p[0], p[1]), 3, colour, 1, cv::LINE_AA);
            if (v > 0)
            {
                // The track's motion since the view before, drawn inside this view.
                const double* q = matched.points[v - 1].ptr<double>(i);
                cv::line(canvas, at(v, q[0], q[1]), at(v, p[0], p[1]), colour, 1, cv::LINE_AA);
            }
        }
    }
    for (int i = 0; i < matched.lines[0].rows; ++i)
    {
        const cv::Scalar colour = inlier(lineInliers, i) ? green : red;
        for (int v = 0; v < 3; ++v)
        {
            const double* s = matched.lines[v].ptr<double>(i);
            cv::line(canvas, at(v, s[0], s[1]), at(v, s[2], s[3]), colour, 2, cv::LINE_AA);
        }
    }
    return canvas;
}

void writePng(const std::string& path, const cv::Mat& image)
{
    std::vector<uchar> png;
    if (!cv::imencode(".png", image, png))
        throw std::runtime_error("cannot encode " + path);
    writeFileAtomically(path, png);
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    Problem calibration;
    std::vector<cv::Mat> images;
    try
    {
        options = parseArguments(argc, argv);
        checkWritable(options.output, "--output");
        checkWritable(options.overlay, "--overlay");
        checkWritable(options.matches, "--matches");
        calibration = readCalibration(options.calib);
        for (int v = 0; v < 3; ++v)
        {
            images.push_back(readImage(options.images[v]));
            checkImageFitsCalibration(images[v], options.images[v], cameraMatrixOf(calibration, v),
                                      cameraKey(calibration, v));
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_images: " << e.what() << "\n";
        return 1;
    }

    // Front end: features of each image, then views 1-2 under their pose and view 3 under the geometry
    // of its descriptor matches with view 2.
    StageTimes times;
    cv::Matx33d K[3];
    std::vector<cv::Mat> dist;
    for (int v = 0; v < 3; ++v)
    {
        K[v] = cameraMatrixOf(calibration, v);
        dist.push_back(distortionOf(calibration, v));
    }
    // Features found in reduced images are that much less precise in the images' pixels: every pixel
    // tolerance, the matching's and the estimate's, grows by the reduction.
    const double pixelScale = detectionScale(images, options.features.maxImageSize);
    const std::string reduction = reductionNote(pixelScale, options.features.maxImageSize);
    const cv::tripose::RansacParams ransac = withPixelScale(options.ransac, pixelScale);
    if (!reduction.empty())
        std::cout << "tripose_images: " << reduction << "; pixel tolerances scaled by it\n";
    const std::vector<ImageFeatures> extracted =
        extractFeaturesOfImages(images, { K[0], K[1], K[2] }, dist, options.features, times);
    const ImageFeatures features[3] = { extracted[0], extracted[1], extracted[2] };
    // The most common calibration mistake, view 2's pose inverted (or the images in another order),
    // still yields matches and a pose, a wrong one: the descriptor matches of views 1-2, which do not
    // depend on the calibration, tell it.
    const int64 matchingStart = cv::getTickCount();
    const cv::tripose::FeatureTriplets triplets = cv::tripose::matchFeatureTriplets(
        features[0], features[1], features[2], std::vector<cv::Mat>{ cv::Mat(K[0]), cv::Mat(K[1]), cv::Mat(K[2]) },
        calibration.R12, calibration.t12, withPixelScale(cv::tripose::MatchParams(), pixelScale));
    times.matching += 1e3 * double(cv::getTickCount() - matchingStart) / cv::getTickFrequency();
    if (contradicts(triplets.pairAgreement))
        std::cerr << "tripose_images: warning: images 1 and 2 do not follow R12, t12 of " << options.calib << ": "
                  << agreementSummary(triplets.pairAgreement) << ". Is [R12 | t12] view 2's pose in view 1's frame (x2 = R12 x1 + t12, "
                  << "not its inverse), and are the images in the calibration's order?\n";
    const int tracks = triplets.points[0].rows, segments = triplets.lines[0].rows;
    std::cout << cv::format("tripose_images: %d / %d / %d points, %d / %d / %d segments; %d point pairs of views "
                            "1-2, %d point tracks; %d segment pairs, %d segment triplets\n",
                            features[0].points.rows, features[1].points.rows, features[2].points.rows,
                            features[0].segments.rows, features[1].segments.rows, features[2].segments.rows,
                            triplets.pointPairs, tracks, triplets.segmentPairs, segments);
    if (tracks + segments < kMinFeatures)
    {
        std::cerr << "tripose_images: too few features seen in all three images (" << options.images[0] << ", "
                  << options.images[1] << ", " << options.images[2] << "): " << tracks << " point tracks and "
                  << segments << " segment triplets, at least " << kMinFeatures << " needed"
                  << (reduction.empty() ? "" : " (" + reduction + ")") << "\n";
        return 1;
    }

    // The matched features as a problem: undistorted pixels, so the problem carries no dist.
    Problem matched = calibration;
    matched.dist.clear();
    for (int v = 0; v < 3; ++v)
    {
        matched.points[v] = triplets.points[v];
        matched.lines[v] = triplets.lines[v];
    }
    cv::Mat R, t, pointInliers, lineInliers;
    int inliers = 0;
    try
    {
        const int64 start = cv::getTickCount();
        // The floor is applied below rather than by the estimator, so that the message can give the
        // support of the best pose it found.
        cv::tripose::RansacParams search = ransac;
        search.minInliers = 0;
        inliers = cv::tripose::estimatePoseLinePointRansac(matched.points[0], matched.points[1], matched.points[2],
                                                           matched.lines[0], matched.lines[1], matched.lines[2],
                                                           matched.K, cv::noArray(), matched.R12, matched.t12, R, t,
                                                           search, pointInliers, lineInliers);
        times.estimation += 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_images: the solver rejected the input" << problemKeyNamedBy(e.err) << " of "
                  << options.calib << ": " << e.err << "\n";
        return 1;
    }
    std::cout << cv::format("tripose_images: ms: points (SIFT) %.1f, segment detection (EDLines) %.1f, segment "
                            "description (LBD) %.1f (summed over the images; wall-clock %.1f, the images in "
                            "parallel), matching %.1f, estimation %.1f, total %.1f wall-clock\n",
                            times.points, times.segmentDetection, times.segmentDescription, times.featuresWall,
                            times.matching, times.estimation, times.wallTotal());
    if (R.empty() || inliers < ransac.minInliers)
    {
        std::cerr << "tripose_images: no reliable pose: " << tracks << " point tracks and " << segments
                  << " segment triplets matched, " << inliers << " inliers, fewer than the " << ransac.minInliers
                  << " a pose needs; nothing written\n";
        return 3;
    }
    std::cout << "tripose_images: " << inliers << " inliers\n";

    try
    {
        writeAtomically(options.output, [&](cv::FileStorage& fs) {
            fs << "num_solutions" << 1 << "R" << R << "t" << t;
            fs << "num_inliers" << inliers << "point_inliers" << inlierColumn(pointInliers) << "line_inliers"
               << inlierColumn(lineInliers);
            fs << "num_point_tracks" << tracks << "num_segment_triplets" << segments;
            // The tolerances the estimate used, in the images' pixels: what tripose_estimate needs to
            // solve the problem below again.
            fs << "pixel_scale" << pixelScale << "threshold" << ransac.threshold << "loss_scale"
               << ransac.refineParams.lossScale;
            fs << "ms_points" << times.points << "ms_segment_detection" << times.segmentDetection
               << "ms_segment_description" << times.segmentDescription << "ms_matching" << times.matching
               << "ms_estimation" << times.estimation << "ms_features_wall" << times.featuresWall
               << "ms_total_wall" << times.wallTotal();
            fs << "images" << "[:" << options.images[0] << options.images[1] << options.images[2] << "]";
            writeProblem(fs, matched);
        });
        if (!options.overlay.empty())
            writePng(options.overlay, drawOverlay(images[2], matched, R, t, pointInliers, lineInliers));
        if (!options.matches.empty())
            writePng(options.matches, drawMatches(images, matched, pointInliers, lineInliers));
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_images: " << e.what() << "\n";
        return 1;
    }
    std::cout << "tripose_images: result written to " << options.output << "\n";
    return 0;
}
