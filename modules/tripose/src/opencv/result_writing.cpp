// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "../precomp.hpp"

#include "covariance_writing.hpp"
#include "result_writing.hpp"

namespace cv {
namespace tripose {
namespace detail {

namespace {

Mat toMat(const Eigen::Matrix3d& R)
{
    Mat m(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m.at<double>(r, c) = R(r, c);
    return m;
}

Mat toMat(const Eigen::Vector3d& t)
{
    return (Mat_<double>(3, 1) << t.x(), t.y(), t.z());
}

void writeMask(const std::vector<unsigned char>& mask, OutputArray out)
{
    if (out.needed())
        Mat((int)mask.size(), 1, CV_8U, (void*)mask.data()).copyTo(out);
}

void checkVectorOutput(OutputArrayOfArrays out, const char* name)
{
    if (out.needed() && out.kind() != _InputArray::STD_VECTOR_MAT)
        CV_Error_(Error::StsBadArg, ("%s must be a std::vector<Mat>", name));
}

void checkSingleOutput(OutputArray out, const char* name)
{
    const auto kind = out.kind();
    if (out.needed() && (kind == _InputArray::STD_VECTOR_MAT || kind == _InputArray::STD_VECTOR_UMAT ||
                         kind == _InputArray::STD_VECTOR_VECTOR || kind == _InputArray::STD_ARRAY_MAT))
        CV_Error_(Error::StsBadArg, ("%s must be a single array, not a vector of arrays", name));
}

} // namespace

void checkCandidateOutputs(OutputArrayOfArrays candidateRs, OutputArrayOfArrays candidateTs, OutputArray errors,
                           OutputArray covariance, OutputArray noiseVariance)
{
    checkVectorOutput(candidateRs, "candidateRs");
    checkVectorOutput(candidateTs, "candidateTs");
    checkSingleOutput(errors, "reprojectionErrors");
    checkSingleOutput(covariance, "covariance");
    checkSingleOutput(noiseVariance, "noiseVariance");
}

void writePose(const core::CameraPose* pose, OutputArray R, OutputArray t)
{
    if (!pose)
    {
        R.release();
        t.release();
        return;
    }
    R.create(3, 3, CV_64F);
    Mat Rm = R.getMat();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            Rm.at<double>(r, c) = pose->R(r, c);
    t.create(3, 1, CV_64F);
    Mat tm = t.getMat();
    for (int r = 0; r < 3; ++r)
        tm.at<double>(r) = pose->t(r);
}

void writePoseVectors(const std::vector<core::CameraPose>& poses, OutputArrayOfArrays Rs, OutputArrayOfArrays ts,
                      const char* RsName, const char* tsName)
{
    const int n = (int)poses.size();
    if (Rs.needed())
    {
        if (Rs.kind() != _InputArray::STD_VECTOR_MAT)
            CV_Error_(Error::StsBadArg, ("%s must be a std::vector<Mat>", RsName));
        Rs.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            Rs.getMatRef(i) = toMat(poses[i].R);
    }
    if (ts.needed())
    {
        if (ts.kind() != _InputArray::STD_VECTOR_MAT)
            CV_Error_(Error::StsBadArg, ("%s must be a std::vector<Mat>", tsName));
        ts.create(n, 1, CV_64F, -1, true);
        for (int i = 0; i < n; ++i)
            ts.getMatRef(i) = toMat(poses[i].t);
    }
}

void writeRankedPoses(const std::vector<core::ScoredPose>& poses, OutputArrayOfArrays Rs, OutputArrayOfArrays ts,
                      OutputArray errors, const char* RsName, const char* tsName)
{
    const int n = (int)poses.size();
    std::vector<core::CameraPose> plain(n);
    for (int i = 0; i < n; ++i)
        plain[i] = poses[i].pose;
    writePoseVectors(plain, Rs, ts, RsName, tsName);
    if (errors.needed())
    {
        Mat values(n, 1, CV_64F);
        for (int i = 0; i < n; ++i)
            values.at<double>(i) = poses[i].rms;
        values.copyTo(errors);
    }
}

int writeCandidates(const std::vector<core::ScoredPose>& candidates, OutputArray R, OutputArray t,
                    OutputArrayOfArrays Rs, OutputArrayOfArrays ts, OutputArray errors, const char* RsName,
                    const char* tsName)
{
    writePose(candidates.empty() ? nullptr : &candidates[0].pose, R, t);
    writeRankedPoses(candidates, Rs, ts, errors, RsName, tsName);
    return (int)candidates.size();
}

int writeCandidateEstimate(const core::ViewSet& views, const std::vector<core::ScoredPose>& candidates, bool refined,
                           OutputArray R, OutputArray t, OutputArrayOfArrays candidateRs,
                           OutputArrayOfArrays candidateTs, OutputArray errors, OutputArray covariance,
                           OutputArray noiseVariance)
{
    writeEstimateCovariance(views, refined && !candidates.empty() ? &candidates.front().pose : nullptr,
                            core::RefineOptions(), nullptr, nullptr, covariance, noiseVariance);
    return writeCandidates(candidates, R, t, candidateRs, candidateTs, errors, "candidateRs", "candidateTs");
}

int writeRobustEstimate(bool found, const core::RobustEstimate& estimate, OutputArray R, OutputArray t,
                        OutputArray pointInliers, OutputArray lineInliers)
{
    writePose(found ? &estimate.pose : nullptr, R, t);
    writeMask(estimate.pointInliers, pointInliers);
    writeMask(estimate.lineInliers, lineInliers);
    return found ? estimate.numInliers : 0;
}

void writeStructure(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& lineEnds,
                    int numPoints, int numLines, OutputArray points3d, OutputArray lines3d)
{
    if (points3d.needed())
    {
        points3d.create(numPoints, 3, CV_64F);
        Mat out = points3d.getMat();
        for (int i = 0; i < numPoints; ++i)
            for (int c = 0; c < 3; ++c)
                out.at<double>(i, c) = points[i](c);
    }
    if (lines3d.needed())
    {
        lines3d.create(numLines, 6, CV_64F);
        Mat out = lines3d.getMat();
        for (int i = 0; i < numLines; ++i)
            for (int c = 0; c < 3; ++c)
            {
                out.at<double>(i, c) = lineEnds[2 * i](c);
                out.at<double>(i, 3 + c) = lineEnds[2 * i + 1](c);
            }
    }
}

void writeFeatureViewMatrix(const std::vector<double>& values, int numFeatures, int numViews, OutputArray out)
{
    if (!out.needed())
        return;
    CV_Assert(values.size() == (size_t)numFeatures * numViews);
    out.create(numFeatures, numViews, CV_64F);
    Mat m = out.getMat();
    for (int i = 0; i < numFeatures; ++i)
        for (int v = 0; v < numViews; ++v)
            m.at<double>(i, v) = values[(size_t)i * numViews + v];
}

} // namespace detail
} // namespace tripose
} // namespace cv
