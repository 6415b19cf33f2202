// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What a problem file holds: its keys (those the reader reads and the ground truth a scene file adds),
// the Problem and StereoCalibration they describe, the unknown-key check with its nearest-key
// suggestion, and the writing of a problem and of a result's inlier column.
#ifndef TRIPOSE_SAMPLES_PROBLEM_SCHEMA_HPP
#define TRIPOSE_SAMPLES_PROBLEM_SCHEMA_HPP

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace tripose_samples {

/** The keys the reader reads, written once: its key lookup (problem_reader.cpp) refuses any other
key, so that a key the reader reads cannot be missing here, and the unknown-key check (checkKeys)
accepts exactly these and kSceneKeys.
*/
inline constexpr const char* kProblemKeys[] = { "K",       "K1",      "K2",      "K3",      "K4",     "dist",   "dist1",
                                                "dist2",   "dist3",   "dist4",   "R12",     "t12",    "points1", "points2",
                                                "points3", "points4", "lines1",  "lines2",  "lines3", "lines4" };

/** The ground truth tripose_make_scene writes beside the problem keys. A scene file is a problem file
(tools and tests pass it to tripose_estimate as it is), so these keys are known, though not read.
*/
inline constexpr const char* kSceneKeys[] = { "R_gt",          "t_gt",         "points3d",         "lines3d",
                                              "point_inliers", "line_inliers", "point_visibility", "line_visibility" };

//! The fields of a matrix as FileStorage writes one: rows and cols or sizes, dt, data; JSON adds type_id.
inline constexpr const char* kMatrixFields[] = { "type_id", "rows", "cols", "sizes", "dt", "data" };

//! The inputs of estimatePoseLinePoint (three views) or estimatePoseLinePointStereo (a stereo rig,
//! four views) as read from a problem file.
struct Problem
{
    bool stereo = false;        //!< points4 or lines4 given: views 1-2 and 3-4 are a rig at two times.
    std::vector<cv::Mat> K;     //!< One 3x3 matrix (key K) or one per view (K1..K3, rig: K1..K4).
    std::vector<cv::Mat> dist;  //!< Empty, one (dist) or one per view (dist1..dist3, rig: dist1..dist4).
    cv::Mat R12, t12;           //!< Pose of view 2; for a rig, the rig (right camera w.r.t. left).
    cv::Mat points[4];          //!< Nx2 (0x2 when absent); [3] only for a rig.
    cv::Mat lines[4];           //!< Mx4 (0x4 when absent); [3] only for a rig.
    int numViews() const { return stereo ? 4 : 3; }
};

/** A stereo rig's calibration: the left camera K1 (optional dist1), the right camera K2 (dist2), or
K and dist shared by both, and the rig R12 (3x3 or 3x1 Rodrigues), t12: the right camera's pose
relative to the left (x_2 = R12 x_1 + t12).
*/
struct StereoCalibration
{
    cv::Mat K[2], dist[2]; //!< Left, right; dist empty when not given.
    cv::Mat R12, t12;
};

//! The top-level keys a problem file may hold: those readProblem reads, and the ground truth
//! tripose_make_scene writes beside them (R_gt, t_gt, points3d, ...).
std::vector<std::string> problemFileKeys();

//! The key of @p valid nearest to @p key in edits (insertions, deletions, substitutions, swaps of
//! neighbours) when it is near enough to be a typo (a third of the key's length, at least one), else "".
std::string closestKey(const std::string& key, const std::vector<std::string>& valid);

/** Throws std::runtime_error "unknown key 'point1' in <file> (did you mean 'points1'?)" for the first
of @p keys not in @p valid; with @p parent, "unknown key 'row' of 'K1' in <file> ...". Without a near
key the message lists the valid ones.
*/
void checkKeys(const std::vector<std::string>& keys, const std::vector<std::string>& valid, const std::string& file,
               const std::string& parent = "");

/** Writes the keys of a three-view problem (K or K1..K3, dist or dist1..dist3 when given, R12, t12,
points1..points3 and lines1..lines3, a kind left out when it has no rows), as readProblem() reads them.
*/
void writeProblem(cv::FileStorage& fs, const Problem& problem);

//! An inlier mask of the robust estimators as an Nx1 CV_32S column (0x1 when empty), as the result files hold it.
cv::Mat inlierColumn(const cv::Mat& mask);

/** The problem key behind the argument a solver message names, as " (key 'K2')", or "" when it names
none: the solver speaks of cameraMatrix[1] and distCoeffs, the file of K2 and dist.
*/
std::string problemKeyNamedBy(const std::string& solverMessage);

} // namespace tripose_samples

#endif // TRIPOSE_SAMPLES_PROBLEM_SCHEMA_HPP
