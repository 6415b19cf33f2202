// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_SCORING_POSE_SCORER_HPP
#define OPENCV_TRIPOSE_SCORING_POSE_SCORER_HPP

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "../geometry/view_set.hpp"
#include "../estimator/feature_subset.hpp"
#include "sequential_test.hpp"

namespace tripose {

//! How well a pose explains the observations of the estimated views (see PoseScorer::score()).
struct PoseScore
{
    //! MSAC cost: over the observations in the estimated views, the sum of min(r^2, threshold^2);
    //! an observation whose feature has no structure, or lies behind the camera (a point, or the
    //! observed segment of a line: geometry/segment_cheirality.hpp), costs threshold^2.
    //! +inf when the score was abandoned at its bound.
    double cost = 0;
    int inliers = 0;        //!< Observations with r^2 < threshold^2.
    double sumSquares = 0;  //!< Sum of the squared pixel residuals of the observations that could be measured.
    int residuals = 0;      //!< Their number: one per point distance, one per line end-point distance.
    int behind = 0;         //!< Point features, and line end points (two per segment seen behind), behind an estimated view.
    int considered = 0;     //!< Those that could be checked: one per point, two per line.
    int pointInliers = 0;   //!< The inlier observations that are of points (inliers - pointInliers: of lines).
    //! The pose failed the sequential test (SequentialTest) before it was scored: judged bad, cost +inf.
    bool rejected = false;
    //! Per kind (SequentialTest::Kind), the observations the sequential test checked and those of
    //! them within the threshold.
    int tested[2] = { 0, 0 };
    int testedConsistent[2] = { 0, 0 };

    //! RMS reprojection error (px) over the measured residuals; +inf when there are none.
    double rms() const;
};

/** The one scorer of candidate poses, for the linear solver's selection, the robust estimator's
hypotheses and its final inlier test.

The structure is triangulated once, from the views whose pose is known (geometry/triangulation:
points by depth-weighted least squares, lines as the lift of the first known view's end points
onto the other known views' planes). A pose is then judged by the residuals (geometry/residuals)
of the estimated views that see each feature. The squared residual r^2 of an observation is, for a
point, its squared pixel distance, and for a line the mean of the squared distances of its two
observed end points to the projected line.

With KnownDepth::Slides, the known structure is not held fixed: each observation of an estimated
view is scored with its feature moved along the rays of the first known view that sees it (a point
by one depth, a line by the depths of its two end points) to where that observation and the known
views' agree best, to first order: the residual minimised over those depths, the known views'
residuals included. A short known baseline (the rig at time A of a stereo rig) places structure
well across its rays and poorly along them, and an estimated camera that moved along the baseline's
normal sees that depth error as pixels: scored against fixed structure a good pose loses inliers.

refitResiduals() judges a pose instead by re-triangulating every feature from all views, the
estimated ones at that pose: it does not carry the triangulation error of the known views into the
estimated ones, at the price of a triangulation per feature and pose.
*/
class PoseScorer
{
public:
    enum class KnownDepth
    {
        Fixed,  //!< The structure of the known views as triangulated.
        Slides, //!< Its depth along the first known view's rays refit per observation (see above).
    };

    explicit PoseScorer(const ViewSet& set, KnownDepth depth = KnownDepth::Fixed);

    //! True when scores let the known structure's depth slide (KnownDepth::Slides).
    bool slidesKnownDepth() const { return slides_; }

    /** Score of @p pose of the estimated camera with inlier threshold @p threshold (px; +inf: plain
    least squares, nothing truncated). Scoring stops, with cost +inf, as soon as the cost exceeds
    @p bound: most hypotheses of a robust estimator are bad. @p inliers, when given, receives the
    features with an inlier observation (complete only when the score was not abandoned).

    With an active @p test, on sets of kMinTestedObservations or more, the observations are first
    checked in a fixed random order (up to kMaxTested of them) by the sequential probability ratio
    test: a pose it rejects gets cost +inf
    and PoseScore::rejected, with what the test saw in PoseScore::tested and testedConsistent.
    A pose that passes is scored as without the test (the same cost, inliers and early stop).
    */
    PoseScore score(const CameraPose& pose, double threshold = std::numeric_limits<double>::infinity(),
                    double bound = std::numeric_limits<double>::infinity(), FeatureSubset* inliers = nullptr,
                    const SequentialTest* test = nullptr) const;

    //! Observations of the estimated views that scores measure, of points or of lines
    //! (SequentialTest::Kind): the denominators of the rates of SequentialTest::setGoodRates().
    int observations(int kind) const { return observations_[kind]; }

    /** The sequential test checks at most this many observations: a wrong pose is rejected after a
    few, and a pose that passes them all is scored in full, the checked ones again. */
    static constexpr int kMaxTested = 100;
    /** Sets with fewer observations are not tested: there the cost bound stops a wrong pose about as
    early as the test would, and a pose that passes would be scored twice (doc/studies/speed.md). */
    static constexpr int kMinTestedObservations = 100;

