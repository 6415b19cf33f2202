// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_MULTIVIEW_SYSTEM_HPP
#define OPENCV_TRIPOSE_LINEAR_MULTIVIEW_SYSTEM_HPP

#include <vector>

#include "../geometry/view_set.hpp"
#include "linear_solver.hpp"
#include "linear_system.hpp"

namespace tripose {

//! Which pairs of known views give a feature its rows in the multi-view linear system.
enum class PairSelection
{
    Best, //!< The pair with the widest triangulation angle (points) or plane angle (lines).
    All,  //!< Every pair of known views that sees the feature (from six features on; fewer: Best).
};

/** The paper's linear system for registering one camera against any number of known views.

Layout of @p set: views 0..V-1 known (world poses), one view estimated, mounted at the identity; a
feature enters when the estimated view and at least two known views see it. A feature's rows are
the three-view rows (linear_system.hpp) of a pair (a, b) of known views that see it, written in the
frame of a: view b at R_ab = R_b R_a^T, t_ab = t_b - R_ab t_a, and the unknown camera at
R_a = R R_a^T, t_a = t - R_a t_a, which is linear in the unknown v = [r1; r2; r3; t]: v_a = M_a v
with a constant 12x12 M_a, so the rows A_f M_a v = 0 share one unknown. The unknown is the pose
relative to the first known view (its frame is the reference, so that t stays of the size of the
known baselines), in units of the largest distance of a known centre from the reference centre;
the candidates are returned in the world frame.

Rows are built per pair with buildConstraintMatrix(), so the Hartley normalisation of points and
the balancing of point and line rows are those of the three-view system, per pair.
*/
class MultiViewSystem
{
public:
    MultiViewSystem(const ViewSet& set, PairSelection selection);

    /** Candidate poses of the estimated view (world frame) from the selected features (null: all),
    as linearPoseCandidates(). A minimal sample (fewer than six features) always takes one pair per
    feature: the kernel dimension counts two independent rows per feature.
    */
    int candidates(std::vector<CameraPose>& poses, const std::vector<int>* pointIndices,
                   const std::vector<int>* lineIndices, const CandidateOptions& options) const;

    //! Known views of the pair that gives point @p i its rows (Best), for tests and diagnostics.
    std::pair<int, int> bestPointPair(int i) const;

private:
    //! The three-view problem of one pair (a, b): views {a at [I|0], b at [R_ab|t_ab], estimated},
    //! holding the features that take rows from it, renumbered.
    struct Pair
    {
        int a = 0, b = 0;
        ViewSet views;
        Matrix12d M;           //!< v_a = M v (t in units of the system's scale).
        std::vector<int> pointLocal, lineLocal; //!< Per feature of the full set: its index here, -1 if absent.
    };

    int pairFor(int a, int b);
    void addFeature(int pair, bool point, int feature);

    const ViewSet& set_;
    PairSelection selection_;
    int estimated_ = -1; //!< The estimated view (mounted at the identity).
    CameraPose reference_;
    double scale_ = 0;
    std::vector<Pair> pairs_;
    std::vector<int> bestPointPair_, bestLinePair_;               //!< Per feature: index into pairs_.
    std::vector<std::vector<int>> allPointPairs_, allLinePairs_;  //!< Per feature, All: every pair.
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_MULTIVIEW_SYSTEM_HPP
