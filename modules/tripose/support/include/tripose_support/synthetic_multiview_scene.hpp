// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Synthetic scenes for registration against several known views (the multi-view functions) with
// their ground truth, for the tests and perf tests. Part of the tripose support library (built
// beside the module, not installed).

#ifndef TRIPOSE_SUPPORT_SYNTHETIC_MULTIVIEW_SCENE_HPP
#define TRIPOSE_SUPPORT_SYNTHETIC_MULTIVIEW_SCENE_HPP

#include <vector>

#include "opencv2/core.hpp"

namespace cv {
namespace tripose {
namespace support {

/** @brief V known views and a new one around a 10 m cube (cameras about 20 m away in random
directions, looking at the cube's centre with a random roll), f = 800 px, no noise. Every feature is
seen by the new view and by a random subset of at least @p minSeen known views (each further known
view with probability 1/2); a row of NaN in the views that do not see it. The world frame is the
cube's, not a camera's. Deterministic for a given seed.
*/
struct SyntheticMultiViewScene
{
    std::vector<Mat> points, lines; //!< V + 1 arrays (the known views, then the new one): Nx2, Mx4 CV_64F.
    std::vector<Mat> Rs, ts;        //!< The V known world poses (3x3, 3x1 CV_64F).
    Matx33d K;                      //!< The intrinsics of every view.
    Matx33d R;                      //!< The new view's world rotation: the ground truth to estimate.
    Vec3d t;                        //!< The new view's world translation.

    SyntheticMultiViewScene(int numKnown, int numPoints, int numLines, uint64 seed, int minSeen = 2);

    //! Adds Gaussian noise of standard deviation @p sigma (px) to every observed coordinate (NaN rows stay NaN).
    void addNoise(double sigma, uint64 seed);
};

} // namespace support
} // namespace tripose
} // namespace cv

#endif // TRIPOSE_SUPPORT_SYNTHETIC_MULTIVIEW_SCENE_HPP
