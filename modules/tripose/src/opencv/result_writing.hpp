// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_OPENCV_RESULT_WRITING_HPP
#define OPENCV_TRIPOSE_OPENCV_RESULT_WRITING_HPP

#include <vector>

#include "opencv2/core.hpp"

#include "../core/estimator/scored_pose.hpp"
#include "../core/refine/ml_refinement.hpp"
#include "../core/robust/robust_estimator.hpp"
#include "argument_reading.hpp"
#include "core_calls.hpp"

namespace cv {
namespace tripose {
namespace detail {

//! R (3x3) and t (3x1) as CV_64F, the one form of every pose output; both released when @p pose is null.
void writePose(const core::CameraPose* pose, OutputArray R, OutputArray t);

/** @p poses into vectors of 3x3 rotations and 3x1 translations (CV_64F), where wanted;
@p RsName / @p tsName are the caller's names of the outputs, for errors.
*/
void writePoseVectors(const std::vector<core::CameraPose>& poses, OutputArrayOfArrays Rs, OutputArrayOfArrays ts,
                      const char* RsName, const char* tsName);

/** Ranked poses into vectors of 3x3 rotations and 3x1 translations and their RMS errors (Nx1
CV_64F) in @p errors, where wanted (writePoseVectors()).
*/
void writeRankedPoses(const std::vector<core::ScoredPose>& poses, OutputArrayOfArrays Rs, OutputArrayOfArrays ts,
                      OutputArray errors, const char* RsName, const char* tsName);

/** Ranked candidates as the candidate functions return them: the best in R, t (released when
there is none), all in the vectors, their RMS errors in @p errors. Returns their number.
*/
int writeCandidates(const std::vector<core::ScoredPose>& candidates, OutputArray R, OutputArray t,
                    OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray errors, const char* RsName,
                    const char* tsName);

/** What the candidate functions write: the candidates as writeCandidates() does (outputs named
candidateRs, candidateTs), and with @p refined (POSE_LINEAR_REFINE) the uncertainty of the best
one (covariance_writing.hpp; released otherwise). Returns their number.
*/
int writeCandidateEstimate(const core::ViewSet& views, const std::vector<core::ScoredPose>& candidates, bool refined,
                           OutputArray R, OutputArray t, OutputArrayOfArrays candidateRs,
                           OutputArrayOfArrays candidateTs, OutputArray errors, OutputArray covariance,
                           OutputArray noiseVariance);

/** Rejects, before any work, candidate and uncertainty outputs of the wrong kind: @p candidateRs and
@p candidateTs must be std::vector<Mat> and @p errors, @p covariance and @p noiseVariance single
arrays where wanted, so that outputs passed in another order fail naming the argument instead of
receiving another output's values.
*/
void checkCandidateOutputs(OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs, OutputArray errors,
                           OutputArray covariance, OutputArray noiseVariance);

//! A robust estimate (or none: @p found false) and its inlier masks (Nx1 CV_8U). Returns the inlier count.
int writeRobustEstimate(bool found, const core::RobustEstimate& estimate, OutputArray R, OutputArray t,
                        OutputArray pointInliers, OutputArray lineInliers);

//! Structure as Nx3 points and Mx6 line end points (CV_64F), where wanted: @p points holds N points,
//! @p lineEnds two end points per line.
void writeStructure(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& lineEnds,
                    int numPoints, int numLines, OutputArray points3d, OutputArray lines3d);

//! Per-feature, per-view values (@p values[feature * views + view]) as a features x views CV_64F matrix.
void writeFeatureViewMatrix(const std::vector<double>& values, int numFeatures, int numViews, OutputArray out);

} // namespace detail
} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_OPENCV_RESULT_WRITING_HPP
