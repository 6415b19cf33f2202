// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The Corridor analysis of doc/studies/tracking.md: where registration and maximum-likelihood refinement
// put the frames of a VGG sequence when frames 0 and 1 are given.
//
//   tripose_tracking_study --data <sequence> --floor
//       each frame from 2 on registered (RANSAC + refinement) against every other frame at the
//       sequence's poses: the error of registration alone, per frame in % of the path;
//   tripose_tracking_study --data <sequence> --adjust [--start track.yml] [--loss squared|huber]
//       every frame from 2 on and the structure refined together (adjustPosesMultiView, frames 0
//       and 1 fixed; Huber loss at 2 px by default), started at the sequence's poses or at the poses
//       of a tripose_track output: the maximum-likelihood estimate of the whole sequence given
//       frames 0 and 1; prints each frame's position error and the last frame's drift. A key of
//       track.yml that tripose_track does not write is an error naming it (--allow-unknown-keys:
//       accept such keys).

#include <exception>
#include <iostream>
#include <string>

#include <opencv2/tripose.hpp>

#include "problem_io.hpp"
#include "sequence_tracking.hpp"
#include "tripose_support/vgg_dataset.hpp"

namespace {

double centreDistance(const cv::Mat& R, const cv::Mat& t, const cv::Mat& Rref, const cv::Mat& tref)
{
    return cv::norm(cv::Mat(-R.t() * t), cv::Mat(-Rref.t() * tref));
}

} // namespace

int main(int argc, char** argv)
{
    std::string data, start;
    std::string loss = "huber";
    bool floor = false, adjust = false, allowUnknownKeys = false;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--data" && i + 1 < argc)
            data = argv[++i];
        else if (arg == "--start" && i + 1 < argc)
            start = argv[++i];
        else if (arg == "--loss" && i + 1 < argc)
            loss = argv[++i];
        else if (arg == "--adjust")
            adjust = true;
        else if (arg == "--floor")
            floor = true;
        else if (arg == "--allow-unknown-keys")
            allowUnknownKeys = true;
        else
        {
            std::cerr << "tripose_tracking_study: unknown or incomplete argument " << arg << "\n";
            return 1;
        }
    }
    if (floor == adjust || (loss != "huber" && loss != "squared"))
    {
        std::cerr << "usage: tripose_tracking_study --data <sequence> (--floor | --adjust [--start track.yml] "
                     "[--loss squared|huber] [--allow-unknown-keys])\n";
        return 1;
    }
    try
    {
        const cv::tripose::support::VggSequence seq = cv::tripose::support::loadVggSequence(data);
        const int F = (int)seq.Rs.size();
        tripose_samples::SequenceObservations obs;
        obs.cameraMatrices = seq.cameraMatrices;
        obs.points = seq.points;
        obs.lines = seq.lines;
        std::vector<cv::tripose::TrackedFrame> frames(F);
        for (int k = 0; k < F; ++k)
        {
            frames[k].status = k < 2 ? cv::tripose::FRAME_GIVEN : cv::tripose::FRAME_REGISTERED;
            frames[k].R = seq.Rs[k].clone();
            frames[k].t = seq.ts[k].clone();
        }
        double path = 0;
        for (int k = 1; k < F; ++k)
            path += centreDistance(seq.Rs[k], seq.ts[k], seq.Rs[k - 1], seq.ts[k - 1]);

        if (floor)
        {
            for (int k = 2; k < F; ++k)
            {
                std::vector<int> others;
                for (int j = 0; j < F; ++j)
                    if (j != k)
                        others.push_back(j);
                std::vector<cv::Mat> p, l, K, Rs, ts;
                int features = 0;
                cv::Mat R, t;
                if (!tripose_samples::registrationViews(obs, frames, k, others, p, l, K, Rs, ts, features) ||
                    cv::tripose::estimatePoseMultiViewRansac(p, l, K, cv::noArray(), Rs, ts, R, t) == 0)
                {
                    std::cout << "frame " << k << ": no pose\n";
                    continue;
                }
                std::cout << cv::format("frame %d: %d features, position error %.3f %% of the path\n", k, features,
                                        100 * centreDistance(R, t, seq.Rs[k], seq.ts[k]) / path);
            }
            return 0;
        }

        if (!start.empty())
        {
            cv::FileStorage fs(start, cv::FileStorage::READ);
            cv::Mat poses;
            if (fs.isOpened())
            {
                // A typo ("pose") would otherwise read as a missing key and a confusing message.
                if (!allowUnknownKeys)
                    tripose_samples::checkKeys(fs.root().keys(), tripose_samples::trackResultKeys(), start);
                fs["poses"] >> poses;
            }
            if (poses.rows != F || poses.cols != 12 || poses.type() != CV_64F || !cv::checkRange(poses.rowRange(2, F)))
            {
                std::cerr << "tripose_tracking_study: " << start << ": expected poses, " << F
                          << " x 12 CV_64F, every frame tracked\n";
                return 1;
            }
            for (int k = 2; k < F; ++k)
            {
                frames[k].R = poses.row(k).colRange(0, 9).clone().reshape(1, 3);
                frames[k].t = poses.row(k).colRange(9, 12).clone().t();
            }
        }
        cv::tripose::RefineParams params;
        params.loss = loss == "huber" ? cv::tripose::LOSS_HUBER : cv::tripose::LOSS_SQUARED;
        params.lossScale = 2;
        params.maxIterations = 200;
        std::cout << cv::format("start: last frame %.3f %% of the path\n",
                                100 * centreDistance(frames[F - 1].R, frames[F - 1].t, seq.Rs[F - 1], seq.ts[F - 1]) / path);
        std::vector<int> fixed = { 0, 1 }, free;
        for (int k = 2; k < F; ++k)
            free.push_back(k);
        const double rms = tripose_samples::adjustFrames(obs, frames, free, fixed, params);
        std::cout << cv::format("adjusted: RMS %.4f px\n", rms);
        for (int k = 2; k < F; ++k)
            std::cout << cv::format("frame %d: position error %.3f %% of the path\n", k,
                                    100 * centreDistance(frames[k].R, frames[k].t, seq.Rs[k], seq.ts[k]) / path);
        std::cout << cv::format("last frame %.3f %% of the path\n",
                                100 * centreDistance(frames[F - 1].R, frames[F - 1].t, seq.Rs[F - 1], seq.ts[F - 1]) / path);
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_tracking_study: " << e.err << "\n";
        return 1;
    }
    catch (const std::exception& e) // an unknown key of --start's file
    {
        std::cerr << "tripose_tracking_study: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
