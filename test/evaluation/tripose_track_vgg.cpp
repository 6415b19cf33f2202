// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_track_vgg: cv::tripose::Tracker along a sequence in the Oxford VGG multi-view format,
// for the tracking evaluation (doc/studies/tracking.md). Frames 0 and 1 take their poses from the sequence;
// the others are tracked from the sequence's own correspondences or, with --from-images, from the
// folder's images (one per camera, in name order). Writes the poses, prints per-frame errors
// against the sequence's cameras and, with --plot, draws both trajectories seen from above.
//
//   tripose_track_vgg --data <VGG sequence folder> --output track.yml [--window N] [--plot trajectory.png]
//                 [--method ransac|linear] [--threshold px] [--seed n] [--check-tracks 0|1] [--min-inliers n]
//                 [--keyframe-parallax deg] [--from-images]

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/tripose.hpp>

#include "arguments.hpp"
#include "image_estimation.hpp"
#include "problem_io.hpp"
#include "sequence_tracking.hpp"
#include "tracker_arguments.hpp"
#if TRIPOSE_HAVE_IMAGE_FRONT_END
#include "image_input.hpp"
#include "image_features.hpp"
#endif
#include "tripose_support/pose_error.hpp"
#include "tripose_support/vgg_dataset.hpp"

namespace {

const char* kUsage =
    "usage: tripose_track_vgg --data <VGG sequence folder> --output track.yml [--window N] [--plot trajectory.png]\n"
    "                     [--method ransac|linear] [--threshold px] [--seed n] [--local-refine 0|1] [--from-images]\n"
    "                     [--check-tracks 0|1] [--min-inliers n] [--keyframe-parallax deg]\n"
    "                     [--observations tracks.yml] [--max-image-size px]\n"
    "  --window N     register each frame against the last N keyframes (default 5, at least 2; 2 is the\n"
    "                 three-view chain)\n"
    "  --method       ransac (default: RANSAC, then maximum-likelihood refinement) or linear\n"
    "  --local-refine 1: after each registration, refine the window's registered frames, the new one and\n"
    "                 the structure together against the earlier frames (a local bundle adjustment;\n"
    "                 default 0: off, unlike the library's default)\n"
    "  --check-tracks 1 (default): before a frame is registered, drop each feature's window observations\n"
    "                 that disagree with the window's poses by more than the threshold; after, start new\n"
    "                 tracks from the frame's observations that the registration rejected. 0: off\n"
    "  --min-inliers n  a frame whose pose fewer than n features agree with is lost (default 15; chance\n"
    "                 matches of an unrelated image gave up to 7)\n"
    "  --keyframe-parallax deg  a registered frame may enter later windows (is a keyframe) when the median\n"
    "                 angle between the rays from it and from the window's last keyframe, over its inlier\n"
    "                 points and inlier lines' end points, is at least deg (default 0.1; a camera standing\n"
    "                 still adds none; 0: every registered frame)\n"
    "  --from-images  points and segments found and matched in the folder's images (one per camera, in\n"
    "                 name order; SIFT, EDLines + LBD) instead of the sequence's correspondences\n"
    "  --max-image-size  with --from-images: detect the features in images reduced to this longer side\n"
    "                 (px; default 1600, 0: full size); --threshold and the matching's tolerance grow by\n"
    "                 the reduction\n"
    "  --observations also write the tracks the frames were registered from: per frame k (from 0) K<k>,\n"
    "                 points<k> (N x 2) and lines<k> (M x 4, segments), row i of every frame the same track,\n"
    "                 NaN where frame k does not see it\n"
    "Output (OpenCV FileStorage): poses (F x 12 CV_64F, row k: R_k row-major then t_k, x ~ K_k (R_k X + t_k),\n"
    "X in frame 0's camera frame; NaN for a lost frame), status (F x 1: 0 given, 1 registered, 2 lost),\n"
    "keyframe (F x 1: 1 for frames 0 and 1 and registered frames with enough parallax, which later\n"
    "windows may hold), features and inliers per frame,\n"
    "rotation_error_deg and position_error per frame, drift_percent.\n";

struct Options
{
    std::string data, output, plot, observations, method = "ransac";
    bool fromImages = false;
    int maxImageSize = -1; //!< --max-image-size; -1: not given (the front end's default)
    cv::tripose::TrackerParams track;
};

Options parseArguments(int argc, char** argv)
{
    using namespace tripose_samples;
    Options o;
    // The studies of the VGG sequences measure the tracker without the local adjustment unless asked.
    o.track.localAdjustment = false;
    std::vector<std::string> known = { "--data", "--output", "--plot", "--method", "--check-tracks", "--observations",
                                       "--max-image-size" };
    for (const std::string& name : trackerOptionNames("--local-refine"))
        known.push_back(name);
    for (const auto& option : optionPairs(argc, argv, kUsage, known, { "--from-images" }))
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--from-images")
            o.fromImages = true;
        else if (arg == "--data")
            o.data = value;
        else if (arg == "--output")
            o.output = value;
        else if (arg == "--plot")
            o.plot = value;
        else if (arg == "--observations")
            o.observations = value;
        else if (arg == "--method")
            o.method = value;
        else if (arg == "--check-tracks")
            o.track.checkTracks = parseSwitch(arg, value);
        else if (arg == "--max-image-size")
            o.maxImageSize = parseInteger(arg, value, 0.0);
        else
            readTrackerOption(arg, value, "--local-refine", o.track);
    }
    if (o.data.empty())
        throw std::runtime_error("argument --data is required");
    if (o.output.empty())
        throw std::runtime_error("argument --output is required");
    if (o.method != "ransac" && o.method != "linear")
        throw argumentError("--method", "expected 'ransac' or 'linear', got '" + o.method + "'");
    o.track.robust = o.method == "ransac";
    if (o.maxImageSize >= 0 && !o.fromImages)
        throw argumentError("--max-image-size", "applies to --from-images only");
    return o;
}

