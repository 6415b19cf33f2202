// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_PYTHON_POSE_RESULT_HPP
#define TRIPOSE_PYTHON_POSE_RESULT_HPP

#include <nanobind/nanobind.h>

#include <Eigen/Core>

/** tripose.PoseResult: what every estimator, robust and refining function returns, one field per
quantity, None where the function does not give it. The Python values are made once, when the result is;
the rest is what its repr prints. */
struct PoseResult
{
    enum class Kind
    {
        Robust,   //!< estimate_pose_*_ransac
        Refined,  //!< refine_pose_*
        Adjusted, //!< adjust_poses_multiview (Rs, ts; R and t None)
        Candidates, //!< estimate_pose_* (the ranked candidates; for one release also read as their list)
    };

    nanobind::object R = nanobind::none(), t = nanobind::none(), num_inliers = nanobind::none(),
                     point_inliers = nanobind::none(), line_inliers = nanobind::none(), rms = nanobind::none(),
                     covariance = nanobind::none(), noise_variance = nanobind::none(),
                     candidates = nanobind::none(), candidate_rms = nanobind::none(), ambiguous = nanobind::none(),
                     points3d = nanobind::none(), lines3d = nanobind::none(), Rs = nanobind::none(),
                     ts = nanobind::none();

    Kind kind = Kind::Robust;
    bool hasPose = false;
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    int numPoints = 0, numLines = 0, pointInliers = 0, lineInliers = 0, numCandidates = 0, numPoses = 0;
    double rmsValue = 0;
};

//! The class tripose.PoseResult.
void bindPoseResult(nanobind::module_& m);

#endif // TRIPOSE_PYTHON_POSE_RESULT_HPP
