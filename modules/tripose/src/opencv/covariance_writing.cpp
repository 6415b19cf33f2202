// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "../core/pipeline/pose_pipelines.hpp"
#include "covariance_writing.hpp"

namespace cv {
namespace tripose {
namespace detail {

bool covarianceWanted(OutputArray covariance, OutputArray noiseVariance)
{
    return covariance.needed() || noiseVariance.needed();
}

void writeCovariance(const core::PoseCovariance& uncertainty, OutputArray covariance, OutputArray noiseVariance)
{
    if (!uncertainty.valid)
    {
        covariance.release();
        noiseVariance.release();
        return;
    }
    if (covariance.needed())
    {
        covariance.create(6, 6, CV_64F);
        Mat out = covariance.getMat();
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c)
                out.at<double>(r, c) = uncertainty.covariance(r, c);
    }
    if (noiseVariance.needed())
        Mat(1, 1, CV_64F, Scalar(uncertainty.noiseVariance)).copyTo(noiseVariance);
}

void writeEstimateCovariance(const core::ViewSet& views, const core::CameraPose* pose,
                             const core::RefineOptions& options, const std::vector<unsigned char>* pointMask,
                             const std::vector<unsigned char>* lineMask, OutputArray covariance,
                             OutputArray noiseVariance)
{
    if (!covarianceWanted(covariance, noiseVariance))
        return;
    const core::PoseCovariance uncertainty =
        pose ? core::covarianceOfEstimate(views, *pose, options, pointMask, lineMask) : core::PoseCovariance();
    writeCovariance(uncertainty, covariance, noiseVariance);
}

} // namespace detail
} // namespace tripose
} // namespace cv
