// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef TRIPOSE_CORE_ESTIMATOR_POSE_SOLVER_HPP
#define TRIPOSE_CORE_ESTIMATOR_POSE_SOLVER_HPP

#include <vector>

#include "../geometry/camera.hpp"
#include "feature_subset.hpp"

namespace tripose {

/** Samples of several kinds, for a solver that solves minimal sets of points and lines mixed (as
LIMAP's hybrid RANSAC does): a kind is so many points and so many lines, each drawn from one pool of
features that the solver can use together in a minimal sample. A problem with one estimated camera
has one pool; a stereo rig at time B has one per camera (the features each of its cameras sees),
and a sample is drawn from one of them.
*/
struct MixedSampling
{
    struct Pool
    {
        std::vector<int> points, lines; //!< Point and line indices a sample of this pool may draw.
    };
    struct Kind
    {
        int points;
        int lines;
        //! Time of a sample of this kind (its solve and the scoring of its poses), relative to the others.
        double cost;
        int pool; //!< Index into pools.
    };
    std::vector<Kind> kinds;
    std::vector<Pool> pools;
};

/** The seam between a pose problem and the robust estimator (as calib3d's USAC separates them): the
estimator loop draws samples, asks the solver for models, judges them with the PoseScorer and hands
the best to the refiner; a new problem (another arrangement of views) supplies these two.
*/
class PoseSolver
{
public:
    virtual ~PoseSolver() {}
    //! Features in a minimal sample.
    virtual int sampleSize() const = 0;
    //! Fewest features estimateNonMinimal() accepts (it is over-determined from there).
    virtual int nonMinimalSize() const = 0;
    /** Samples are drawn from the first samplePool() of the @p numFeatures features in the single
    index range (points first, see FeatureSubset): a solver for points alone returns the number of
    points. The stopping rule counts the inliers among these features.
    */
    virtual int samplePool(int numFeatures) const { return numFeatures; }
    /** Non-null when the minimal samples are of several kinds (MixedSampling): each sample is then
    one kind's points and lines from its pools, and sampleSize() and samplePool() do not apply.
    */
    virtual const MixedSampling* mixedSampling() const { return nullptr; }
    /** Appends the candidate poses of a minimal sample to @p models; returns how many. @p exhaustive:
    every distinct sample is drawn once (few features), so nothing else will repair a poor
    hypothesis and a solver may spend more per sample.
    */
    virtual int estimateMinimal(const FeatureSubset& sample, bool exhaustive, std::vector<CameraPose>& models) const = 0;
    //! Appends candidate poses from a larger set of features (local optimisation, fallback).
    virtual int estimateNonMinimal(const FeatureSubset& features, std::vector<CameraPose>& models) const = 0;
};

class PoseRefiner
{
public:
    virtual ~PoseRefiner() {}
    /** Refines @p pose on @p inliers; false (pose unchanged) when it could not. @p maxIterations,
    when positive, caps the iterations of a refiner that descends from the pose it is given
    (!searchesOtherStarts()); @p stoppedAtCap, when given, receives whether it stopped at its
    iteration limit (that cap or its options'), not converged: a call on the same features from the
    pose it returned continues where it stopped. */
    virtual bool refine(const FeatureSubset& inliers, CameraPose& pose, int maxIterations = 0,
                        bool* stoppedAtCap = nullptr) const = 0;
    /** True when the problem's cost has several basins (see scoring/known_structure.hpp), so that
    the estimator should also settle its final pose from all the features, not only from the
    hypothesis' inliers. */
    virtual bool searchesSeveralBasins() const { return false; }
    /** True when refine() also searches other starts than the given pose (several basins), so that
    two calls on the same features from different poses may end in different minima. */
    virtual bool searchesOtherStarts() const { return false; }
    /** True when refine() searches the basin of sets of any size (a narrow known pair), so that the
    estimator's samples need only find the inliers, not the basin. */
    virtual bool searchesBasinOfLargeSets() const { return false; }
};

} // namespace tripose

#endif // TRIPOSE_CORE_ESTIMATOR_POSE_SOLVER_HPP
