"""tripose: the pose of a calibrated camera from point and line correspondences seen by cameras
whose poses are known.

Conventions (the same as the C++ API, doc/conventions.md):

* A pose (R, t) maps world coordinates into the camera: x_cam = R @ X + t. R is a 3x3 float64
  array, t has shape (3,).
* Three views: view 1 is at [I|0], view 2 at [R12|t12] (its pose relative to view 1; t12 != 0 fixes
  the metric scale), and the estimated pose is that of view 3 in the frame of view 1.
* Stereo rig: views 1 and 2 are the left and right cameras at time A (left at [I|0], right at
  [R12|t12]: the rig), views 3 and 4 the same cameras at time B; the estimate is the left camera's
  pose at time B. A row of NaN in points3/points4/lines3/lines4 marks a feature that view does not see.
* Several known views: points[k], lines[k] hold view k's observations (the known views first, then
  the new view), NaN rows where a view does not see a feature; Rs[k], ts[k] are the known views'
  world poses; the estimate is the new view's world pose.
* Observations are pixels: points of shape (N, 2), lines of shape (M, 4) (segments x0 y0 x1 y1) or
  (M, 3) (homogeneous lines a b c, not with dist). float32 or float64, any memory layout; None or an
  empty array where a view has none of that kind.
* K: one 3x3 camera matrix shared by every view, or a sequence of one per view. dist: None, or
  OpenCV's distortion coefficients (4, 5, 8, 12 or 14 values), shared or one per view; the
  observations are undistorted as cv2.undistortPoints does.
* Options: the robust functions take options=RansacOptions() (threshold, confidence,
  max_iterations: samples drawn, local_optimization, refine, refine_options, seed, min_inliers), the
  refiners options=RefineOptions() (max_iterations: Levenberg-Marquardt steps, loss, loss_scale,
  tolerance); every options class takes any of its fields as a keyword, the rest keeping their
  defaults: RansacOptions(threshold=3, min_inliers=5). The keyword arguments of earlier releases (threshold=..., loss=...) still work for
  this release and warn (README.md, "Changes").
* Results: every estimator returns a PoseResult (R, t, num_inliers, point_inliers, line_inliers,
  rms, covariance, noise_variance, candidates, candidate_rms, ambiguous, points3d, lines3d, Rs, ts;
  None where the function does not give it; result["R"] reads result.R). The candidate functions
  (estimate_pose_line_point, estimate_pose_line_point_stereo, estimate_pose_multiview) fill R, t and
  rms with the best candidate's, candidates with every candidate as (R, t), best first, and
  candidate_rms; for this release len(result), iterating over it and result[0] still read
  candidates as the list they returned before, and warn (README.md, "Changes").
* Pose covariance (PoseResult.covariance of the refiners and the robust functions): covariance is the (6, 6)
  covariance of the pose for 1 px image noise, order [rotation; translation], the rotation error d
  with R_est = expm([d]x) @ R_true, the translation error t_est - t_true, the structure
  marginalised; multiply it by the noise variance, estimated from the residuals as noise_variance.
  Both are None when the pose is not the refinement's (refine=False) or not determined.
* Bad input raises ValueError (or TypeError for a wrong type) whose message names the argument.
* Estimation releases the GIL: threads run estimates in parallel.
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _tripose_ext as _ext
from ._tripose_ext import PoseResult
from .tracking import (Features, FrameResult, FrameStatus, MatchOptions, RansacOptions, RefineOptions, StereoTracker,
                       Tracker, TrackerOptions, match_triplets)

__all__ = [
    "estimate_pose_line_point",
    "estimate_pose_line_point_ransac",
    "refine_pose_line_point",
    "estimate_pose_line_point_stereo",
    "estimate_pose_line_point_stereo_ransac",
    "refine_pose_line_point_stereo",
    "estimate_pose_multiview",
    "estimate_pose_multiview_ransac",
    "refine_pose_multiview",
    "adjust_poses_multiview",
    "triangulate_multiview",
    "PoseResult",
    "Tracker",
    "StereoTracker",
    "TrackerOptions",
    "RansacOptions",
    "RefineOptions",
    "MatchOptions",
    "Features",
    "match_triplets",
    "FrameStatus",
    "FrameResult",
]

ArrayLike = Union[np.ndarray, Sequence[Any], None]
Pose = Tuple[np.ndarray, np.ndarray]


def _seed(seed: int) -> int:
    """A seed as the 64 bits the sampler's generator starts from (a negative seed is a valid seed)."""
    return int(seed) & 0xFFFFFFFFFFFFFFFF


