// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_RIG_SYSTEM_HPP
#define OPENCV_TRIPOSE_LINEAR_RIG_SYSTEM_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/view_set.hpp"
#include "linear_system.hpp"
#include "rig_feature_counts.hpp"

namespace tripose {

/** Views of a stereo rig seen at two times, as a ViewSet: view 1 (index kView1) the left camera at
time A at [I|0], view 2 (kView2) the right camera at time A at the rig pose [R12|t12], both known;
view 3 (kView3) the left camera at time B, estimated, mounted at the identity; view 4 (ViewSet::kRigRightB)
the right camera at time B, estimated, mounted at the rig pose (R12, t12) again. Every feature is
seen in views 1 and 2 and in view 3, view 4 or both.
*/

/** The stereo-rig linear system A v = b in v = [r1; r2; r3; t] (the pose of view 3; r_i the
columns of R). A line gets the two points of its 3D line from views 1-2 (lineNullSpace()); in
view 3 they give the homogeneous line rows, in view 4 the rows of rigLineRows with b != 0 (view 4's
pose is affine in v). A point gives the trilinear rows of views 1, 2, 3 and rigPointRows for
views 1, 2, 4, each view Hartley-normalised over the selected points it sees. Every block of rows
(one feature in one view) is scaled to Frobenius norm sqrt 2 (a line's two unit rows), b with it,
so that neither kind nor any view dominates whatever the normalising scales. From six features
(over-determined) a line's rows instead use its noise-weighted end points (lineEndPoints()), as the
three-view system does.
*/
struct RigSystem
{
    ConstraintMatrix A;
    Eigen::VectorXd b;
    //! The features that contributed rows (a line in an epipolar plane of views 1-2 has no 3D
    //! position and contributes none; neither does a feature seen in neither time-B view).
    RigFeatureCounts counts;
    //! |t12|: t12 is divided by it before the rows are formed, so that the solved t is in units of
    //! the baseline and the columns of A are balanced whatever the user's units.
    double translationScale = 1;
};

/** Builds the rig system of the selected features (null pointers: all of them) of a four-view
ViewSet laid out as above. Returns false when the rig has no baseline.
*/
bool buildRigSystem(const ViewSet& set, const std::vector<int>* pointIndices, const std::vector<int>* lineIndices,
                    RigSystem& system);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_RIG_SYSTEM_HPP
