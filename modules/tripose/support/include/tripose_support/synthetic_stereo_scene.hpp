// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Synthetic stereo-rig scenes (four views: a calibrated stereo pair at two times) with their ground
// truth, for the tests, perf tests, samples and benchmarks of the stereo functions. Part of the
// tripose support library (built beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_SYNTHETIC_STEREO_SCENE_HPP
#define TRIPOSE_SUPPORT_SYNTHETIC_STEREO_SCENE_HPP

#include <vector>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

//! Which time-B views see a feature (views 1 and 2, time A, see every feature).
enum StereoVisibility
{
    SEEN_IN_VIEW3 = 1,       //!< The left camera at time B only.
    SEEN_IN_VIEW4 = 2,       //!< The right camera at time B only.
    SEEN_IN_BOTH = 3,        //!< Both cameras at time B.
};

/** @brief Parameters of generateSyntheticStereoScene(). The defaults: a rig of 640x480 cameras with
f = 800 px, a baseline of 0.1-0.5 m, structure 5-30 m in front of it, moving 0.3-3 m and turning up
to 20 degrees between the two times.
*/
struct SyntheticStereoParams
{
    SyntheticStereoParams();
    int numPoints;             //!< Number of points.
    int numLines;              //!< Number of line segments.
    /** Range (m) of the rig's baseline along the left camera's x axis, drawn uniformly; the right
    camera is also off that axis by Gaussian amounts of 5 % of it in y and z. */
    double baselineMin, baselineMax;
    double rigTiltDegrees;     //!< The right camera is turned by up to this angle from parallel to the left.
    double depthMin, depthMax; //!< Range (m) of the depth of the structure in view 1, drawn uniformly.
    double motionMin, motionMax;       //!< Range (m) of the distance the rig moves between times A and B.
    double rotationDegrees;    //!< The rig turns by an angle uniform in [0, rotationDegrees] between the times.
    double noiseSigma;         //!< Standard deviation (px) of Gaussian noise on every observed coordinate.
    /** Fraction in [0, 1) of points and of lines whose time-B observations are a wrong match: the
    projections, in the time-B views that see the feature, of another random 3D point or segment
    (a stereo-consistent wrong match), at least 20 px from consistent in each of them. */
    double outlierRatio;
    /** Fraction in [0, 1] of points and of lines seen by only one time-B view (view 3 or view 4,
    with equal probability); the others are seen by both. Ignored for a kind whose visibility is
    given below. */
    double missingRatio;
    /** Empty, or one StereoVisibility per point: which time-B views see each (overrides missingRatio). */
    std::vector<int> pointVisibility;
    std::vector<int> lineVisibility; //!< The same per line.
    Size imageSize;            //!< Image size of every view (px); features are kept inside it in the views that see them.
    double focalLength;        //!< Focal length (px) of the four cameras; the principal point is the image centre.
    int seed;                  //!< Seed of the scene's random generator: same seed, same scene.
};

/** @brief A generated stereo-rig scene with its ground truth, in the frame of view 1 (the left
camera at time A): view 2 = [R12|t12], view 3 = [R|t], view 4 = [R12 R | R12 t + t12]. All
matrices are CV_64F; a feature a time-B view does not see is a row of NaN there (the convention of
estimatePoseLinePointStereo()).
*/
struct SyntheticStereoScene
{
    Mat points1, points2, points3, points4; //!< Nx2 observed points (px), noisy; NaN rows in 3, 4 where not seen.
    Mat lines1, lines2, lines3, lines4;     //!< Mx4 observed segments (x0 y0 x1 y1, px), likewise.
    std::vector<Mat> cameraMatrices;        //!< The four 3x3 intrinsic matrices (equal).
    Mat R12, t12;                           //!< The rig: pose of view 2 (3x3, 3x1).
    Mat R, t;                               //!< Pose of view 3 (3x3, 3x1): the ground truth to estimate.
    Mat points3d;                           //!< Nx3 world points.
    Mat lines3d;                            //!< Mx6 world segment end points (X0 Y0 Z0 X1 Y1 Z1).
    Mat pointVisibility, lineVisibility;    //!< Nx1 / Mx1 CV_8U: the StereoVisibility of each feature.
    Mat pointInliers, lineInliers;          //!< Nx1 / Mx1 CV_8U: 1 where the time-B observations are a true match.
};

/** @brief Generates a random stereo-rig scene of points and line segments.

The rig: the right camera's centre at x uniform in [baselineMin, baselineMax] in the left camera's
frame, y and z Gaussian with a standard deviation of 5 % of x; turned by up to rigTiltDegrees. The motion: view 3's centre
at a distance uniform in [motionMin, motionMax] from view 1's in a uniformly random direction, turned
by up to rotationDegrees about a random axis. Points: a pixel uniform in view 1 at a depth uniform
in [depthMin, depthMax], kept when it projects at least 2 px inside the image and at least 1 m in
front in all four views; segments: two such points at least 0.5 m apart that project at least 20 px
long in all four views. Gaussian noise of standard deviation noiseSigma is added to every
observation, then the rows of the views that do not see a feature are set to NaN.

Deterministic for a given seed and thread-safe. The rig and motion, points, lines, visibility,
outliers and noise use separate random streams, so that e.g. changing noiseSigma, missingRatio or
numLines keeps the geometry and points of a seed.
@throws cv::Exception naming the parameter when a parameter is out of range, or when no feature can
be placed inside all four images.
*/
SyntheticStereoScene generateSyntheticStereoScene(const SyntheticStereoParams& params);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_SYNTHETIC_STEREO_SCENE_HPP