_RANSAC_KEYWORDS = ("threshold", "confidence", "max_iterations", "refine", "seed", "min_inliers")
_REFINE_KEYWORDS = ("max_iterations", "loss", "loss_scale", "tolerance")
# How each deprecated keyword argument's value was read into its field.
_RANSAC_CONVERSIONS = {"threshold": float, "confidence": float, "max_iterations": int, "refine": bool,
                       "seed": _seed, "min_inliers": int}
_REFINE_CONVERSIONS = {"max_iterations": int, "loss": str, "loss_scale": float, "tolerance": float}


def _ransac_options(options: Optional[RansacOptions], function: str, *values: Any) -> Tuple[Any, str]:
    """The RansacOptions to pass and the name its errors give (the fields alone for the keyword
    arguments of earlier releases, values in _RANSAC_KEYWORDS' order, which are deprecated and may
    not be mixed with options)."""
    if values.count(None) == len(values):
        if options is not None and not isinstance(options, RansacOptions):
            raise TypeError(f"options must be a tripose.RansacOptions, got {type(options).__name__}")
        return options, "options"
    legacy = dict(zip(_RANSAC_KEYWORDS, values))
    given = [name for name in _RANSAC_KEYWORDS if legacy[name] is not None]
    if options is not None:
        raise ValueError(f"{function}: options and the keyword arguments {', '.join(given)} are both given; set "
                         f"them in options ({', '.join('options.' + name for name in given)})")
    warnings.warn(f"{function}: the keyword arguments {', '.join(given)} are deprecated; pass "
                  f"options=tripose.RansacOptions({', '.join(name + '=...' for name in given)}) "
                  "(README.md, 'Changes')", DeprecationWarning, stacklevel=3)
    return RansacOptions(**{name: _RANSAC_CONVERSIONS[name](legacy[name]) for name in given}), ""


def _refine_options(options: Optional[RefineOptions], function: str, *values: Any) -> Tuple[Any, str]:
    """The RefineOptions to pass and the name its errors give, as _ransac_options() (values in
    _REFINE_KEYWORDS' order)."""
    if values.count(None) == len(values):
        if options is not None and not isinstance(options, RefineOptions):
            raise TypeError(f"options must be a tripose.RefineOptions, got {type(options).__name__}")
        return options, "options"
    legacy = dict(zip(_REFINE_KEYWORDS, values))
    given = [name for name in _REFINE_KEYWORDS if legacy[name] is not None]
    if options is not None:
        raise ValueError(f"{function}: options and the keyword arguments {', '.join(given)} are both given; set "
                         f"them in options ({', '.join('options.' + name for name in given)})")
    warnings.warn(f"{function}: the keyword arguments {', '.join(given)} are deprecated; pass "
                  f"options=tripose.RefineOptions({', '.join(name + '=...' for name in given)}) "
                  "(README.md, 'Changes')", DeprecationWarning, stacklevel=3)
    return RefineOptions(**{name: _REFINE_CONVERSIONS[name](legacy[name]) for name in given}), ""


def _view_list(value: Any, name: str) -> Any:
    """points, lines, Rs or ts of the multi-view functions: a list of one array per view."""
    if value is None:
        return None
    if not isinstance(value, (list, tuple)):
        raise TypeError(f"{name} must be a list of arrays, one per view, got {type(value).__name__}")
    return list(value)