    /** Per feature: the RMS reprojection error (px) over every view that sees it and every coordinate
    (a point: 2 per view; a line: its 2 end-point distances per view), the feature triangulated from
    all of them with the estimated views at @p pose; +inf where it cannot be triangulated or lies
    behind a view (a line: the part of it a view saw, geometry/segment_cheirality.hpp).
    */
    void refitResiduals(const CameraPose& pose, std::vector<double>& pointResiduals,
                        std::vector<double>& lineResiduals) const;

    const ViewSet& views() const { return set_; }

    /** The structure triangulated from the known views, which every score uses: point @p i and the
    two end points of line @p i (on the first known view's rays), valid when the known views pin the
    feature down in front of them. Minimal solvers reuse it rather than triangulate again.
    */
    const Eigen::Vector3d& knownPoint(int i) const { return points_[i]; }
    bool hasKnownPoint(int i) const { return pointValid_[i] != 0; }
    const Eigen::Vector3d& knownLineEnd(int i, int end) const { return lineEnds_[2 * i + end]; }
    bool hasKnownLine(int i) const { return lineValid_[i] != 0; }

private:
    /** A feature of the known structure free to slide along the rays of the first known view that
    sees it: a point by its inverse depth, a line by those of its two end points (inverse depth
    keeps the projections into the other views close to linear, and covers every depth in front of
    that view). The known views' residuals grow, to first order about the triangulated position,
    by s^T H s + 2 g^T s for a change s of the inverse depths. */
    template <int N>
    struct KnownSlide
    {
        Eigen::Vector3d origin;                    //!< Centre of the first known view.
        Eigen::Matrix<double, 3, N> rays;          //!< Unit directions from it (world frame).
        Eigen::Matrix<double, N, 1> inverseDepth;  //!< Of the triangulated position along each ray.
        Eigen::Matrix<double, N, N> H;
        Eigen::Matrix<double, N, 1> g;
    };
    struct PointTerm
    {
        int feature;
        Eigen::Vector3d X;
        Eigen::Vector2d observed;
    };
    struct LineTerm
    {
        int feature;
        Eigen::Vector3d A, B;
        Eigen::Vector2d end0, end1;                     //!< Pixels.
        Eigen::Vector2d calibratedEnd0, calibratedEnd1; //!< For the segment's cheirality.
    };
    //! What one estimated view measures: terms of the features with structure, the count of those without.
    struct EstimatedView
    {
        int view;
        std::vector<PointTerm> points;
        std::vector<LineTerm> lines;
        //! With KnownDepth::Slides, the slide of each term's feature (kept apart so that fixed
        //! structure scores over the terms alone).
        std::vector<KnownSlide<1>> pointSlides;
        std::vector<KnownSlide<2>> lineSlides;
        int unmeasured = 0;
    };

    //! One observation in the order of the sequential test: of estimated view estimated_[view], its
    //! point or line term (kind) number term.
    struct TestedObservation
    {
        int view, kind, term;
    };

    void triangulateKnown();
    //! Squared residual of term @p k of @p e in a view at @p p, as score() counts it; false when it
    //! cannot be measured (@p behind: because the segment is behind the camera).
    bool pointTermResidual2(const EstimatedView& e, size_t k, const Intrinsics& camera, const CameraPose& p,
                            double threshold2, double& e2) const;
    bool lineTermResidual2(const EstimatedView& e, size_t k, const Intrinsics& camera, const CameraPose& p,
                           double threshold2, double& e2, bool& behind) const;
    //! The sequential test of @p pose over testOrder_; false when it rejects the pose.
    bool passesSequentialTest(const CameraPose& pose, double threshold2, const SequentialTest& test,
                              PoseScore& s) const;
    void knownPointSlide(const std::vector<CameraPose>& poses, int i, KnownSlide<1>& slide) const;
    void knownLineSlide(const std::vector<CameraPose>& poses, int i, KnownSlide<2>& slide) const;
    /** Squared residual (px^2, both coordinates or both end-point distances) of @p term in a view at
    @p pose with its structure slid (KnownDepth::Slides); false when it cannot be measured, with
    @p behind set when that is because the feature is behind the camera. @p bound2: the squared
    residual that makes an inlier. Well within it without the slide, the residual is left unslid (the
    slide cannot change that verdict); beyond it by the first step's linear model, too (an outlier
    whose further steps would seldom bring it inside). */
    bool slidPointResidual2(const Intrinsics& camera, const CameraPose& pose, const PointTerm& term,
                            const KnownSlide<1>& slide, double bound2, double& r2) const;
    bool slidLineResidual2(const Intrinsics& camera, const CameraPose& pose, const LineTerm& term,
                           const KnownSlide<2>& slide, double bound2, double& r2, bool& behind) const;

    const ViewSet& set_;
    bool slides_;
    double minDepth_;
    std::vector<Eigen::Vector3d> points_, lineEnds_;
    std::vector<unsigned char> pointValid_, lineValid_;
    std::vector<EstimatedView> estimated_;
    std::vector<TestedObservation> testOrder_;
    int observations_[2] = { 0, 0 };
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_SCORING_POSE_SCORER_HPP
