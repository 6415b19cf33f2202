// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_PIPELINE_POSED_STRUCTURE_HPP
#define TRIPOSE_CORE_PIPELINE_POSED_STRUCTURE_HPP

#include <vector>

#include <Eigen/Core>

#include "../geometry/view_set.hpp"

namespace tripose {

/** The structure of features seen by views of known pose, and how far each observation lies from
it: what a tracker needs to find the wrong links of its tracks before it registers a new view
against them, and what a user needs to triangulate from posed views.
*/
struct PosedStructure
{
    std::vector<Eigen::Vector3d> points;   //!< One per point; NaN where it has none (see below).
    std::vector<Eigen::Vector3d> lineEnds; //!< Two per line, on the rays of the end points of the
                                           //!< first view that sees it; NaN where it has none.
    /** Per feature and view (index feature * views + view), the observation's reprojection error in
    pixels: for a point, the distance between its projection and the observation; for a line, the
    larger of the distances of the two observed end points to its image. NaN where the view does not
    see the feature, +inf in every view that sees a feature without structure. */
    std::vector<double> pointErrors, lineErrors;
    int numWithStructure = 0; //!< Points + lines with structure.
};

/** Every feature of @p set (whose views must all be known) triangulated from all the views that
see it (geometry/feature_refit.hpp). A feature has no structure when it cannot be triangulated
(seen by fewer than two views, a point's rays parallel, a line's planes one plane) or lies behind a
view that sees it. A line seen by two views fits both exactly: its errors say something only from
three views on.
*/
PosedStructure triangulateStructure(const ViewSet& set);

} // namespace tripose

#endif // TRIPOSE_CORE_PIPELINE_POSED_STRUCTURE_HPP
