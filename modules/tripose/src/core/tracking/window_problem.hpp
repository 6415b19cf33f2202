// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_TRACKING_WINDOW_PROBLEM_HPP
#define TRIPOSE_CORE_TRACKING_WINDOW_PROBLEM_HPP

#include <string>
#include <vector>

#include "../pipeline/posed_structure.hpp"
#include "../problem/problem_arguments.hpp"
#include "track_store.hpp"

namespace tripose {

//! The linear method needs four features.
const int kMinFeatures = 4;

const FeatureKind kKinds[2] = { FeatureKind::Point, FeatureKind::Line };

//! A problem over frames (every one a view, each free to miss features) on a set of tracks.
struct WindowProblem
{
    std::vector<int> tracks[2];
    ProblemArguments arguments;
    std::vector<ArgumentMatrix> Rs, ts;

    //! The observations of @p features (point and line tracks) in @p frames; the first @p posedViews
    //! frames' poses as known poses.
    WindowProblem(const TrackStore& store, const std::vector<int>& frames, const std::vector<int> (&features)[2],
                  int posedViews);

    ArgumentMatrix& rows(int kind, size_t view);
    //! Whether feature @p row of kind @p kind is seen in view @p view.
    bool seen(int kind, size_t view, int row) const;
    //! Keeps the features seen by at least two of the first @p views views.
    void keepSeenTwice(size_t views);
    int numFeatures() const { return (int)(tracks[0].size() + tracks[1].size()); }
    //! The first @p views views alone (known poses), for triangulation.
    PosedStructure triangulate(size_t views) const;
};

} // namespace tripose

#endif // TRIPOSE_CORE_TRACKING_WINDOW_PROBLEM_HPP
