// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Reader of the Oxford VGG multi-view sequences (test/data/vgg), for the module's tests, the samples
// and the evaluation. Part of the tripose support library, which is built beside the module but not
// installed: a data-set parser is not part of the module's API.

#ifndef TRIPOSE_SUPPORT_VGG_DATASET_HPP
#define TRIPOSE_SUPPORT_VGG_DATASET_HPP

#include <vector>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

/** @brief Three views of a sequence in the Oxford VGG multi-view format (per view: .corners,
.lines, .P; per sequence: nview-corners, nview-lines, p3d, l3d), restricted to the features seen in
all three views, with the ground truth expressed relative to the first of them (x ~ K(RX + t)).
All matrices are CV_64F unless stated.
*/
struct VggTriplet
{
    Mat points1, points2, points3;   //!< Nx2 corners (px) seen in all three views.
    Mat lines1, lines2, lines3;      //!< Mx4 segments (x0 y0 x1 y1, px) seen in all three views.
    Mat pointIds, lineIds;           //!< Nx1 / Mx1 CV_32S: row of each feature in p3d / l3d.
    Mat points3d;                    //!< Nx3 points of p3d in the frame of the first view.
    Mat lines3d;                     //!< Mx6 segments of l3d in the frame of the first view.
    std::vector<Mat> cameraMatrices; //!< The three 3x3 intrinsic matrices (from the P matrices).
    Mat R12, t12;                    //!< Pose of the second view (3x3, 3x1).
    Mat R, t;                        //!< Pose of the third view (3x3, 3x1).
};

/** @brief Every view of a sequence in the Oxford VGG multi-view format, with each feature's
visibility: the whole track of each 3D point and line of p3d / l3d. Ground truth relative to the
first view (x ~ K_k (R_k X + t_k), X in the first view's frame). All matrices CV_64F.
*/
struct VggSequence
{
    std::vector<String> stems;        //!< Per view, the file stem (<folder>/<name> without .P).
    std::vector<Mat> cameraMatrices;  //!< Per view, 3x3 K.
    std::vector<Mat> Rs, ts;          //!< Per view, pose (3x3, 3x1) relative to view 0.
    std::vector<Mat> points;          //!< Per view, Nx2 corners (px) of the N features of p3d, NaN rows where unseen.
    std::vector<Mat> lines;           //!< Per view, Mx4 segments of the M features of l3d, NaN rows where unseen.
    Mat points3d;                     //!< Nx3 points of p3d in the frame of view 0.
    Mat lines3d;                      //!< Mx6 segments of l3d in the frame of view 0.
};

/** @brief Number of views of a VGG multi-view sequence stored in a folder. */
int vggSequenceViewCount(const String& sequenceDir);

/** @brief Loads three views (0-based indices in image order, distinct, in any order) of a VGG
multi-view sequence.

The files are found by name: {stem}.P, {stem}.corners and {stem}.lines per view (stems sorted by
name, e.g. bt.000 ... bt.010 or 001 ... 003) and {prefix}p3d, {prefix}l3d, {prefix}nview-corners,
{prefix}nview-lines, where {prefix} is what precedes the view number ("bt.", "house." or nothing).
Unseen features are '*' (or -1) in the nview files; extra columns of .lines files are ignored.

Each camera matrix is scaled by -1 if needed so that the structure it sees is in front of it, then
decomposed into K[R|t] (RQ decomposition, K with positive diagonal and K(2,2) = 1). A sequence
whose world frame is mirrored (Model House and Corridor: det of the left 3x3 block negative while
the structure lies in front of the cameras) is read in a world frame with the Z axis flipped, so
that every rotation is proper. Features are returned in p3d / l3d order.
@throws cv::Exception naming the file when a file is missing or malformed, or the view index when
it is out of range.
*/
VggTriplet loadVggTriplet(const String& sequenceDir, int view1, int view2, int view3);

/** @brief Loads every view of a VGG multi-view sequence (files and conventions as loadVggTriplet()).
@throws cv::Exception naming the folder when it holds no sequence, or the file when one is missing
or malformed.
*/
VggSequence loadVggSequence(const String& sequenceDir);

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_VGG_DATASET_HPP