def estimate_pose_line_point(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike,
                             lines1: ArrayLike, lines2: ArrayLike, lines3: ArrayLike,
                             K: ArrayLike, R12: ArrayLike, t12: ArrayLike, *,
                             dist: ArrayLike = None, refine: bool = False) -> PoseResult:
    """Pose of view 3 from points and lines seen in views 1, 2 (known) and 3, without outliers.

    The unified linear method on all features (at least four: points + lines); with refine=True
    each candidate is then refined by maximum likelihood over the three views (the distinct minima
    kept).

    Returns a PoseResult: candidates, the candidate poses as a list of (R, t), best first (lowest
    reprojection error in view 3; with refine=True lowest RMS over the three views), empty when the
    geometry determines no pose; candidate_rms their RMS reprojection errors (px); R, t and rms the
    best candidate's (None without one). The other fields are None (no inliers, covariance or
    structure: refine_pose_line_point gives the covariance and structure of a pose). Deprecated
    for this release: len(result), iterating over it and result[i] read candidates as the list
    returned before, and warn.
    """
    return _ext.estimate_pose_line_point(points1, points2, points3, lines1,
                                         lines2, lines3, K, R12, t12,
                                         dist, bool(refine))


def estimate_pose_line_point_ransac(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike,
                                    lines1: ArrayLike, lines2: ArrayLike, lines3: ArrayLike,
                                    K: ArrayLike, R12: ArrayLike, t12: ArrayLike, *,
                                    dist: ArrayLike = None, options: Optional[RansacOptions] = None,
                                    covariance: bool = False, threshold: Optional[float] = None,
                                    confidence: Optional[float] = None, max_iterations: Optional[int] = None,
                                    refine: Optional[bool] = None, seed: Optional[int] = None,
                                    min_inliers: Optional[int] = None) -> PoseResult:
    """Robust pose of view 3 from point and line triplets with wrong matches (RANSAC).

    options: a RansacOptions (None: the defaults): threshold (px: a feature's RMS reprojection error
    over the three views, re-triangulated with the pose), confidence, max_iterations (samples drawn),
    local_optimization, refine (finish with the maximum-likelihood refinement over the inliers, under
    refine_options: a RefineOptions with its loss), seed (the same seed gives the same result) and
    min_inliers (the fewest inliers of a returned pose, 15: chance matches agree with a pose in
    numbers up to about a dozen, so lower it only where every feature is known to be right).
    covariance: also return the pose's uncertainty (it costs one more refinement over the inliers,
    about half the estimate's time). threshold=, confidence=, max_iterations=, refine=, seed=,
    min_inliers=: the keyword arguments of earlier releases, deprecated (set them in options).

    Returns a PoseResult: R (3x3) and t (3,) (None when no pose was found or its inliers are fewer
    than min_inliers, num_inliers then 0; a pose also needs one inlier more than a minimal sample
    holds, four or five: a sample fits wrong matches too), num_inliers, point_inliers and
    line_inliers (bool arrays), rms (the RMS of the inliers' residuals in pixels), covariance ((6, 6)
    for 1 px noise, see help(tripose)) and noise_variance (px^2) of the refined pose over the inliers
    (None unless covariance=True, and without refinement or when no pose was found). The pose is view 3's
    in the frame of view 1, x_cam = R @ X + t; view 2 is at [R12 | t12] (see help(tripose) for the
    conventions).

    Several minima: candidates is a list of (R, t), the returned pose first, then the other minima of
    the cost that the final refinement reached and that the data cannot tell apart from it (their sum
    of squared residuals over the inliers exceeds the returned pose's by less than 12.59, the 95 %
    quantile of chi-square with 6 degrees of freedom, times the noise variance estimated there),
    lowest cost first; candidate_rms their RMS reprojection errors (px) over the inliers in the three
    views; ambiguous is True when there is more than one: with a narrow baseline of views 1-2 the pose
    is then a coin toss between them, and a tracker should wait for more parallax. Only the
    returned pose where the refinement searched one basin (a wide baseline, or more than 60
    inliers); empty without refinement or when no pose was found.
    """
    options, name = _ransac_options(options, "estimate_pose_line_point_ransac", threshold, confidence,
                                    max_iterations, refine, seed, min_inliers)
    return _ext.estimate_pose_line_point_ransac(points1, points2, points3, lines1, lines2, lines3, K, R12, t12, dist,
                                                options, name, bool(covariance))


