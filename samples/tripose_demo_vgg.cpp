// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// tripose_demo_vgg: estimates the pose of the third of three views of a sequence in the Oxford VGG
// multi-view format from the points and lines seen in all three, compares it with the sequence's
// own cameras, and draws the sequence's 3D lines into the third image with the estimated pose.
//
//   tripose_demo_vgg --data <sequence folder> [--views 0 1 2] [--image <third image>] [--output out.png]

#include <iostream>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/tripose.hpp>

#include "tripose_support/pose_error.hpp"
#include "tripose_support/vgg_dataset.hpp"

namespace {

const char* kUsage =
    "usage: tripose_demo_vgg --data <VGG sequence folder> [--views i j k] [--image <image of view k>] "
    "[--output overlay.png]\n";

//! Projects world segments (Mx6) with K[R|t]; draws those in front of the camera.
void drawSegments(cv::Mat& image, const cv::Mat& segments, const cv::Mat& K, const cv::Mat& R, const cv::Mat& t,
                  const cv::Scalar& colour, int thickness)
{
    for (int i = 0; i < segments.rows; ++i)
    {
        cv::Point2d ends[2];
        bool visible = true;
        for (int e = 0; e < 2; ++e)
        {
            const cv::Mat X = (cv::Mat_<double>(3, 1) << segments.at<double>(i, 3 * e), segments.at<double>(i, 3 * e + 1),
                               segments.at<double>(i, 3 * e + 2));
            const cv::Mat x = K * (R * X + t);
            const double z = x.at<double>(2);
            visible = visible && z > 0;
            ends[e] = cv::Point2d(x.at<double>(0) / z, x.at<double>(1) / z);
        }
        if (visible)
            cv::line(image, ends[0], ends[1], colour, thickness, cv::LINE_AA);
    }
}

} // namespace

int main(int argc, char** argv)
{
    std::string data, imagePath, output = "tripose_demo.png";
    int views[3] = { 0, 1, 2 };
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--data" && i + 1 < argc)
            data = argv[++i];
        else if (arg == "--image" && i + 1 < argc)
            imagePath = argv[++i];
        else if (arg == "--output" && i + 1 < argc)
            output = argv[++i];
        else if (arg == "--views" && i + 3 < argc)
            for (int k = 0; k < 3; ++k)
                views[k] = std::atoi(argv[++i]);
        else
        {
            std::cerr << "tripose_demo_vgg: unknown or incomplete argument " << arg << "\n" << kUsage;
            return 1;
        }
    }
    if (data.empty())
    {
        std::cerr << "tripose_demo_vgg: --data is required\n" << kUsage;
        return 1;
    }

    cv::tripose::support::VggTriplet triplet;
    try
    {
        triplet = cv::tripose::support::loadVggTriplet(data, views[0], views[1], views[2]);
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "tripose_demo_vgg: " << e.err << "\n";
        return 1;
    }
    std::cout << "Sequence " << data << ", views " << views[0] << ", " << views[1] << ", " << views[2] << ": "
              << triplet.points1.rows << " point and " << triplet.lines1.rows << " line triplets\n";

    cv::Mat R, t;
    const int64 start = cv::getTickCount();
    const int n = cv::tripose::estimatePoseLinePoint(triplet.points1, triplet.points2, triplet.points3,
                                                     triplet.lines1, triplet.lines2, triplet.lines3,
                                                     triplet.cameraMatrices, cv::noArray(), triplet.R12, triplet.t12, R, t);
    const double ms = 1e3 * double(cv::getTickCount() - start) / cv::getTickFrequency();
    if (n == 0)
    {
        std::cerr << "tripose_demo_vgg: no pose found\n";
        return 2;
    }

    const cv::tripose::support::PoseError error = cv::tripose::support::poseError(R, t, triplet.R, triplet.t);
    const double directionError =
        std::acos(std::max(-1.0, std::min(1.0, t.dot(triplet.t) / (cv::norm(t) * cv::norm(triplet.t))))) * 180.0 / CV_PI;
    std::cout << cv::format("Solved in %.3f ms (%d candidate(s))\n", ms, n)
              << "Estimated R =\n" << R << "\nGround truth R =\n" << triplet.R << "\n"
              << "Estimated t = " << t.t() << "\nGround truth t = " << triplet.t.t() << "\n"
              << cv::format("Rotation error: %.4f deg\n", error.rotationDeg)
              << cv::format("Translation error: %.2f %% of |t| (direction %.4f deg)\n", 100 * error.relativeTranslation,
                            directionError);

    if (!imagePath.empty())
    {
        cv::Mat image = cv::imread(imagePath, cv::IMREAD_COLOR);
        if (image.empty())
        {
            std::cerr << "tripose_demo_vgg: cannot read image " << imagePath << "\n";
            return 1;
        }
        const cv::Mat& K3 = triplet.cameraMatrices[2];
        for (int i = 0; i < triplet.lines3.rows; ++i) // observed segments, thin red
            cv::line(image, cv::Point2d(triplet.lines3.at<double>(i, 0), triplet.lines3.at<double>(i, 1)),
                     cv::Point2d(triplet.lines3.at<double>(i, 2), triplet.lines3.at<double>(i, 3)),
                     cv::Scalar(0, 0, 255), 1, cv::LINE_AA);
        drawSegments(image, triplet.lines3d, K3, R, t, cv::Scalar(0, 255, 0), 2); // reprojected, green
        for (int i = 0; i < triplet.points3.rows; ++i)
            cv::circle(image, cv::Point2d(triplet.points3.at<double>(i, 0), triplet.points3.at<double>(i, 1)), 3,
                       cv::Scalar(255, 128, 0), 1, cv::LINE_AA);
        const std::string caption = "green: 3D lines reprojected with the estimated pose; red: observed segments";
        int baseline = 0;
        const cv::Size textSize = cv::getTextSize(caption, cv::FONT_HERSHEY_SIMPLEX, 0.6, 2, &baseline);
        cv::rectangle(image, cv::Rect(0, 0, textSize.width + 20, textSize.height + baseline + 16), cv::Scalar(0, 0, 0),
                      cv::FILLED);
        cv::putText(image, caption, cv::Point(10, textSize.height + 8), cv::FONT_HERSHEY_SIMPLEX, 0.6,
                    cv::Scalar(255, 255, 255), 2, cv::LINE_AA);
        if (!cv::imwrite(output, image))
        {
            std::cerr << "tripose_demo_vgg: cannot write " << output << "\n";
            return 1;
        }
        std::cout << "Overlay written to " << output << "\n";
    }
    return 0;
}
