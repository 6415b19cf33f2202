// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_GEOMETRY_CAMERA_HPP
#define OPENCV_TRIPOSE_GEOMETRY_CAMERA_HPP

#include <Eigen/Core>

namespace tripose {

//! A camera pose: a world point X is at R X + t in the camera frame (x ~ K (R X + t)).
struct CameraPose
{
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d t = Eigen::Vector3d::Zero();

    Eigen::Vector3d centre() const { return -R.transpose() * t; }
    Eigen::Vector3d toCamera(const Eigen::Vector3d& X) const { return R * X + t; }
    bool allFinite() const { return R.allFinite() && t.allFinite(); }
};

//! The pose of a camera rigidly mounted at @p mount in the frame of a camera at @p pose:
//! x_mount = R_m (R X + t) + t_m.
inline CameraPose composePose(const CameraPose& mount, const CameraPose& pose)
{
    CameraPose p;
    p.R = mount.R * pose.R;
    p.t = mount.R * pose.t + mount.t;
    return p;
}

//! The pose that undoes @p pose: world from camera, X = R^T (x - t).
inline CameraPose inversePose(const CameraPose& pose)
{
    CameraPose p;
    p.R = pose.R.transpose();
    p.t = -(p.R * pose.t);
    return p;
}

//! The pose of a camera at world pose @p pose in the frame of a camera at world pose @p frame:
//! composePose(poseRelativeTo(pose, frame), frame) is @p pose.
inline CameraPose poseRelativeTo(const CameraPose& pose, const CameraPose& frame)
{
    CameraPose p;
    p.R = pose.R * frame.R.transpose();
    p.t = pose.t - p.R * frame.t;
    return p;
}

//! [v]x, the matrix of the cross product v x (.).
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d S;
    S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return S;
}

/** A pinhole intrinsic matrix K = [fx s cx; 0 fy cy; 0 0 1] in the forms the residuals need. Pixels
handled here are undistorted: distortion is removed once, when the input is read.
*/
struct Intrinsics
{
    double fx = 1, shear = 0, cx = 0, fy = 1, cy = 0;
    //! K^-T scaled by fx: maps a calibrated line (or a Plücker moment in the camera frame) to its
    //! pixel line. fx keeps the entries near 1 for typical cameras; the scale cancels in distances.
    Eigen::Matrix3d lineK = Eigen::Matrix3d::Identity();

    Intrinsics() {}
    explicit Intrinsics(const Eigen::Matrix3d& K)
        : fx(K(0, 0)), shear(K(0, 1)), cx(K(0, 2)), fy(K(1, 1)), cy(K(1, 2))
    {
        lineK = K.inverse().transpose() * fx;
    }

    Eigen::Matrix3d matrix() const
    {
        Eigen::Matrix3d K;
        K << fx, shear, cx, 0, fy, cy, 0, 0, 1;
        return K;
    }

    //! K^-1 applied to a pixel (closed form: K is upper triangular).
    Eigen::Vector2d calibrate(const Eigen::Vector2d& pixel) const
    {
        const double y = (pixel.y() - cy) / fy;
        return Eigen::Vector2d((pixel.x() - cx - shear * y) / fx, y);
    }

    //! Pixel of a point in the camera frame (z > 0 is the caller's to check).
    Eigen::Vector2d project(const Eigen::Vector3d& Xc) const
    {
        const double x = Xc.x() / Xc.z(), y = Xc.y() / Xc.z();
        return Eigen::Vector2d(fx * x + shear * y + cx, fy * y + cy);
    }
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_GEOMETRY_CAMERA_HPP
