// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include <Eigen/Dense>
#include "opencv_compat.hpp"

#include "input/problem_input.hpp"
#include "refine/ml_refinement.hpp"

namespace cv {
namespace tripose {

RefineParams::RefineParams() : maxIterations(30), loss(LOSS_SQUARED), lossScale(1.0), tolerance(1e-10)
{
}

namespace {

//! How the caller gave the rotation, so that it is written back in the same form.
struct RotationForm
{
    bool rodrigues = false;
    int rows = 3, cols = 3;
};

Eigen::Matrix3d readInitialRotation(InputArray arr, RotationForm& form)
{
    const Mat m = arr.getMat();
    form.rodrigues = m.total() * m.channels() == 3;
    form.rows = m.rows;
    form.cols = m.cols;
    // Validated like R12; returned as an exact rotation, which the multiplicative update needs.
    return detail::readRotation(arr, "R");
}

void writeRotation(const Eigen::Matrix3d& E, const RotationForm& form, OutputArray out)
{
    Mat R(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            R.at<double>(r, c) = E(r, c);
    if (!form.rodrigues)
    {
        R.copyTo(out);
        return;
    }
    Mat rvec;
    Rodrigues(R, rvec);
    rvec.reshape(1, form.rows).copyTo(out);
}

} // namespace

double refinePoseLinePoint(InputArray points1, InputArray points2, InputArray points3,
                           InputArray lines1, InputArray lines2, InputArray lines3,
                           InputArrayOfArrays cameraMatrix, InputArrayOfArrays distCoeffs,
                           InputArray R12, InputArray t12, InputOutputArray R, InputOutputArray t,
                           const RefineParams& params, OutputArray points3d, OutputArray lines3d)
{
    CV_INSTRUMENT_REGION();

    const detail::ViewSet data = detail::readThreeViewInput(points1, points2, points3, lines1, lines2, lines3,
                                                            cameraMatrix, distCoeffs, R12, t12, 3);
    RotationForm form;
    detail::CameraPose pose;
    pose.R = readInitialRotation(R, form);
    pose.t = detail::readTranslation(t, "t", false);
    detail::checkRefineParams(params);

    detail::RefinedStructure structure;
    const detail::RefinementSummary summary = detail::refinePoseAndStructure(data, pose, params, nullptr, nullptr,
                                                                             &structure);

    writeRotation(pose.R, form, R);
    Mat(Matx31d(pose.t.x(), pose.t.y(), pose.t.z())).copyTo(t);
    if (points3d.needed())
    {
        points3d.create(data.numPoints, 3, CV_64F);
        Mat out = points3d.getMat();
        for (int i = 0; i < data.numPoints; ++i)
            for (int c = 0; c < 3; ++c)
                out.at<double>(i, c) = structure.points[i](c);
    }
    if (lines3d.needed())
    {
        lines3d.create(data.numLines, 6, CV_64F);
        Mat out = lines3d.getMat();
        for (int i = 0; i < data.numLines; ++i)
            for (int c = 0; c < 3; ++c)
            {
                out.at<double>(i, c) = structure.lineEnds[2 * i](c);
                out.at<double>(i, 3 + c) = structure.lineEnds[2 * i + 1](c);
            }
    }
    return summary.finalRms;
}

} // namespace tripose
} // namespace cv