def refine_pose_line_point(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike,
                           lines1: ArrayLike, lines2: ArrayLike, lines3: ArrayLike,
                           K: ArrayLike, R12: ArrayLike, t12: ArrayLike, R: ArrayLike, t: ArrayLike, *,
                           dist: ArrayLike = None, options: Optional[RefineOptions] = None,
                           max_iterations: Optional[int] = None, loss: Optional[str] = None,
                           loss_scale: Optional[float] = None, tolerance: Optional[float] = None) -> PoseResult:
    """Maximum-likelihood refinement of the pose (R, t) of view 3 and of the structure.

    Minimises the reprojection error in pixels in all three views (Levenberg-Marquardt, structure
    eliminated). R: 3x3 or a rotation vector. options: a RefineOptions (None: the defaults):
    max_iterations (Levenberg-Marquardt steps), loss ('squared', 'huber' or 'cauchy') with scale
    loss_scale pixels, tolerance (stop when a step lowers the cost by less than this fraction).
    max_iterations=, loss=, loss_scale=, tolerance=: the keyword arguments of earlier releases,
    deprecated (set them in options).

    Returns a PoseResult: R (3x3), t (3,), rms (final RMS reprojection error, px), points3d (N, 3),
    lines3d (M, 6: two 3D end points per line), covariance ((6, 6), of the pose for 1 px noise: see
    help(tripose); None when the pose is not determined) and noise_variance (the estimate of the
    noise variance in px^2 from the residuals; None with the covariance).
    """
    options, name = _refine_options(options, "refine_pose_line_point", max_iterations, loss, loss_scale, tolerance)
    return _ext.refine_pose_line_point(points1, points2, points3, lines1, lines2, lines3, K, R12, t12, R, t, dist,
                                       options, name)


def estimate_pose_line_point_stereo(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike, points4: ArrayLike,
                                    lines1: ArrayLike, lines2: ArrayLike, lines3: ArrayLike, lines4: ArrayLike,
                                    K: ArrayLike, R12: ArrayLike, t12: ArrayLike, *,
                                    dist: ArrayLike = None, refine: bool = False) -> PoseResult:
    """Motion of a calibrated stereo rig (the left camera's pose at time B), without outliers.

    Views 1, 2: left and right at time A; views 3, 4: left and right at time B (NaN rows where one
    of them does not see a feature; every feature must be seen in view 3 or 4). (R12, t12): the rig.
    Returns a PoseResult as estimate_pose_line_point: candidates (R, t), best first, candidate_rms,
    and R, t, rms of the best.
    """
    return _ext.estimate_pose_line_point_stereo(points1, points2, points3, points4,
                                                lines1, lines2, lines3, lines4,
                                                K, R12, t12, dist,
                                                bool(refine))


