// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "../core/pipeline/pose_pipelines.hpp"
#include "argument_reading.hpp"
#include "covariance_writing.hpp"
#include "options_conversion.hpp"
#include "pose_refinement.hpp"
#include "result_writing.hpp"

namespace cv {
namespace tripose {
namespace detail {

double refineGivenPose(const core::ViewSet& views, InputOutputArray R, InputOutputArray t, const RefineParams& params,
                       OutputArray points3d, OutputArray lines3d, OutputArray covariance, OutputArray noiseVariance)
{
    core::CameraPose pose;
    // An exact rotation, which the multiplicative update needs.
    pose.R = readRotation(R, "R");
    pose.t = readTranslation(t, "t", false);
    const core::RefineOptions options = toCoreOptions(params);
    core::RefinedStructure structure;
    const bool wantCovariance = covarianceWanted(covariance, noiseVariance);
    core::PoseCovariance uncertainty;
    const double rms = core::refineInitialPose(views, pose, options, &structure, wantCovariance ? &uncertainty : nullptr);
    writePose(&pose, R, t);
    writeStructure(structure.points, structure.lineEnds, views.numPoints, views.numLines, points3d, lines3d);
    if (wantCovariance)
        writeCovariance(uncertainty, covariance, noiseVariance);
    return rms;
}

} // namespace detail
} // namespace tripose
} // namespace cv
