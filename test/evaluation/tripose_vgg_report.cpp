// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_vgg_report: for every run of three consecutive views of one or more sequences in the
// Oxford VGG multi-view format, estimates the pose of the third view from all point and line
// triplets with the linear solver and with the robust estimator (RANSAC + refinement), and prints
// a Markdown table of rotation and translation errors against the sequences' own cameras.
//
//   tripose_vgg_report <sequence folder> [<sequence folder> ...] [--threshold px]

#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/tripose.hpp>

#include "tripose_support/pose_error.hpp"
#include "tripose_support/vgg_dataset.hpp"

namespace {

std::string baseName(const std::string& path)
{
    std::string p = path;
    while (!p.empty() && p.back() == '/')
        p.pop_back();
    const size_t slash = p.find_last_of('/');
    return slash == std::string::npos ? p : p.substr(slash + 1);
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> folders;
    cv::tripose::RansacParams params;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--threshold" && i + 1 < argc)
            params.threshold = std::atof(argv[++i]);
        else
            folders.push_back(arg);
    }
    if (folders.empty())
    {
        std::fprintf(stderr, "usage: tripose_vgg_report <VGG sequence folder>... [--threshold px]\n");
        return 1;
    }
    std::printf("| sequence | views | points | lines | linear rot (deg) | linear t (%%) | robust rot (deg) | robust t (%%) | inliers |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (const std::string& folder : folders)
    {
        int views = 0;
        try
        {
            views = cv::tripose::support::vggSequenceViewCount(folder);
        }
        catch (const cv::Exception& e)
        {
            std::fprintf(stderr, "%s\n", e.err.c_str());
            return 1;
        }
        for (int v = 0; v + 2 < views; ++v)
        {
            const cv::tripose::support::VggTriplet s = cv::tripose::support::loadVggTriplet(folder, v, v + 1, v + 2);
            const int features = s.points1.rows + s.lines1.rows;
            std::string linear = "- | -", robust = "- | - | -";
            if (features >= 4)
            {
                cv::Mat R, t;
                if (cv::tripose::estimatePoseLinePoint(s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3,
                                                       s.cameraMatrices, cv::noArray(), s.R12, s.t12, R, t) > 0)
                {
                    const cv::tripose::support::PoseError e = cv::tripose::support::poseError(R, t, s.R, s.t);
                    linear = cv::format("%.3f | %.2f", e.rotationDeg, 100 * e.relativeTranslation);
                }
                cv::Mat pm, lm;
                const int inliers = cv::tripose::estimatePoseLinePointRansac(
                    s.points1, s.points2, s.points3, s.lines1, s.lines2, s.lines3, s.cameraMatrices, cv::noArray(),
                    s.R12, s.t12, R, t, params, pm, lm);
                if (inliers > 0)
                {
                    const cv::tripose::support::PoseError e = cv::tripose::support::poseError(R, t, s.R, s.t);
                    robust = cv::format("%.3f | %.2f | %d/%d", e.rotationDeg, 100 * e.relativeTranslation, inliers, features);
                }
            }
            std::printf("| %s | %d-%d-%d | %d | %d | %s | %s |\n", baseName(folder).c_str(), v, v + 1, v + 2,
                        s.points1.rows, s.lines1.rows, linear.c_str(), robust.c_str());
        }
    }
    return 0;
}
