// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "tripose_support/pose_error.hpp"

#include <algorithm>
#include <cmath>

#include "opencv_geometry.hpp"

namespace cv {
namespace tripose {
namespace support {

namespace {

//! The 3 values of a vector in any of the shapes callers hold one in (3x1, 1x3, 1x1 3-channel).
Vec3d readVector(InputArray arr, const char* name)
{
    const Mat m = arr.getMat();
    if (m.total() * m.channels() != 3 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error(Error::StsBadArg, format("poseError: %s must have 3 elements, CV_32F or CV_64F", name));
    Mat m64;
    m.convertTo(m64, CV_64F); // a new, continuous matrix even for a column view
    if (!checkRange(m64))
        CV_Error(Error::StsBadArg, format("poseError: %s contains NaN or Inf values", name));
    return Vec3d(m64.ptr<double>());
}

//! A 3x3 rotation matrix, or the matrix of a Rodrigues vector.
Matx33d readRotation(InputArray arr, const char* name)
{
    const Mat m = arr.getMat();
    if (m.total() * m.channels() == 3)
    {
        Matx33d R;
        Rodrigues(readVector(m, name), R);
        return R;
    }
    if (m.rows != 3 || m.cols != 3 || m.channels() != 1 || (m.depth() != CV_32F && m.depth() != CV_64F))
        CV_Error(Error::StsBadArg,
                 format("poseError: %s must be a 3x3 rotation matrix or a 3-element Rodrigues vector, CV_32F or CV_64F", name));
    Mat m64;
    m.convertTo(m64, CV_64F);
    if (!checkRange(m64))
        CV_Error(Error::StsBadArg, format("poseError: %s contains NaN or Inf values", name));
    return Matx33d(m64.ptr<double>());
}

} // namespace

PoseError poseError(InputArray R, InputArray t, InputArray Rref, InputArray tref)
{
    const Matx33d A = readRotation(R, "R"), B = readRotation(Rref, "Rref");
    const Vec3d a = readVector(t, "t"), b = readVector(tref, "tref");
    PoseError e;
    // |A - B|_F = |A B^T - I|_F = 2 sqrt(2) sin(angle / 2) for rotations A, B.
    const double halfChord = norm(A - B, NORM_L2) / (2.0 * std::sqrt(2.0));
    e.rotationDeg = 2.0 * std::asin(std::min(1.0, halfChord)) * 180.0 / CV_PI;
    e.translation = norm(a - b);
    e.relativeTranslation = e.translation / norm(b);
    return e;
}

} // namespace support
} // namespace tripose
} // namespace cv