cv::Point2d topView(const cv::Mat& R, const cv::Mat& t)
{
    const cv::Mat c = -R.t() * t; // camera centre in frame 0; x right, z forward
    return cv::Point2d(c.at<double>(0), c.at<double>(2));
}

//! Both trajectories seen from above (x right, z up the image), PNG bytes.
std::vector<uchar> drawTrajectories(const std::vector<cv::Point2d>& reference, const std::vector<cv::Point2d>& estimated,
                                    const std::vector<bool>& valid, const std::string& title)
{
    const int width = 900, height = 700, margin = 60;
    cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    double xmin = reference[0].x, xmax = xmin, ymin = reference[0].y, ymax = ymin;
    auto extend = [&](const cv::Point2d& p) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
    };
    for (size_t k = 0; k < reference.size(); ++k)
    {
        extend(reference[k]);
        if (valid[k])
            extend(estimated[k]);
    }
    // One scale for both axes (a top view keeps its shape); a degenerate extent gets a small span.
    const double span = std::max(std::max(xmax - xmin, ymax - ymin), 1e-9);
    const double scale = std::min((width - 2.0 * margin) / std::max(xmax - xmin, 1e-3 * span),
                                  (height - 2.0 * margin) / std::max(ymax - ymin, 1e-3 * span));
    const cv::Rect2d box(xmin, ymin, xmax - xmin, ymax - ymin);
    auto pixel = [&](const cv::Point2d& p) {
        return cv::Point2d(margin + (p.x - box.x) * scale, height - margin - (p.y - box.y) * scale);
    };
    const cv::Scalar green(40, 160, 40), red(40, 40, 220);
    for (size_t k = 0; k < reference.size(); ++k)
    {
        if (k > 0)
            cv::line(image, pixel(reference[k - 1]), pixel(reference[k]), green, 2, cv::LINE_AA);
        cv::circle(image, pixel(reference[k]), 5, green, 2, cv::LINE_AA);
        cv::putText(image, std::to_string(k), pixel(reference[k]) + cv::Point2d(7, -7), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                    cv::Scalar(80, 80, 80), 1, cv::LINE_AA);
    }
    for (size_t k = 0; k < estimated.size(); ++k)
    {
        if (!valid[k])
            continue;
        if (k > 0 && valid[k - 1])
            cv::line(image, pixel(estimated[k - 1]), pixel(estimated[k]), red, 1, cv::LINE_AA);
        cv::drawMarker(image, pixel(estimated[k]), red, cv::MARKER_CROSS, 10, 1, cv::LINE_AA);
    }
    cv::putText(image, title, cv::Point(margin, 30), cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    cv::putText(image, "top view (x right, z forward of frame 0); green: sequence cameras, red: tracked",
                cv::Point(margin, height - 20), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    std::vector<uchar> png;
    cv::imencode(".png", image, png);
    return png;
}

/** The sequence tracked from the images of @p folder (one per camera, in name order), their features
detected in images reduced to @p maxImageSize (-1: the front end's default), the pixel tolerances of
@p params grown by that reduction (detectionScale()). Throws std::runtime_error naming the folder or
image when they do not fit the sequence. */
std::vector<cv::tripose::TrackedFrame> trackFolderImages(const std::string& folder,
                                                         const cv::tripose::support::VggSequence& sequence,
                                                         int maxImageSize, cv::tripose::TrackerParams params,
                                                         tripose_samples::SequenceObservations& observations)
{
#if TRIPOSE_HAVE_IMAGE_FRONT_END
    using namespace tripose_samples;
    const std::vector<std::string> files = imageFilesIn(folder);
    if (files.size() != sequence.Rs.size())
        throw std::runtime_error(cv::format("argument --from-images: %s holds %zu images for %zu cameras", folder.c_str(),
                                            files.size(), sequence.Rs.size()));
    std::vector<cv::Mat> images;
    for (size_t k = 0; k < files.size(); ++k)
    {
        images.push_back(readImage(files[k]));
        checkImageFitsCalibration(images.back(), files[k], cv::Matx33d(sequence.cameraMatrices[k]),
                                  "camera " + std::to_string(k));
    }
    StageTimes times;
    FeatureOptions features;
    if (maxImageSize >= 0)
        features.maxImageSize = maxImageSize;
    const double pixelScale = detectionScale(images, features.maxImageSize);
    const std::string reduction = reductionNote(pixelScale, features.maxImageSize);
    if (!reduction.empty())
        std::cout << "Front end: " << reduction << "; pixel tolerances scaled by it\n";
    // The features of reduced images are that much less precise in the images' pixels.
    params.ransac = withPixelScale(params.ransac, pixelScale);
    params.matching.epipolarDistance *= pixelScale;
    std::vector<cv::Matx33d> K;
    for (const cv::Mat& k : sequence.cameraMatrices)
        K.emplace_back(k);
    const std::vector<ImageFeatures> detected = extractFeaturesOfImages(images, K, {}, features, times);
    const cv::Ptr<cv::tripose::Tracker> tracker =
        cv::tripose::Tracker::create(sequence.cameraMatrices[0], cv::noArray(), params);
    std::vector<cv::tripose::TrackedFrame> frames;
    double matching = 0;
    for (size_t k = 0; k < detected.size(); ++k)
    {
        const bool given = k < 2;
        frames.push_back(tracker->addFeatures(detected[k].points, detected[k].pointDescriptors, detected[k].segments,
                                              detected[k].lineDescriptors, given ? sequence.Rs[k] : cv::Mat(),
                                              given ? sequence.ts[k] : cv::Mat(), sequence.cameraMatrices[k]));
        matching += frames.back().milliseconds;
    }
    std::vector<cv::Mat> pointRows, lineRows;
    std::vector<std::vector<int>> pointTracks, lineTracks;
    for (size_t k = 0; k < frames.size(); ++k)
    {
        if (frames[k].status != cv::tripose::FRAME_LOST)
            tracker->getPose((int)k, frames[k].R, frames[k].t);
        pointRows.push_back(detected[k].points);
        lineRows.push_back(detected[k].segments);
        cv::Mat pointTrack, lineTrack;
        tracker->getTracks((int)k, pointTrack, lineTrack);
        pointTracks.push_back(pointTrack.empty() ? std::vector<int>() : std::vector<int>(pointTrack));
        lineTracks.push_back(lineTrack.empty() ? std::vector<int>() : std::vector<int>(lineTrack));
    }
    observations.cameraMatrices = sequence.cameraMatrices;
    observations.points = observationsByTrack(pointRows, pointTracks, 2);
    observations.lines = observationsByTrack(lineRows, lineTracks, 4);
    // Images named out of the cameras' order (img10 sorts before img2) give frames 0-1 the wrong
    // poses; the tracker would still run, on wrong tracks.
    const cv::Vec2i agreement = tracker->givenPairAgreement();
    if (agreement[0] >= 20 && agreement[1] < 0.3 * agreement[0])
        std::cerr << "tripose_track_vgg: warning: the images of frames 0 and 1 (" << files[0] << ", " << files[1]
                  << ") do not follow the sequence's cameras 0 and 1: of " << agreement[0] << " point matches found "
                  << "without the poses, " << agreement[1] << " lie on their epipolar lines. Are the images, in name "
                  << "order, in the order of the cameras?\n";
    std::cout << cv::format("Front end on %zu images; ms: points (SIFT) %.0f, segment detection (EDLines) %.0f, "
                            "segment description (LBD) %.0f; matching and registration %.0f\n",
                            files.size(), times.points, times.segmentDetection, times.segmentDescription, matching);
    return frames;
#else
    (void)folder;
    (void)sequence;
    (void)maxImageSize;
    (void)params;
    (void)observations;
    throw std::runtime_error("argument --from-images: this build has no image front end (it needs OpenCV's "
                             "features2d and contrib's line_descriptor)");
#endif
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    cv::tripose::support::VggSequence sequence;
    try
    {
        options = parseArguments(argc, argv);
        tripose_samples::checkWritable(options.output, "--output");
        tripose_samples::checkWritable(options.plot, "--plot");
        tripose_samples::checkWritable(options.observations, "--observations");
        sequence = cv::tripose::support::loadVggSequence(options.data);
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_track_vgg: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_track_vgg: " << e.what() << "\n" << kUsage;
        return 1;
    }
    const int F = (int)sequence.Rs.size();
    if (F < 3)
    {
        std::cerr << "tripose_track_vgg: " << options.data << " holds " << F
                  << " frame(s); tracking needs two given frames and at least one more\n";
        return 1;
    }

    tripose_samples::SequenceObservations observations;
    std::vector<cv::tripose::TrackedFrame> frames;
    if (options.fromImages)
    {
        try
        {
            frames = trackFolderImages(options.data, sequence, options.maxImageSize, options.track, observations);
        }
        catch (const cv::Exception& e)
        {
            std::cerr << "tripose_track_vgg: " << e.err << "\n";
            return 2;
        }
        catch (const std::exception& e)
        {
            std::cerr << "tripose_track_vgg: " << e.what() << "\n";
            return 1;
        }
    }
    else
    {
        observations.cameraMatrices = sequence.cameraMatrices;
        observations.points = sequence.points;
        observations.lines = sequence.lines;
        observations.R0 = sequence.Rs[0];
        observations.t0 = sequence.ts[0];
        observations.R1 = sequence.Rs[1];
        observations.t1 = sequence.ts[1];
        try
        {
            frames = tripose_samples::trackSequence(observations, options.track);
        }
        catch (const cv::Exception& e)
        {
            std::cerr << "tripose_track_vgg: " << e.err << "\n";
            return 2;
        }
    }

    // Errors against the sequence's cameras; drift in % of the reference path length.
    std::vector<cv::Point2d> reference(F), estimated(F);
    std::vector<bool> valid(F);
    double pathLength = 0;
    for (int k = 1; k < F; ++k)
        pathLength += cv::norm(-sequence.Rs[k].t() * sequence.ts[k] - (-sequence.Rs[k - 1].t() * sequence.ts[k - 1]));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    cv::Mat poses(F, 12, CV_64F, cv::Scalar::all(nan)), status(F, 1, CV_32S), keyframes(F, 1, CV_32S),
        features(F, 1, CV_32S),
        inliers(F, 1, CV_32S), rotationErrors(F, 1, CV_64F, cv::Scalar::all(nan)),
        positionErrors(F, 1, CV_64F, cv::Scalar::all(nan));
    double totalMs = 0;
    int registered = 0, lost = 0, nonKeyframes = 0;
    std::cout << "Sequence " << options.data << ": " << F << " frames, window " << options.track.window << ", method "
              << options.method << "; path length " << pathLength << "\n"
              << "frame  status      known  features  inliers  rot.err(deg)  pos.err  pos.err(% path)  ms\n";
    for (int k = 0; k < F; ++k)
    {
        const cv::tripose::TrackedFrame& f = frames[k];
        status.at<int>(k) = (int)f.status;
        keyframes.at<int>(k) = f.keyframe ? 1 : 0;
        features.at<int>(k) = f.features;
        inliers.at<int>(k) = f.inliers;
        reference[k] = topView(sequence.Rs[k], sequence.ts[k]);
        valid[k] = f.status != cv::tripose::FRAME_LOST;
        const char* name = f.status == cv::tripose::FRAME_GIVEN      ? "given" :
                           f.status == cv::tripose::FRAME_LOST       ? "LOST" :
                           f.keyframe                                     ? "registered" :
                                                                            "registered*";
        nonKeyframes += f.status == cv::tripose::FRAME_REGISTERED && !f.keyframe;
        if (!valid[k])
        {
            ++lost;
            totalMs += f.milliseconds;
            std::cout << cv::format("%5d  %-11s %5d  %8d  %7s  %12s  %7s  %15s  %.2f\n", k, name, f.knownViews,
                                    f.features, "-", "-", "-", "-", f.milliseconds);
            continue;
        }
        for (int r = 0; r < 3; ++r)
        {
            for (int c = 0; c < 3; ++c)
                poses.at<double>(k, 3 * r + c) = f.R.at<double>(r, c);
            poses.at<double>(k, 9 + r) = f.t.at<double>(r);
        }
        estimated[k] = topView(f.R, f.t);
        const cv::tripose::support::PoseError error =
            cv::tripose::support::poseError(f.R, f.t, sequence.Rs[k], sequence.ts[k]);
        const double position = cv::norm(-f.R.t() * f.t - (-sequence.Rs[k].t() * sequence.ts[k]));
        rotationErrors.at<double>(k) = error.rotationDeg;
        positionErrors.at<double>(k) = position;
        if (f.status == cv::tripose::FRAME_REGISTERED)
        {
            ++registered;
            totalMs += f.milliseconds;
            std::cout << cv::format("%5d  %-11s %5d  %8d  %7d  %12.4f  %7.4f  %15.3f  %.2f\n", k, name, f.knownViews,
                                    f.features, f.inliers, error.rotationDeg, position, 100 * position / pathLength,
                                    f.milliseconds);
        }
        else
            std::cout << cv::format("%5d  %-11s\n", k, name);
    }
    if (nonKeyframes > 0)
        std::cout << "* not a keyframe: too little parallax with the window's last keyframe (--keyframe-parallax); "
                     "later frames are not registered against it\n";
    const double drift = valid[F - 1] ? 100 * positionErrors.at<double>(F - 1) / pathLength : nan;
    std::cout << cv::format("Drift of the last frame: %.3f %% of the path; %d registered, %d lost; %.2f ms per frame\n",
                            drift, registered, lost, totalMs / std::max(1, F - 2));

    try
    {
        tripose_samples::writeAtomically(options.output, [&](cv::FileStorage& fs) {
            fs << "sequence" << options.data << "correspondences" << (options.fromImages ? "images" : "sequence")
               << "window" << options.track.window << "method" << options.method
               << "local_refine" << (options.track.localAdjustment ? 1 : 0)
               << "check_tracks" << (options.track.checkTracks ? 1 : 0);
            fs << "poses" << poses << "status" << status << "keyframe" << keyframes << "features" << features
               << "inliers" << inliers;
            fs << "rotation_error_deg" << rotationErrors << "position_error" << positionErrors;
            fs << "path_length" << pathLength << "drift_percent" << drift;
            fs << "ms_per_frame" << totalMs / std::max(1, F - 2);
        });
        if (!options.plot.empty())
        {
            const std::string title = cv::format("%s: window %d, %s, drift %.2f %% of the path", options.data.c_str(),
                                                 options.track.window, options.method.c_str(), drift);
            tripose_samples::writeFileAtomically(options.plot, drawTrajectories(reference, estimated, valid, title));
        }
        if (!options.observations.empty())
            tripose_samples::writeAtomically(options.observations, [&](cv::FileStorage& fs) {
                for (size_t k = 0; k < observations.points.size(); ++k)
                    fs << cv::format("K%zu", k) << observations.cameraMatrices[k] << cv::format("points%zu", k)
                       << observations.points[k] << cv::format("lines%zu", k) << observations.lines[k];
            });
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_track_vgg: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
