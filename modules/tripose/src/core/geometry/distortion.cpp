// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "distortion.hpp"

#include <cmath>
#include <limits>

namespace tripose {

namespace {

// Enough for the fixed-point iteration to converge to rounding on any calibration that a camera
// produces; the pose solver is exact on exact data and should stay so after undistortion.
constexpr int kMaxIterations = 100;
constexpr double kReprojectionTolerance = 1e-15; // px

//! The sensor tilt's projective map and its inverse (identity for tauX = tauY = 0).
void tiltMatrices(double tauX, double tauY, Eigen::Matrix3d& tilt, Eigen::Matrix3d& inverseTilt)
{
    const double cx = std::cos(tauX), sx = std::sin(tauX), cy = std::cos(tauY), sy = std::sin(tauY);
    Eigen::Matrix3d rotX, rotY;
    rotX << 1, 0, 0, 0, cx, sx, 0, -sx, cx;
    rotY << cy, 0, -sy, 0, 1, 0, sy, 0, cy;
    const Eigen::Matrix3d rotXY = rotY * rotX;
    Eigen::Matrix3d projectZ;
    projectZ << rotXY(2, 2), 0, -rotXY(0, 2), 0, rotXY(2, 2), -rotXY(1, 2), 0, 0, 1;
    tilt = projectZ * rotXY;
    const double inv = 1.0 / rotXY(2, 2);
    Eigen::Matrix3d inverseProjectZ;
    inverseProjectZ << inv, 0, inv * rotXY(0, 2), 0, inv, inv * rotXY(1, 2), 0, 0, 1;
    inverseTilt = rotXY.transpose() * inverseProjectZ;
}

Eigen::Vector2d applyHomography(const Eigen::Matrix3d& H, double x, double y)
{
    const Eigen::Vector3d v = H * Eigen::Vector3d(x, y, 1);
    const double w = v(2) != 0 ? 1.0 / v(2) : 1.0;
    return Eigen::Vector2d(w * v(0), w * v(1));
}

} // namespace

void Distortion::undistortPixels(std::vector<Eigen::Vector2d>& pixels, const Eigen::Matrix3d& K) const
{
    // As cv::undistortPoints(): the input pixels are normalised with fx, fy, cx, cy (the shear is
    // not read), the output goes through the whole K.
    const double fx = K(0, 0), fy = K(1, 1), cx = K(0, 2), cy = K(1, 2);
    Eigen::Matrix3d tilt, inverseTilt;
    tiltMatrices(k[12], k[13], tilt, inverseTilt);
    for (Eigen::Vector2d& pixel : pixels)
    {
        const double u = pixel.x(), v = pixel.y();
        const Eigen::Vector2d distorted = applyHomography(inverseTilt, (u - cx) / fx, (v - cy) / fy);
        const double x0 = distorted.x(), y0 = distorted.y();
        double x = x0, y = y0;
        double error = std::numeric_limits<double>::max();
        for (int iteration = 0; iteration < kMaxIterations && !(error < kReprojectionTolerance); ++iteration)
        {
            double r2 = x * x + y * y;
            const double inverseRadial = (1 + ((k[7] * r2 + k[6]) * r2 + k[5]) * r2) /
                                         (1 + ((k[4] * r2 + k[1]) * r2 + k[0]) * r2);
            if (inverseRadial < 0)
            {
                // The model folds over here: no inverse; the point is left undistorted.
                x = (u - cx) / fx;
                y = (v - cy) / fy;
                break;
            }
            const double dx = 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x) + k[8] * r2 + k[9] * r2 * r2;
            const double dy = k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y + k[10] * r2 + k[11] * r2 * r2;
            x = (x0 - dx) * inverseRadial;
            y = (y0 - dy) * inverseRadial;

            // The reprojection error of the current estimate decides when to stop.
            r2 = x * x + y * y;
            const double r4 = r2 * r2, r6 = r4 * r2;
            const double radial = (1 + k[0] * r2 + k[1] * r4 + k[4] * r6) / (1 + k[5] * r2 + k[6] * r4 + k[7] * r6);
            const double xd0 = x * radial + 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x) + k[8] * r2 + k[9] * r4;
            const double yd0 = y * radial + k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y + k[10] * r2 + k[11] * r4;
            const Eigen::Vector2d reprojected = applyHomography(tilt, xd0, yd0);
            error = std::hypot(reprojected.x() * fx + cx - u, reprojected.y() * fy + cy - v);
        }
        const Eigen::Vector3d out = K * Eigen::Vector3d(x, y, 1);
        pixel = Eigen::Vector2d(out(0) / out(2), out(1) / out(2));
    }
}

} // namespace tripose
