// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_FEATURES_HPP
#define OPENCV_TRIPOSE_FEATURES_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {

//! @addtogroup tripose_pose
//! @{

/** The features of one image, from any detector: points (Nx2) and segments (Mx4: x0 y0 x1 y1) in
pixels, each with a descriptor row: CV_32F rows are compared by L2 distance (SIFT, learned
descriptors), CV_8U rows by Hamming distance (ORB, AKAZE, LBD). Segments oriented by their edge's
polarity (the brighter side on one hand) are matched with that test.
*/
struct CV_EXPORTS ImageFeatures
{
    Mat points;           //!< Nx2 (CV_32F or CV_64F).
    Mat pointDescriptors; //!< N rows, CV_32F or CV_8U.
    Mat segments;         //!< Mx4 (CV_32F or CV_64F).
    Mat lineDescriptors;  //!< M rows, CV_32F or CV_8U.
};

//! How the features of two frames are matched. Every match is mutual best with a ratio test.
struct CV_EXPORTS MatchParams
{
    MatchParams();
    /** A point pair is a candidate when each point lies within this distance (px) of the other's
    epipolar line (default 2); also the inlier distance of the fundamental matrix that frames of
    unknown relative pose are matched under. */
    double epipolarDistance;
    //! A segment pair is a candidate when the second segment covers at least this fraction of the
    //! shorter of itself and the epipolar band of the first (default 0.5).
    double minBandOverlap;
    //! Segments within this angle (deg) of the epipolar lines are not matched under the geometry (default 5).
    double minEpipolarAngleDeg;
    double pointRatio; //!< Point descriptors: best distance below this fraction of the second best (default 0.8).
    double lineRatio;  //!< Line descriptors: the same (default 0.8).
    //! Binary line descriptors further apart than this many bits never match (default 80).
    double maxLineDistance;
    //! Frames of unknown relative pose are matched under their fundamental matrix when at least this
    //! many descriptor matches agree with it, by descriptor alone otherwise (default 30).
    int minFundamentalInliers;
};

//! Features seen in all three views of a triplet, as estimatePoseLinePointRansac() takes them.
struct CV_EXPORTS FeatureTriplets
{
    Mat points[3];        //!< Nx2 CV_64F, row i of each view the same point.
    Mat lines[3];         //!< Mx4 CV_64F segments, row i of each view the same line.
    Mat pointRows[3];     //!< Nx1 CV_32S: the row of each triplet's point in each view's features.
    Mat segmentRows[3];   //!< Mx1 CV_32S: the same for the segments.
    int pointPairs = 0;   //!< Points of views 1-2 matched, before view 3.
    int segmentPairs = 0; //!< Segments of views 1-2 matched, before view 3.
    /** (points of views 1-2 matched by descriptor alone, of them within the epipolar distance of their
    epipolar lines under R12, t12): a small share of many matches says that the calibration is not
    the images' (doc/usage.md gives the samples' rule). */
    Vec2i pairAgreement;
};

/** @brief Point and segment triplets of three images whose first two views have a known relative pose.

Views 1 and 2 are matched under their epipolar geometry (R12, t12: view 2's pose, view 1 at the
origin), then view 3 to those pairs' features in view 2 under the fundamental matrix of their
descriptor matches (by descriptor alone when too few matches agree with one). Every match is mutual
best with a ratio test (MatchParams).
@param view1, view2, view3 The features of the three images (positions undistorted).
@param cameraMatrix One 3x3 matrix for every view, or a vector of three.
@param R12, t12 The pose of view 2 (3x3 or Rodrigues; 3x1).
@param params How the features are matched.
*/
CV_EXPORTS FeatureTriplets matchFeatureTriplets(const ImageFeatures& view1, const ImageFeatures& view2,
                                                const ImageFeatures& view3, InputArrayOfArrays cameraMatrix,
                                                InputArray R12, InputArray t12,
                                                const MatchParams& params = MatchParams());

//! @}

} // namespace tripose
} // namespace cv

#endif // OPENCV_TRIPOSE_FEATURES_HPP
