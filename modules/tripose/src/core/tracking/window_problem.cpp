// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "window_problem.hpp"

#include <cmath>

#include <Eigen/Core>

#include "../problem/view_set_builder.hpp"

namespace tripose {

namespace {

int width(FeatureKind kind)
{
    return kind == FeatureKind::Point ? 2 : 4;
}

//! The observations of @p tracks in @p frame, a row each (NaN where unseen).
ArgumentMatrix observations(const TrackStore& store, FeatureKind kind, const std::vector<int>& tracks, int frame,
                            const std::string& name)
{
    ArgumentMatrix m;
    m.name = name;
    if (tracks.empty())
        return m;
    m.rows = (int)tracks.size();
    m.cols = width(kind);
    m.values.resize((size_t)m.rows * m.cols);
    for (int i = 0; i < m.rows; ++i)
        store.observation(kind, tracks[i], frame, &m.values[(size_t)i * m.cols]);
    return m;
}

} // namespace

WindowProblem::WindowProblem(const TrackStore& store, const std::vector<int>& frames,
                             const std::vector<int> (&features)[2], int posedViews)
{
    for (int kind = 0; kind < 2; ++kind)
        tracks[kind] = features[kind];
    for (size_t v = 0; v < frames.size(); ++v)
    {
        const StoredFrame& f = store.frames[frames[v]];
        ViewArguments view;
        view.points = observations(store, FeatureKind::Point, tracks[0], frames[v], "points[" + std::to_string(v) + "]");
        view.lines = observations(store, FeatureKind::Line, tracks[1], frames[v], "lines[" + std::to_string(v) + "]");
        view.mayMiss = true;
        arguments.views.push_back(view);
        Eigen::Matrix<double, 3, 3, Eigen::RowMajor> K = f.K;
        arguments.cameraMatrices.push_back(matrixArgument("K", 3, 3, K.data()));
        if ((int)v < posedViews)
        {
            Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R = f.pose.R;
            Rs.push_back(matrixArgument("Rs[" + std::to_string(v) + "]", 3, 3, R.data()));
            ts.push_back(matrixArgument("ts[" + std::to_string(v) + "]", 3, 1, f.pose.t.data()));
        }
    }
}

ArgumentMatrix& WindowProblem::rows(int kind, size_t view)
{
    return kind == 0 ? arguments.views[view].points : arguments.views[view].lines;
}

bool WindowProblem::seen(int kind, size_t view, int row) const
{
    const ArgumentMatrix& m = kind == 0 ? arguments.views[view].points : arguments.views[view].lines;
    return !m.empty() && !std::isnan(m.values[(size_t)row * m.cols]);
}

void WindowProblem::keepSeenTwice(size_t views)
{
    for (int kind = 0; kind < 2; ++kind)
    {
        std::vector<int> keep;
        for (int i = 0; i < (int)tracks[kind].size(); ++i)
        {
            int count = 0;
            for (size_t v = 0; v < views; ++v)
                count += seen(kind, v, i) ? 1 : 0;
            if (count >= 2)
                keep.push_back(i);
        }
        std::vector<int> kept;
        for (int i : keep)
            kept.push_back(tracks[kind][i]);
        tracks[kind] = kept;
        for (size_t v = 0; v < arguments.views.size(); ++v)
        {
            ArgumentMatrix& m = rows(kind, v);
            ArgumentMatrix out;
            out.name = m.name;
            if (!keep.empty())
            {
                out.rows = (int)keep.size();
                out.cols = m.cols;
                for (int i : keep)
                    out.values.insert(out.values.end(), m.values.begin() + (size_t)i * m.cols,
                                      m.values.begin() + (size_t)(i + 1) * m.cols);
            }
            m = out;
        }
    }
}

PosedStructure WindowProblem::triangulate(size_t views) const
{
    ProblemArguments known = arguments;
    known.views.resize(views);
    known.cameraMatrices.resize(views);
    const std::vector<ArgumentMatrix> R(Rs.begin(), Rs.begin() + views), t(ts.begin(), ts.begin() + views);
    return triangulateStructure(buildPosedViewSet(known, R, t));
}

} // namespace tripose