def estimate_pose_line_point_stereo_ransac(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike,
                                           points4: ArrayLike, lines1: ArrayLike, lines2: ArrayLike,
                                           lines3: ArrayLike, lines4: ArrayLike, K: ArrayLike, R12: ArrayLike,
                                           t12: ArrayLike, *, dist: ArrayLike = None,
                                           options: Optional[RansacOptions] = None, covariance: bool = False,
                                           threshold: Optional[float] = None, confidence: Optional[float] = None,
                                           max_iterations: Optional[int] = None, refine: Optional[bool] = None,
                                           seed: Optional[int] = None, min_inliers: Optional[int] = None) -> PoseResult:
    """Robust motion of a stereo rig (see estimate_pose_line_point_stereo and
    estimate_pose_line_point_ransac for the arguments). Returns the PoseResult of
    estimate_pose_line_point_ransac."""
    options, name = _ransac_options(options, "estimate_pose_line_point_stereo_ransac", threshold, confidence,
                                    max_iterations, refine, seed, min_inliers)
    return _ext.estimate_pose_line_point_stereo_ransac(points1, points2, points3, points4, lines1, lines2, lines3,
                                                       lines4, K, R12, t12, dist, options, name, bool(covariance))


def refine_pose_line_point_stereo(points1: ArrayLike, points2: ArrayLike, points3: ArrayLike, points4: ArrayLike,
                                  lines1: ArrayLike, lines2: ArrayLike, lines3: ArrayLike, lines4: ArrayLike,
                                  K: ArrayLike, R12: ArrayLike, t12: ArrayLike, R: ArrayLike, t: ArrayLike, *,
                                  dist: ArrayLike = None, options: Optional[RefineOptions] = None,
                                  max_iterations: Optional[int] = None, loss: Optional[str] = None,
                                  loss_scale: Optional[float] = None, tolerance: Optional[float] = None) -> PoseResult:
    """Maximum-likelihood refinement of a stereo rig's motion over its four views (arguments and
    result as refine_pose_line_point)."""
    options, name = _refine_options(options, "refine_pose_line_point_stereo", max_iterations, loss, loss_scale,
                                    tolerance)
    return _ext.refine_pose_line_point_stereo(points1, points2, points3, points4, lines1, lines2, lines3, lines4, K,
                                              R12, t12, R, t, dist, options, name)


def estimate_pose_multiview(points: Optional[Sequence[ArrayLike]], lines: Optional[Sequence[ArrayLike]],
                            K: ArrayLike, Rs: Sequence[ArrayLike], ts: Sequence[ArrayLike], *,
                            dist: ArrayLike = None, refine: bool = False) -> PoseResult:
    """World pose of a new view from features seen by V >= 2 views of known world poses Rs, ts.

    points, lines: one array per view (the known views, then the new view), NaN rows where a view
    does not see a feature; every feature must be seen by the new view and two known views.
    Returns a PoseResult as estimate_pose_line_point: candidates (R, t), best first, candidate_rms,
    and R, t, rms of the best.
    """
    return _ext.estimate_pose_multiview(_view_list(points, "points"), _view_list(lines, "lines"), K, _view_list(Rs, "Rs"),
                                        _view_list(ts, "ts"), dist, bool(refine))


def estimate_pose_multiview_ransac(points: Optional[Sequence[ArrayLike]], lines: Optional[Sequence[ArrayLike]],
                                   K: ArrayLike, Rs: Sequence[ArrayLike], ts: Sequence[ArrayLike], *,
                                   dist: ArrayLike = None, options: Optional[RansacOptions] = None,
                                   covariance: bool = False, threshold: Optional[float] = None,
                                   confidence: Optional[float] = None, max_iterations: Optional[int] = None,
                                   refine: Optional[bool] = None, seed: Optional[int] = None,
                                   min_inliers: Optional[int] = None) -> PoseResult:
    """Robust world pose of a new view against several known views (arguments as
    estimate_pose_multiview and estimate_pose_line_point_ransac; result as the latter)."""
    options, name = _ransac_options(options, "estimate_pose_multiview_ransac", threshold, confidence,
                                    max_iterations, refine, seed, min_inliers)
    return _ext.estimate_pose_multiview_ransac(_view_list(points, "points"), _view_list(lines, "lines"), K,
                                               _view_list(Rs, "Rs"), _view_list(ts, "ts"), dist, options, name,
                                               bool(covariance))


