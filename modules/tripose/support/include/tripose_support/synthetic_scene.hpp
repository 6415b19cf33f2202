// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Synthetic three-view scenes with their ground truth, for the module's tests and perf tests, the
// samples, the benchmarks and the evaluation. Part of the tripose support library, which is built
// beside the module but not installed: scenes are a testing tool, not part of the module's API.

#ifndef TRIPOSE_SUPPORT_SYNTHETIC_SCENE_HPP
#define TRIPOSE_SUPPORT_SYNTHETIC_SCENE_HPP

#include <vector>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

//! Camera motion regimes of the synthetic protocol (Qadir & Neubert, Sec. IV-A).
enum SceneMotion
{
    MOTION_LARGE = 0, //!< Views 2 and 3 placed like view 1: at the camera distance from the origin, in random directions.
    MOTION_SMALL = 1, //!< Views 2 and 3 within smallMotionRadius of view 1.
};

/** @brief Parameters of generateSyntheticScene(). The defaults are the paper's protocol: a 10 m
cube centred at the origin, 640x480 cameras with f = 800 px looking at the origin from 20 m.
*/
struct SyntheticSceneParams
{
    SyntheticSceneParams();
    int numPoints;            //!< Number of point triplets.
    int numLines;             //!< Number of line-segment triplets.
    int motion;               //!< One of #SceneMotion.
    double noiseSigma;        //!< Standard deviation (px) of Gaussian noise on point coordinates and segment end points.
    double outlierRatio;      //!< Fraction in [0, 1) of points and of lines whose view-3 observation is a random wrong match.
    double cubeSize;          //!< Edge (m) of the cube holding the structure.
    double cameraDistance;    //!< Distance (m) of view 1 (and of views 2, 3 in large motion) from the origin.
    double smallMotionRadius; //!< Radius (m) around view 1 of views 2 and 3 in small motion.
    /** Distance (m) of view 2 from view 1 (the known pair's baseline), in a uniformly random
    direction, view 2 looking at the origin; view 3 is still placed by #motion. 0 (default): view 2
    is placed by #motion like view 3. At most one of baseline12 and baseline12Fraction is non-zero. */
    double baseline12;
    //! The same as a fraction of cameraDistance (the depth of the cube centre in view 1): 0.01 is a
    //! baseline of 1 % of the depth. 0 (default): not used.
    double baseline12Fraction;
    /** true: every point and segment end point lies on one plane through the cube centre (the
    facade case) instead of filling the cube, uniform in the square of side cubeSize on that plane
    centred at the cube centre. Default false. */
    bool planar;
    /** Angle (degrees, [0, 90)) between the plane's normal and the direction from the cube centre
    to view 1: 0 faces view 1, larger values turn the plane away from it about a random axis
    perpendicular to view 1's viewing direction. Default 30. Used when planar is true. */
    double planeTilt;
    Size imageSize;           //!< Image size of every view (px); features are kept inside it in all three views.
    /** Empty: f = 800 px, principal point at the image centre. Else one 3x3 matrix shared by the
    views or three: finite, with last row (0, 0, k) and k != 0 (returned scaled to k = 1). Nothing
    else is required of them, so that scenes can also be made for intrinsics the estimators reject. */
    std::vector<Mat> cameraMatrices;
    int seed;                 //!< Seed of the scene's random generator: same seed, same scene.
};

/** @brief A generated three-view scene with its ground truth. Poses and structure are expressed in
the frame of view 1 (x ~ K(RX + t)). All matrices are CV_64F.
*/
struct SyntheticScene
{
    Mat points1, points2, points3;   //!< Nx2 observed points (px), noisy.
    Mat lines1, lines2, lines3;      //!< Mx4 observed segments (x0 y0 x1 y1, px), noisy.
    std::vector<Mat> cameraMatrices; //!< The three 3x3 intrinsic matrices.
    Mat R12, t12;                    //!< Pose of view 2 (3x3, 3x1).
    Mat R, t;                        //!< Pose of view 3 (3x3, 3x1): the ground truth to estimate.
    Mat points3d;                    //!< Nx3 world points.
    Mat lines3d;                     //!< Mx6 world segment end points (X0 Y0 Z0 X1 Y1 Z1).
    Mat pointInliers, lineInliers;   //!< Nx1 / Mx1 CV_8U: 1 where the view-3 observation is a true match.
};

/** @brief Generates a random three-view scene of points and line segments following the synthetic
protocol of Qadir & Neubert (Sec. IV-A).

Points and segment end points are uniform in the cube centred at the world origin (or, with
SyntheticSceneParams::planar, in a square on a plane through it). View 1 is at cameraDistance from
the origin in a uniformly random direction, looking at the origin with a random roll; views 2 and 3
are placed the same way (#MOTION_LARGE) or uniformly in the ball of radius smallMotionRadius around
view 1, looking at the origin (#MOTION_SMALL). A non-zero baseline12 (or baseline12Fraction) puts
view 2 at that distance from view 1 instead: the narrow known pair of a stereo rig or of the start
of a sequence. Everything is then expressed in the frame of view 1, where the cube centre is at
(0, 0, cameraDistance).

Features are rejection-sampled: before noise, every point and both end points of every segment
project at least 2 px inside the image in all three views, in front of every camera, and every
projected segment is at least 20 px long. Gaussian noise of standard deviation noiseSigma is then
added to every observed coordinate in all three views. Outliers: exactly round(outlierRatio * N)
points and round(outlierRatio * M) segments, chosen at random, have their view-3 observation
replaced by a random one in the image that is at least 20 px from consistent (point distance, or
largest end-point distance to the true image line); their mask entry is 0.

Deterministic for a given seed and thread-safe (no global state). The cameras, points, lines,
outliers, noise and the plane use separate random streams, so that e.g. changing noiseSigma or
numLines keeps the cameras and points of a seed.
@throws cv::Exception naming the parameter when a parameter is out of range, or when no feature can
be placed inside all three images (e.g. a principal point far outside the image).
*/
SyntheticScene generateSyntheticScene(const SyntheticSceneParams& params);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_SYNTHETIC_SCENE_HPP
