// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "frame_arguments.hpp"

#include <chrono>
#include <cmath>
#include <set>

#include "../problem/problem_arguments.hpp"
#include "../problem/view_set_builder.hpp"
#include "../support/error.hpp"

namespace tripose {

double nowSeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void checkCameraMatrix(const Eigen::Matrix3d& K, const char* name)
{
    if (!K.allFinite() || !(K(0, 0) > 0) || !(K(1, 1) > 0) || K(1, 0) != 0 || K(2, 0) != 0 || K(2, 1) != 0 ||
        K(2, 2) != 1)
        fail(ErrorCode::BadArgument, "%s must be a camera matrix [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0", name);
}

CameraPose checkedPose(const CameraPose& pose, const char* Rname, const char* tname)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMajor = pose.R;
    CameraPose out;
    out.R = readRotation(matrixArgument(Rname, 3, 3, rowMajor.data()));
    out.t = readTranslation(matrixArgument(tname, 3, 1, pose.t.data()), false);
    return out;
}

bool readDistortion(const std::vector<double>& coefficients, const char* name, Distortion& out)
{
    const size_t n = coefficients.size();
    if (!(n == 0 || n == 4 || n == 5 || n == 8 || n == 12 || n == 14))
        fail(ErrorCode::BadArgument, "%s must hold 4, 5, 8, 12 or 14 coefficients (OpenCV's model), got %d", name,
             (int)n);
    bool distorted = false;
    for (size_t i = 0; i < n; ++i)
    {
        if (!std::isfinite(coefficients[i]))
            fail(ErrorCode::BadArgument, "%s[%d] is not finite", name, (int)i);
        out.k[i] = coefficients[i];
        distorted = distorted || coefficients[i] != 0;
    }
    return distorted;
}

void checkObservationIds(size_t numPoints, const std::vector<int64_t>& pointIds, size_t numSegments,
                         const std::vector<int64_t>& lineIds)
{
    if (pointIds.size() != numPoints)
        fail(ErrorCode::BadSize, "point_ids must hold one id per point: %d ids for %d points", (int)pointIds.size(),
             (int)numPoints);
    if (lineIds.size() != numSegments)
        fail(ErrorCode::BadSize, "line_ids must hold one id per segment: %d ids for %d segments", (int)lineIds.size(),
             (int)numSegments);
    for (int kind = 0; kind < 2; ++kind)
    {
        const std::vector<int64_t>& ids = kind == 0 ? pointIds : lineIds;
        if (std::set<int64_t>(ids.begin(), ids.end()).size() != ids.size())
            fail(ErrorCode::BadArgument, "%s: an id appears twice in one frame", kind == 0 ? "point_ids" : "line_ids");
    }
}

} // namespace tripose