def refine_pose_multiview(points: Optional[Sequence[ArrayLike]], lines: Optional[Sequence[ArrayLike]],
                          K: ArrayLike, Rs: Sequence[ArrayLike], ts: Sequence[ArrayLike], R: ArrayLike,
                          t: ArrayLike, *, dist: ArrayLike = None, options: Optional[RefineOptions] = None,
                          max_iterations: Optional[int] = None, loss: Optional[str] = None,
                          loss_scale: Optional[float] = None, tolerance: Optional[float] = None) -> PoseResult:
    """Maximum-likelihood refinement of a new view's world pose (R, t) and the structure over every
    view, the known views fixed (result as refine_pose_line_point)."""
    options, name = _refine_options(options, "refine_pose_multiview", max_iterations, loss, loss_scale, tolerance)
    return _ext.refine_pose_multiview(_view_list(points, "points"), _view_list(lines, "lines"), K, _view_list(Rs, "Rs"),
                                      _view_list(ts, "ts"), R, t, dist, options, name)


def adjust_poses_multiview(points: Optional[Sequence[ArrayLike]], lines: Optional[Sequence[ArrayLike]],
                           K: ArrayLike, fixed_views: Sequence[bool], Rs: Sequence[ArrayLike],
                           ts: Sequence[ArrayLike], *, dist: ArrayLike = None,
                           options: Optional[RefineOptions] = None, max_iterations: Optional[int] = None,
                           loss: Optional[str] = None, loss_scale: Optional[float] = None,
                           tolerance: Optional[float] = None) -> PoseResult:
    """Local adjustment: the world poses of the views not in fixed_views and the structure refined
    together (at least two fixed views at distinct centres fix the frame and the scale).

    fixed_views: one flag per view, true where its pose stays fixed. Rs, ts: every view's world pose
    (the initial values of the free ones). options: a RefineOptions, as refine_pose_line_point.
    Returns a PoseResult: Rs, ts (every view's pose; the fixed ones as given, made exact rotations),
    rms, points3d, lines3d (R and t None).
    """
    flags = [int(bool(f)) for f in np.asarray(fixed_views).ravel()]
    options, name = _refine_options(options, "adjust_poses_multiview", max_iterations, loss, loss_scale, tolerance)
    return _ext.adjust_poses_multiview(_view_list(points, "points"), _view_list(lines, "lines"), K, flags,
                                       _view_list(Rs, "Rs"), _view_list(ts, "ts"), dist, options, name)


def triangulate_multiview(points: Optional[Sequence[ArrayLike]], lines: Optional[Sequence[ArrayLike]],
                          K: ArrayLike, Rs: Sequence[ArrayLike], ts: Sequence[ArrayLike], *,
                          dist: ArrayLike = None) -> Dict[str, Any]:
    """Structure of features seen by views of known pose (V >= 2, every view posed: Rs, ts), and
    the reprojection error of every observation; each feature triangulated from all the views that
    see it, as the robust estimators' final inlier test does.

    Returns a dict: num_with_structure (points + lines with structure, the C++ return value),
    points3d (N, 3) and lines3d (M, 6) (two points of each line, on the end-point rays of the first
    view that sees it), NaN rows for features without structure (seen by fewer than two views,
    parallel rays, one plane, or behind a view that sees them); point_errors (N, V):
    the distance in px between each point's projection and its observation; line_errors (M, V): the
    larger of the two observed end points' distances to the line's image. NaN where a view does not
    see the feature, inf in every view that sees a feature without structure. A wrong observation
    pulls the structure towards it: drop the observation with the largest error and triangulate
    again. A line seen by two views fits both exactly; its errors tell from three views on.
    """
    return _ext.triangulate_multiview(_view_list(points, "points"), _view_list(lines, "lines"), K,
                                      _view_list(Rs, "Rs"), _view_list(ts, "ts"), dist)
