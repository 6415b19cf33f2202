// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_PARAMS_HPP
#define OPENCV_TRIPOSE_PARAMS_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

//! Loss applied to the reprojection error of each observation (a point, or the two end points of a segment, in one view).
enum RobustLoss
{
    LOSS_SQUARED = 0, //!< Plain least squares: the maximum-likelihood estimate under Gaussian noise.
    LOSS_HUBER = 1,   //!< Quadratic up to RefineParams::lossScale pixels, linear beyond.
    LOSS_CAUCHY = 2,  //!< \f$c^2 \log(1 + e^2 / c^2)\f$ with \f$c\f$ = RefineParams::lossScale: gross errors barely count.
};

/** @brief Parameters of the maximum-likelihood refinement: refinePoseLinePoint(),
refinePoseLinePointStereo(), refinePoseMultiView(), adjustPosesMultiView(), and the final stage of
the RANSAC estimators (RansacParams::refineParams).
*/
struct CV_EXPORTS_W_SIMPLE RefineParams
{
    CV_WRAP RefineParams();
    CV_PROP_RW int maxIterations; //!< Maximum number of Levenberg-Marquardt steps, accepted or rejected (> 0, default 30).
    CV_PROP_RW int loss;          //!< One of #RobustLoss (default LOSS_SQUARED).
    CV_PROP_RW double lossScale;  //!< Scale \f$c\f$ of the robust loss in pixels (> 0, default 1); unused by LOSS_SQUARED.
    CV_PROP_RW double tolerance;  //!< Stop when an accepted step lowers the cost by less than this fraction of it (>= 0, default 1e-10).
};

/** @brief Parameters of the RANSAC estimators: estimatePoseLinePointRansac(),
estimatePoseLinePointStereoRansac() and estimatePoseMultiViewRansac().
*/
struct CV_EXPORTS_W_SIMPLE RansacParams
{
    CV_WRAP RansacParams();
    /** Inlier threshold in pixels (default 2). A feature is an inlier of the returned pose when its
    RMS reprojection error over every view that sees it, the feature re-triangulated from all of
    them with that pose, is below it (a point: its two coordinates in each view; a line: the
    distances of its two observed end points to the projected 3D line in each view). While
    sampling, hypotheses are scored on the estimated view(s) alone (view 3; views 3 and 4 of a rig;
    the new view) against structure triangulated from the known views, which carries the
    triangulation error of those views: there the threshold is doubled.
    */
    CV_PROP_RW double threshold;
    CV_PROP_RW double confidence;      //!< Probability, in (0, 1), of drawing at least one all-inlier sample (default 0.999).
    CV_PROP_RW int maxIterations;      //!< Upper bound on the number of samples (default 10000).
    CV_PROP_RW bool localOptimization; //!< Re-estimate from the inliers of every new best model (default true).
    CV_PROP_RW bool refine;            //!< Finish with the maximum-likelihood refinement over the inliers (refinePoseLinePoint() and its siblings), with refineParams (default true).
    CV_PROP_RW RefineParams refineParams; //!< Parameters of the final refinement (default RefineParams()).
    CV_PROP_RW int seed;               //!< Seed of the sampler: the same seed gives the same result (default 0).
    /** Fewest inliers of a returned pose (default 15; >= 0): an estimate with fewer is no pose (the
    functions return 0, R and t empty). Wrong matches can agree with a wrong pose by chance in small
    numbers (doc/conventions.md, "Results and errors", says how many); set it lower only where every
    feature is known to be right, as in small synthetic problems. */
    CV_PROP_RW int minInliers;
};

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_PARAMS_HPP
