// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A whole sequence of given correspondences run through cv::tripose::Tracker, and the helpers of
// the tracking evaluation that re-register or re-adjust frames of a tracked sequence.

#ifndef TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP
#define TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP

#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

namespace tripose_samples {

//! A sequence's observations: per frame, the same N points (Nx2) and M segments (Mx4), NaN rows where
//! the frame does not see the feature; per frame K; the given poses of frames 0 and 1.
struct SequenceObservations
{
    std::vector<cv::Mat> cameraMatrices, points, lines;
    cv::Mat R0, t0, R1, t1;
};

/** Tracks the whole sequence with cv::tripose::Tracker::addObservations(), row i of every frame being
feature i; frames 0 and 1 are given. @p sequence receives the tracks the tracker ended with (with
TrackerParams::checkTracks it splits the tracks a registration rejects): row r of every frame is
track r. */
std::vector<cv::tripose::TrackedFrame> trackSequence(SequenceObservations& sequence,
                                                     const cv::tripose::TrackerParams& params);

/** Per frame, a row per track (NaN where the frame does not see it), from each frame's observations
@p rows (one Mat per frame, width columns) and the track of each row (-1: none, the row left out). */
std::vector<cv::Mat> observationsByTrack(const std::vector<cv::Mat>& rows, const std::vector<std::vector<int>>& tracks,
                                         int width);

/** Registration data of frame @p frame against the frames @p known (which must have poses): the
features it sees with at least two of them, as estimatePoseMultiView() takes them (one array per
known frame, then the frame's own; their K and poses). False when they are fewer than four.
*/
bool registrationViews(const SequenceObservations& sequence, const std::vector<cv::tripose::TrackedFrame>& frames,
                       int frame, const std::vector<int>& known, std::vector<cv::Mat>& points,
                       std::vector<cv::Mat>& lines, std::vector<cv::Mat>& cameraMatrices, std::vector<cv::Mat>& Rs,
                       std::vector<cv::Mat>& ts, int& features);

/** Refines frames @p free and the structure together (adjustPosesMultiView) with frames @p fixed held,
on the features seen by at least two of these frames, one of them free. Returns the RMS error (px);
+inf, frames unchanged, when the refinement fails or fewer than four features qualify.
@p fixed must hold two frames at distinct centres.
*/
double adjustFrames(const SequenceObservations& sequence, std::vector<cv::tripose::TrackedFrame>& frames,
                    const std::vector<int>& free, const std::vector<int>& fixed, const cv::tripose::RefineParams& params);

//! The top-level keys of tripose_track_vgg's result file (poses: one row per frame, R row-major then
//! t), which tools that read the file back check its keys against.
std::vector<std::string> trackResultKeys();

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_SEQUENCE_TRACKING_HPP
