// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_ESTIMATOR_FEATURE_SUBSET_HPP
#define TRIPOSE_CORE_ESTIMATOR_FEATURE_SUBSET_HPP

#include <algorithm>
#include <vector>

namespace tripose {

/** A subset of the features of a ViewSet, by kind. Robust estimation draws features as one index
range, points first: feature f is point f when f < numPoints, else line f - numPoints.
*/
struct FeatureSubset
{
    std::vector<int> points, lines;

    int size() const { return (int)(points.size() + lines.size()); }
    void clear()
    {
        points.clear();
        lines.clear();
    }
    //! Sorts each kind and drops repeated indices.
    void removeDuplicates()
    {
        for (std::vector<int>* v : { &points, &lines })
        {
            std::sort(v->begin(), v->end());
            v->erase(std::unique(v->begin(), v->end()), v->end());
        }
    }
    //! Every feature of a problem with @p numPoints points and @p numLines lines.
    static FeatureSubset all(int numPoints, int numLines)
    {
        FeatureSubset subset;
        subset.points.resize(numPoints);
        subset.lines.resize(numLines);
        for (int i = 0; i < numPoints; ++i)
            subset.points[i] = i;
        for (int i = 0; i < numLines; ++i)
            subset.lines[i] = i;
        return subset;
    }
    //! Sets this subset to the features of @p indices (the single index range above).
    void assign(const std::vector<int>& indices, int numPoints)
    {
        clear();
        for (int f : indices)
        {
            if (f < numPoints)
                points.push_back(f);
            else
                lines.push_back(f - numPoints);
        }
    }
};

} // namespace tripose

#endif // TRIPOSE_CORE_ESTIMATOR_FEATURE_SUBSET_HPP
