// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_LINEAR_RIG_FEATURE_COUNTS_HPP
#define OPENCV_TRIPOSE_LINEAR_RIG_FEATURE_COUNTS_HPP

namespace tripose {

/** The features of a stereo-rig system by kind and by the time-B views that see them (views 3 and
4: the left and right cameras at time B). Every counted feature is seen in views 1 and 2 too.
*/
struct RigFeatureCounts
{
    int pointsBoth = 0, linesBoth = 0;   //!< Seen in views 3 and 4.
    int pointsOnly3 = 0, linesOnly3 = 0; //!< Seen in view 3, not in view 4.
    int pointsOnly4 = 0, linesOnly4 = 0; //!< Seen in view 4, not in view 3.

    int pointsSingle() const { return pointsOnly3 + pointsOnly4; }
    int linesSingle() const { return linesOnly3 + linesOnly4; }
    int both() const { return pointsBoth + linesBoth; }
    int total() const { return both() + pointsSingle() + linesSingle(); }
    int points() const { return pointsBoth + pointsSingle(); }
};

/** Dimension d of the kernel of A in the rig system A v = b (v = [r1; r2; r3; t]) for exact data in
general position, from the feature counts alone: with noise the singular values show no gap.

A v = b relaxes R to any 3x3 matrix M, i.e. asks for an affine map f(X) = M X + t sending each
feature of time A onto its observations at time B. A feature seen in one time-B view constrains 2
of the 12 unknowns (onto a ray, into a plane); a line seen in both 4 (onto the line the two views
triangulate); a point seen in both only 3 (views 3 and 4 triangulate it, f(X) = Y; its fourth
equation is their epipolar constraint, which exact data satisfies anyway). Points seen in both
views fix f at those points and the other constraints then overlap:
- one such point: two lines seen in both lie in planes through it sharing a direction w, and
  M w = 0 is counted twice;
- two: M = w1 b1^T + w2 b2^T (b_i spanning the normal plane of X2 - X1) with w1, w2 in a common
  subspace of dimension s = 3 - (lines seen once) - 2 (lines seen in both); each point seen once
  removes min(s, 2) of the 2 s;
- three: M = w n^T (n normal to their plane); a point seen once removes 2, a line seen once 1, a
  line seen in both 2;
- four or more: M is fixed.
When every time-B observation is in one view the system is the homogeneous three-view one, whose
kernel holds the true v: d >= 1. (test/evaluation/codegen/stereo_rig.py checks this rule against
numeric ranks for every mix of up to six features.)
*/
int rigKernelDimension(const RigFeatureCounts& counts);

/** How many poses exact data in general position admits for these features (0: not determined).
d >= 7 leaves fewer than six constraints; two points seen in both time-B views leave a turn about
the line through them free. Two features seen in both views, two lines or a point and a line,
admit a second rigid motion mapping them onto themselves (the half turn about their common
perpendicular, through the point): 2. d = 6 is a minimal problem with 8 poses, 4 when a line is
seen in both views or the features are two points and a line.
*/
int rigSolutionCount(const RigFeatureCounts& counts, int kernelDimension);

} // namespace tripose

#endif // OPENCV_TRIPOSE_LINEAR_RIG_FEATURE_COUNTS_HPP
