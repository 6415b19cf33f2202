// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_track: tracks a camera through a folder of images, a video or a list of image files with
// cv::tripose::Tracker, and writes its trajectory in the TUM format. Points (SIFT) and segments
// (EDLines fitted to their edges, LBD) are detected in each frame; the first two frames take their
// poses from the calibration (frame 0 at the origin, frame 1 at R12, t12) or from a trajectory file.
// With --right, the images are a stereo rig's left camera and --right its right camera's, tracked
// with cv::tripose::StereoTracker: the calibration gives the rig, and no pose is needed. With --mode
// video, points are followed from frame to frame by optical flow instead (video_following.hpp) and
// given to the tracker as linked observations, in real time.
//
//   tripose_track --images <folder | video | list> [--right <folder | video | list>] --calib calib.yml
//                 [--poses initial.txt] --output trajectory.txt [--yaml result.yml] [options]

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/tripose.hpp>

#include "arguments.hpp"
#include "frame_source.hpp"
#include "image_features.hpp"
#include "image_input.hpp"
#include "problem_io.hpp"
#include "tracker_arguments.hpp"
#include "trajectory_io.hpp"
#include "video_following.hpp"

namespace {

const char* kUsage =
    "usage: tripose_track --images <folder | video | list> [--right <folder | video | list>]\n"
    "                     --calib calib.yml [--poses initial.txt]\n"
    "                     --output trajectory.txt [--yaml result.yml] [--window N] [--min-inliers N]\n"
    "                     [--threshold px] [--local-adjustment 0|1] [--loop-closure 0|1]\n"
    "                     [--keyframe-parallax deg] [--seed n] [--max-image-size px]\n"
    "                     [--contrast-threshold value] [--global-adjustment-interval N]\n"
    "                     [--max-points N] [--mode full|video]\n"
    "  --images       a folder (its images in natural name order), a video file, or a text file listing\n"
    "                 image paths (one per line, relative to the list, optionally after a timestamp)\n"
    "  --calib        K (3x3), optional dist, and, without --poses, R12 and t12: the pose of frame 1 in\n"
    "                 frame 0's camera frame (frame 0 is the world's origin; |t12| sets the scale)\n"
    "  --right        the right camera's images of a stereo rig (--images: the left camera's), as many\n"
    "                 frames as --images; the calibration then holds K1 (optional dist1) of the left\n"
    "                 camera, K2 (dist2) of the right, and R12, t12: the right camera's pose relative to\n"
    "                 the left (|t12| sets the scale). No pose is needed: frame 0's left camera is the\n"
    "                 world's origin, or the first pose of --poses. --local-adjustment and\n"
    "                 --loop-closure are not available\n"
    "  --poses        a TUM trajectory (timestamp tx ty tz qx qy qz qw, camera to world) whose lines are\n"
    "                 the poses of the first frames, in order (at least two)\n"
    "  --output       the trajectory (TUM), one line per frame with a pose; lost frames are left out\n"
    "  --yaml         also every frame's status (0 given, 1 registered, 2 lost, 3 restarted: a new map),\n"
    "                 keyframe, features, inliers, pose (R row-major, t; NaN when lost), recognised_keyframe:\n"
    "                 the keyframe of a place seen before through which the frame was registered (a loop\n"
    "                 closed, a link to an older place, a lost camera found again or two maps joined), -1\n"
    "                 for none, and map: the map its pose is in at the end (0 the first; -1 lost)\n"
    "  --window N     register each frame against the last N keyframes (default 5, at least 2)\n"
    "  --min-inliers  a frame is lost when fewer features agree with its pose (default 15)\n"
    "  --threshold    the registration's inlier threshold (px, default 2)\n"
    "  --local-adjustment 0|1: refine the window's frames and structure after each frame (default 1)\n"
    "  --loop-closure 1: after each keyframe, look for a place seen before among the older keyframes, join\n"
    "                 its tracks and close the loop through it (default 0; the least drift, at a place\n"
    "                 check per keyframe and 2 to 3.3 times the time per frame). A frame lost against\n"
    "                 the window is looked for among all keyframes either way\n"
    "  --global-adjustment-interval N: adjust every frame and the structure after each N keyframes (default\n"
    "                 0: never)\n"
    "  --keyframe-parallax  a registered frame becomes a keyframe from this parallax on (deg, default 0.1)\n"
    "  --max-image-size     detect in images reduced to this longer side (px; default 1600, 0: full size)\n"
    "  --contrast-threshold SIFT's contrast threshold (default 0.01, tripose_images' 0.04): lower finds\n"
    "                       more, fainter points, which hold a trajectory better\n"
    "  --max-points   the strongest SIFT points kept per image (default 8192, tripose_images' 4000; 0: all)\n"
    "  --mode video   for a video in real time: points (goodFeaturesToTrack) followed from frame to frame\n"
    "                 by optical flow, detected afresh only in the frame after a keyframe or when fewer\n"
    "                 than 120 survive, and given to the tracker as linked observations (no descriptors,\n"
    "                 no matching; with --right, each is found in the right image by the same flow).\n"
    "                 Keyframes from 0.5 deg of parallax unless --keyframe-parallax says otherwise;\n"
    "                 --max-image-size, --contrast-threshold, --max-points and --loop-closure do not\n"
    "                 apply. Default: full (features detected and matched in every frame)\n"
    "Exit status: 0 when the whole source was read (frames may be lost: see the table), 1 on bad\n"
    "arguments or input (the message names the option, file, frame or key; no output is written).\n";

// A video's frames are close: keyframes are spaced by this parallax (deg) instead of the full mode's
// 0.1 (a keyframe at nearly every frame, each triangulating from the narrow baselines of the last).
const double kVideoKeyframeParallaxDeg = 0.5;

struct Options
{
    std::string images, right, calib, poses, output, yaml;
    bool video = false;
    int maxImageSize = -1, maxPoints = -1;
    double contrastThreshold = -1;
    cv::tripose::TrackerParams track;
};

Options parseArguments(int argc, char** argv)
{
    using namespace tripose_samples;
    Options o;
    std::vector<std::string> known = { "--images", "--right", "--calib", "--poses", "--output", "--yaml",
                                       "--max-image-size", "--contrast-threshold", "--max-points",
                                       "--mode" };
    for (const std::string& name : trackerOptionNames("--local-adjustment"))
        known.push_back(name);
    const auto options = optionPairs(argc, argv, kUsage, known, {});
    // The video mode's defaults first, so that the options given override them.
    for (const auto& option : options)
        if (option.first == "--mode")
        {
            if (option.second != "full" && option.second != "video")
                throw argumentError(option.first, "must be full or video, got " + option.second);
            o.video = option.second == "video";
        }
    if (o.video)
        o.track.keyframeParallaxDeg = kVideoKeyframeParallaxDeg;
    for (const auto& option : options)
    {
        const std::string& arg = option.first;
        const std::string& value = option.second;
        if (arg == "--images")
            o.images = value;
        else if (arg == "--right")
            o.right = value;
        else if (arg == "--calib")
            o.calib = value;
        else if (arg == "--poses")
            o.poses = value;
        else if (arg == "--output")
            o.output = value;
        else if (arg == "--yaml")
            o.yaml = value;
        else if (arg == "--mode")
            continue;
        else if (arg == "--max-image-size")
            o.maxImageSize = parseInteger(arg, value, 0.0);
        else if (arg == "--max-points")
            o.maxPoints = parseInteger(arg, value, 0.0);
        else if (arg == "--contrast-threshold")
        {
            o.contrastThreshold = parseNumber(arg, value);
            if (!(o.contrastThreshold >= 0))
                throw argumentError(arg, "must be a number >= 0, got " + value);
        }
        else
            readTrackerOption(arg, value, "--local-adjustment", o.track);
    }
    for (const auto& required : { std::make_pair("--images", &o.images), std::make_pair("--calib", &o.calib),
                                  std::make_pair("--output", &o.output) })
        if (required.second->empty())
            throw std::runtime_error(std::string("argument ") + required.first + " is required");
    if (o.video && o.maxImageSize >= 0)
        throw argumentError("--max-image-size", "not used by --mode video (the points are followed in the full-size "
                            "frames)");
    if (o.video && o.contrastThreshold >= 0)
        throw argumentError("--contrast-threshold", "not used by --mode video (its points are corners, not SIFT's)");
    if (o.video && o.maxPoints >= 0)
        throw argumentError("--max-points", "not used by --mode video (its points are corners, not SIFT's)");
    if (o.video && o.track.loopClosure)
        throw argumentError("--loop-closure", "not used by --mode video (its points have no descriptors to "
                            "recognise a place by)");
    for (const auto& option : options)
        if (option.first == "--local-adjustment" && !o.right.empty() && parseSwitch(option.first, option.second))
            throw argumentError("--local-adjustment", "not available with --right (the stereo tracker has none)");
    if (!o.right.empty() && o.track.loopClosure)
        throw argumentError("--loop-closure", "not available with --right (the stereo tracker has none)");
    if (!o.right.empty() && o.track.globalAdjustmentInterval > 0)
        throw argumentError("--global-adjustment-interval", "not available with --right (the stereo tracker has none)");
    return o;
}

//! R12 (3x3 or a rotation vector) and t12 of a calibration file as a rotation and a translation.
void readRelativePose(const cv::Mat& R12, const cv::Mat& t12, cv::Matx33d& R, cv::Vec3d& t)
{
    cv::Mat rotation;
    R12.convertTo(rotation, CV_64F);
    if (rotation.total() == 3)
        cv::Rodrigues(rotation.reshape(1, 3), rotation);
    R = cv::Matx33d(rotation.reshape(1, 3));
    cv::Mat translation;
    t12.convertTo(translation, CV_64F);
    t = cv::Vec3d(translation.reshape(1, 3));
}

//! The poses of the first frames: from --poses, else frame 0 at the origin and frame 1 at R12, t12.
std::vector<tripose_samples::StampedPose> initialPoses(const Options& o, const tripose_samples::Problem& calib)
{
    using tripose_samples::StampedPose;
    if (!o.poses.empty())
    {
        std::vector<StampedPose> poses = tripose_samples::readTumTrajectory(o.poses);
        if (poses.size() < 2)
            throw std::runtime_error("argument --poses: " + o.poses + " holds " + std::to_string(poses.size()) +
                                     " pose(s); the first two frames need theirs");
        return poses;
    }
    if (calib.R12.empty())
        throw std::runtime_error("calibration " + o.calib + ": key 'R12': missing (give R12 and t12, the pose of "
                                 "frame 1 relative to frame 0, or --poses)");
    StampedPose first, second;
    first.R = cv::Matx33d::eye();
    first.t = cv::Vec3d(0, 0, 0);
    readRelativePose(calib.R12, calib.t12, second.R, second.t);
    return { first, second };
}

} // namespace

int main(int argc, char** argv)
{
    using namespace tripose_samples;
    Options options;
    Problem calib;
    StereoCalibration rig;
    std::vector<StampedPose> given;
    std::unique_ptr<FrameSource> source, rightSource;
    try
    {
        options = parseArguments(argc, argv);
        checkWritable(options.output, "--output");
        checkWritable(options.yaml, "--yaml");
        if (options.right.empty())
        {
            try
            {
                calib = readProblem(options.calib, false, !options.poses.empty());
            }
            catch (const std::exception& e)
            {
                throw std::runtime_error("calibration " + options.calib + ": " + e.what());
            }
            if (calib.K.size() != 1)
                throw std::runtime_error("calibration " + options.calib + ": key 'K': one camera matrix for the "
                                         "sequence expected (K1.. are per view of a triplet; K1, K2 with --right)");
            given = initialPoses(options, calib);
        }
        else
        {
            try
            {
                rig = readStereoCalibration(options.calib);
            }
            catch (const std::exception& e)
            {
                throw std::runtime_error("calibration " + options.calib + " (--right: K1, K2, R12, t12): " + e.what());
            }
            try
            {
                cv::tripose::StereoTracker::create(rig.K[0], rig.dist[0], rig.K[1], rig.dist[1], rig.R12, rig.t12,
                                                   options.track);
            }
            catch (const cv::Exception& e)
            {
                throw std::runtime_error("calibration " + options.calib + " (--right: K1, K2, R12, t12): " + e.err);
            }
            // A rig needs no pose: --poses, when given, places frame 0 only.
            if (!options.poses.empty())
            {
                given = readTumTrajectory(options.poses);
                if (given.empty())
                    throw std::runtime_error("argument --poses: " + options.poses + " holds no pose");
                given.resize(1);
            }
        }
        source.reset(new FrameSource(options.images));
        if (!options.right.empty())
            rightSource.reset(new FrameSource(options.right));
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_track: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_track: " << e.what() << "\n";
        return 1;
    }

    const bool stereo = !options.right.empty();
    const cv::Matx33d K(stereo ? rig.K[0] : calib.K[0]);
    const cv::Mat dist = stereo ? rig.dist[0] : calib.dist.empty() ? cv::Mat() : calib.dist[0];
    const cv::Matx33d rightK = stereo ? cv::Matx33d(rig.K[1]) : K;
    const char* const leftKey = stereo ? "K1" : "K";
    const int fixedFrames = stereo ? 1 : 2; // the frames whose images must be read
    FeatureOptions features = trackingFeatureOptions();
    if (options.maxImageSize >= 0)
        features.maxImageSize = options.maxImageSize;
    if (options.contrastThreshold >= 0)
        features.contrastThreshold = options.contrastThreshold;
    if (options.maxPoints >= 0)
        features.maxPoints = options.maxPoints;
    std::unique_ptr<VideoFrontEnd> video;
    if (options.video && stereo)
    {
        VideoRig videoRig;
        for (int c = 0; c < 2; ++c)
        {
            videoRig.K[c] = cv::Matx33d(rig.K[c]);
            videoRig.dist[c] = rig.dist[c];
        }
        readRelativePose(rig.R12, rig.t12, videoRig.R, videoRig.t);
        video.reset(new VideoFrontEnd(FollowOptions(), videoRig));
    }
    else if (options.video)
        video.reset(new VideoFrontEnd());
    cv::Ptr<cv::tripose::Tracker> tracker;
    cv::Ptr<cv::tripose::StereoTracker> stereoTracker;
    std::vector<cv::tripose::TrackedFrame> results;
    std::vector<double> timestamps;
    StageTimes times;
    int givenFrames = 0, registered = 0, lost = 0, restarted = 0;
    std::cout << "frame  status       inliers/features  ms    name\n";
    try
    {
        for (SourceFrame frame; source->next(frame);)
        {
            const bool hasPose = frame.index < (int)given.size();
            SourceFrame rightFrame;
            if (stereo && !rightSource->next(rightFrame))
                throw std::runtime_error("--images " + options.images + " holds more frames than --right " +
                                         options.right + " (" + std::to_string(frame.index) +
                                         "): a rig's two sources must hold the same number of frames");
            for (const SourceFrame* f : { &frame, &rightFrame })
                if (f->image.empty() && frame.index < fixedFrames && (f == &frame || stereo))
                    throw std::runtime_error("frame " + std::to_string(frame.index) + " (" + f->name + "): " +
                                             f->error + (stereo ? "; the first frame fixes the world and must be read"
                                                                : "; the first two frames fix the world and must be read"));
            ImageFeatures found, foundRight;
            if (frame.image.empty())
                std::cerr << "tripose_track: frame " << frame.index << " (" << frame.name << "): " << frame.error
                          << "; lost\n";
            else
            {
                checkImageFitsCalibration(frame.image, frame.name, K, leftKey);
                if (!tracker && !video)
                {
                    // The features of reduced images are that much less precise in the images' pixels.
                    const double pixelScale = detectionScale(frame.image.size(), features.maxImageSize);
                    options.track.ransac.threshold *= pixelScale;
                    options.track.matching.epipolarDistance *= pixelScale;
                }
                if (!video)
                    found = extractFeatures(frame.image, K, cv::Mat(), features, times);
            }
            if (stereo && rightFrame.image.empty())
                std::cerr << "tripose_track: frame " << frame.index << " (" << rightFrame.name << ", --right): "
                          << rightFrame.error << "; registered from the left image alone if it can be\n";
            else if (stereo)
            {
                checkImageFitsCalibration(rightFrame.image, rightFrame.name, rightK, "K2");
                if (!video)
                    foundRight = extractFeatures(rightFrame.image, rightK, cv::Mat(), features, times);
            }
            const cv::Mat givenR = hasPose ? cv::Mat(given[frame.index].R) : cv::Mat();
            const cv::Mat givenT = hasPose ? cv::Mat(given[frame.index].t) : cv::Mat();
            cv::tripose::TrackedFrame result;
            if (stereo && !stereoTracker)
                stereoTracker = cv::tripose::StereoTracker::create(K, dist, rightK, rig.dist[1], rig.R12, rig.t12,
                                                                   options.track);
            if (!stereo && !tracker)
                tracker = cv::tripose::Tracker::create(K, dist, options.track);
            if (video)
            {
                const VideoObservations o = video->next(frame.image, rightFrame.image);
                result = stereo ? stereoTracker->addObservations(o.points, o.pointIds, o.rightPoints, o.segments,
                                                                 o.lineIds, o.rightSegments, givenR, givenT)
                                : tracker->addObservations(o.points, o.pointIds, o.segments, o.lineIds, givenR, givenT);
                video->keyframeDone(result.keyframe);
            }
            else if (stereo)
                result = stereoTracker->addFrame(found, foundRight, givenR, givenT);
            else
                result = tracker->addFeatures(found.points, found.pointDescriptors, found.segments,
                                              found.lineDescriptors, givenR, givenT);
            const char* status = result.status == cv::tripose::FRAME_GIVEN     ? "given" :
                                 result.status == cv::tripose::FRAME_LOST      ? "LOST" :
                                 result.status == cv::tripose::FRAME_RESTARTED ? "restarted" :
                                 result.keyframe                               ? "registered" :
                                                                                 "registered*";
            givenFrames += result.status == cv::tripose::FRAME_GIVEN;
            registered += result.status == cv::tripose::FRAME_REGISTERED;
            lost += result.status == cv::tripose::FRAME_LOST;
            restarted += result.status == cv::tripose::FRAME_RESTARTED;
            std::cout << cv::format("%5d  %-11s  %7d/%-8d  %4.0f  %s", result.frame, status, result.inliers,
                                    result.features, result.milliseconds, frame.name.c_str());
            if (!result.reason.empty())
                std::cout << "  (" << result.reason << ")";
            if (result.recognisedKeyframe >= 0)
                std::cout << "  (place of keyframe " << result.recognisedKeyframe << ")";
            std::cout << "\n";
            results.push_back(result);
            timestamps.push_back(frame.timestamp);
            const cv::Vec2i agreement = tracker ? tracker->givenPairAgreement() : cv::Vec2i();
            if (result.frame == 1 && agreement[0] >= 20 && agreement[1] < 0.3 * agreement[0])
                std::cerr << "tripose_track: warning: frames 0 and 1 do not follow their given poses: of "
                          << agreement[0] << " point matches found without the poses, " << agreement[1]
                          << " lie on their epipolar lines. Are the frames in order, and the calibration theirs?\n";
        }
        SourceFrame extra;
        if (stereo && rightSource->next(extra))
            throw std::runtime_error("--right " + options.right + " holds more frames than --images " + options.images +
                                     " (" + std::to_string(results.size()) +
                                     "): a rig's two sources must hold the same number of frames");
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_track: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_track: " << e.what() << "\n";
        return 1;
    }
    const std::string restarts = restarted ? cv::format(", %d restarted", restarted) : std::string();
    const double frames = (double)std::max<size_t>(1, results.size());
    double trackingMs = 0;
    for (const auto& r : results)
        trackingMs += r.milliseconds;
    std::cout << cv::format("%zu frames: %d given, %d registered, %d lost%s; ms per frame: ", results.size(),
                            givenFrames, registered, lost, restarts.c_str());
    if (video)
        std::cout << cv::format("flow %.1f, detection %.1f%s, tracking %.1f\n", video->times().flow / frames,
                                video->times().detection / frames,
                                stereo ? cv::format(", right image %.1f", video->times().stereo / frames).c_str() : "",
                                trackingMs / frames);
    else
        std::cout << cv::format("points (SIFT) %.0f, segments (EDLines, LBD) %.0f, tracking %.0f\n",
                                times.points / frames, (times.segmentDetection + times.segmentDescription) / frames,
                                trackingMs / frames);

    try
    {
        std::string text;
        const int F = (int)results.size();
        cv::Mat poses(F, 12, CV_64F, cv::Scalar::all(std::nan(""))), status(F, 1, CV_32S), keyframes(F, 1, CV_32S),
            featureCounts(F, 1, CV_32S), inliers(F, 1, CV_32S), recognised(F, 1, CV_32S), maps(F, 1, CV_32S);
        for (int k = 0; k < F; ++k)
        {
            cv::tripose::TrackedFrame& r = results[k];
            status.at<int>(k) = r.status;
            keyframes.at<int>(k) = r.keyframe ? 1 : 0;
            featureCounts.at<int>(k) = r.features;
            inliers.at<int>(k) = r.inliers;
            recognised.at<int>(k) = r.recognisedKeyframe;
            maps.at<int>(k) = stereo ? stereoTracker->getMap(k) : (r.status == cv::tripose::FRAME_LOST ? -1 : 0);
            // The current poses: a local adjustment moves frames after their own result.
            if (r.status == cv::tripose::FRAME_LOST ||
                !(stereo ? stereoTracker->getPose(k, r.R, r.t) : tracker->getPose(k, r.R, r.t)))
                continue;
            StampedPose pose;
            pose.timestamp = timestamps[k];
            pose.R = cv::Matx33d(r.R);
            pose.t = cv::Vec3d(r.t);
            text += tumLine(pose) + "\n";
            for (int i = 0; i < 9; ++i)
                poses.at<double>(k, i) = pose.R(i / 3, i % 3);
            for (int i = 0; i < 3; ++i)
                poses.at<double>(k, 9 + i) = pose.t[i];
        }
        writeFileAtomically(options.output, std::vector<unsigned char>(text.begin(), text.end()));
        if (!options.yaml.empty())
            writeAtomically(options.yaml, [&](cv::FileStorage& fs) {
                fs << "images" << options.images;
                if (stereo)
                    fs << "right" << options.right;
                fs << "window" << options.track.window << "poses" << poses
                   << "status" << status << "keyframe" << keyframes << "features" << featureCounts << "inliers"
                   << inliers << "recognised_keyframe" << recognised << "map" << maps;
            });
    }
    catch (const std::exception& e)
    {
        std::cerr << "tripose_track: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
