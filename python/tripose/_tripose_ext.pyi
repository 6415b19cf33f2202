"""
tripose's extension; use the functions of the tripose package, which document them.
"""

from collections.abc import Iterator, Sequence
import enum
from typing import overload

import numpy
import numpy.typing


class RefineOptions:
    """
    Options of the maximum-likelihood refinement: Levenberg-Marquardt over the pose and the structure, minimising the reprojection error in pixels under a loss. Fields: max_iterations, loss, loss_scale, tolerance.
    """

    def __init__(self, *, max_iterations: int = 30, loss: str = 'squared', loss_scale: float = 1.0, tolerance: float = 1e-10) -> None:
        """The defaults, with any field given as a keyword set to its value."""

    @property
    def max_iterations(self) -> int:
        """Levenberg-Marquardt steps, accepted or rejected (> 0)."""

    @max_iterations.setter
    def max_iterations(self, arg: int, /) -> None: ...

    @property
    def loss(self) -> str:
        """The loss of each reprojection error: 'squared', 'huber' or 'cauchy'."""

    @loss.setter
    def loss(self, arg: str, /) -> None: ...

    @property
    def loss_scale(self) -> float:
        """Scale of the robust loss in pixels (> 0)."""

    @loss_scale.setter
    def loss_scale(self, arg: float, /) -> None: ...

    @property
    def tolerance(self) -> float:
        """
        Stop when an accepted step lowers the cost by less than this fraction (>= 0).
        """

    @tolerance.setter
    def tolerance(self, arg: float, /) -> None: ...

    def __repr__(self) -> str: ...

class RansacOptions:
    """
    Options of the robust estimators (LO-MSAC over minimal samples, then the maximum-likelihood refinement over the inliers). Fields: threshold (px), confidence, max_iterations (samples), local_optimization, refine, refine_options (a RefineOptions), seed, min_inliers.
    """

    def __init__(self, *, threshold: float = 2.0, confidence: float = 0.999, max_iterations: int = 10000, local_optimization: bool = True, refine: bool = True, refine_options: RefineOptions = ..., seed: int = 0, min_inliers: int = 15) -> None:
        """The defaults, with any field given as a keyword set to its value."""

    @property
    def threshold(self) -> float:
        """Inlier threshold in pixels (> 0)."""

    @threshold.setter
    def threshold(self, arg: float, /) -> None: ...

    @property
    def confidence(self) -> float:
        """
        Probability, in (0, 1), of drawing an all-inlier sample before stopping.
        """

    @confidence.setter
    def confidence(self, arg: float, /) -> None: ...

    @property
    def max_iterations(self) -> int:
        """Most samples drawn (> 0)."""

    @max_iterations.setter
    def max_iterations(self, arg: int, /) -> None: ...

    @property
    def local_optimization(self) -> bool:
        """Re-estimate from the inliers of every new best model."""

    @local_optimization.setter
    def local_optimization(self, arg: bool, /) -> None: ...

    @property
    def refine(self) -> bool:
        """Finish with the maximum-likelihood refinement over the inliers."""

    @refine.setter
    def refine(self, arg: bool, /) -> None: ...

    @property
    def refine_options(self) -> RefineOptions:
        """Options of that refinement."""

    @refine_options.setter
    def refine_options(self, arg: RefineOptions, /) -> None: ...

    @property
    def seed(self) -> int:
        """Seed of the sampler: the same seed gives the same result."""

    @seed.setter
    def seed(self, arg: int, /) -> None: ...

    @property
    def min_inliers(self) -> int:
        """
        Fewest inliers of a returned pose (>= 0); an estimate with fewer is no pose. Chance matches agree with a pose in numbers up to about a dozen: lower it only where every feature is known to be right.
        """

    @min_inliers.setter
    def min_inliers(self, arg: int, /) -> None: ...

    def __repr__(self) -> str: ...

class MatchOptions:
    """
    How the features of two frames are matched: candidates near the epipolar lines (or any, without a geometry), then mutual best descriptor with a ratio test. Fields: epipolar_distance (px), min_band_overlap, min_epipolar_angle_deg, point_ratio, line_ratio, max_line_distance, min_fundamental_inliers.
    """

    def __init__(self, *, epipolar_distance: float = 2.0, min_band_overlap: float = 0.5, min_epipolar_angle_deg: float = 5.0, point_ratio: float = 0.8, line_ratio: float = 0.8, max_line_distance: float = 80.0, min_fundamental_inliers: int = 30) -> None:
        """The defaults, with any field given as a keyword set to its value."""

    @property
    def epipolar_distance(self) -> float:
        """
        Largest distance (px) of a point from the other's epipolar line; also the fundamental matrix's inlier distance.
        """

    @epipolar_distance.setter
    def epipolar_distance(self, arg: float, /) -> None: ...

    @property
    def min_band_overlap(self) -> float:
        """
        Fraction of a segment that must overlap the epipolar band of the other.
        """

    @min_band_overlap.setter
    def min_band_overlap(self, arg: float, /) -> None: ...

    @property
    def min_epipolar_angle_deg(self) -> float:
        """
        Segments closer than this to the epipolar lines are not matched under the geometry.
        """

    @min_epipolar_angle_deg.setter
    def min_epipolar_angle_deg(self, arg: float, /) -> None: ...

    @property
    def point_ratio(self) -> float:
        """Ratio test of point descriptors."""

    @point_ratio.setter
    def point_ratio(self, arg: float, /) -> None: ...

    @property
    def line_ratio(self) -> float:
        """Ratio test of line descriptors."""

    @line_ratio.setter
    def line_ratio(self, arg: float, /) -> None: ...

    @property
    def max_line_distance(self) -> float:
        """Binary line descriptors further apart than this many bits never match."""

    @max_line_distance.setter
    def max_line_distance(self, arg: float, /) -> None: ...

    @property
    def min_fundamental_inliers(self) -> int:
        """
        Matches that must agree with the fundamental matrix for two frames to be matched under it.
        """

    @min_fundamental_inliers.setter
    def min_fundamental_inliers(self, arg: int, /) -> None: ...

    def __repr__(self) -> str: ...

class TrackerOptions:
    """
    Options of tripose.Tracker: the window of keyframes a frame is registered against, the support a pose needs (min_inliers), keyframes by parallax, the track checks, the local adjustment, and the RansacOptions (ransac) and MatchOptions (matching) it uses. Defaults are the library's.
    """

    def __init__(self, *, window: int = 5, min_inliers: int = 15, keyframe_parallax_deg: float = 0.1, check_tracks: bool = True, local_adjustment: bool = True, loop_closure: bool = False, global_adjustment_interval: int = 0, robust: bool = True, ransac: RansacOptions = ..., matching: MatchOptions = ..., covariance: bool = False, max_frame_gap: int = 3) -> None:
        """The defaults, with any field given as a keyword set to its value."""

    @property
    def window(self) -> int:
        """Keyframes a new frame is registered against (>= 2)."""

    @window.setter
    def window(self, arg: int, /) -> None: ...

    @property
    def min_inliers(self) -> int:
        """
        A frame is registered only when at least this many features agree with its pose.
        """

    @min_inliers.setter
    def min_inliers(self, arg: int, /) -> None: ...

    @property
    def keyframe_parallax_deg(self) -> float:
        """
        A registered frame is a keyframe when its structure's median parallax to the window's last keyframe is at least this (degrees; 0: every registered frame).
        """

    @keyframe_parallax_deg.setter
    def keyframe_parallax_deg(self, arg: float, /) -> None: ...

    @property
    def check_tracks(self) -> bool:
        """
        Drop the window's observations that disagree with its poses, and split the tracks a registration rejects.
        """

    @check_tracks.setter
    def check_tracks(self, arg: bool, /) -> None: ...

    @property
    def local_adjustment(self) -> bool:
        """
        Refine the window's registered frames and their structure after each registration, splitting off the features matched by the tracker that disagree with the result.
        """

    @local_adjustment.setter
    def local_adjustment(self, arg: bool, /) -> None: ...

    @property
    def loop_closure(self) -> bool:
        """
        After each new keyframe, look for a place seen before among the keyframes older than the window (by descriptors); registered against it, join the tracks and, once per loop for a place more than two windows of keyframes before the frame, correct the frames since by a pose graph and adjust every frame (frames given as features only).
        """

    @loop_closure.setter
    def loop_closure(self, arg: bool, /) -> None: ...

    @property
    def global_adjustment_interval(self) -> int:
        """
        Every this many new keyframes, adjust every registered frame and the structure together, the given frames held, and split off the observations that disagree, except those linked by id in track_observations() (0: only at a loop).
        """

    @global_adjustment_interval.setter
    def global_adjustment_interval(self, arg: int, /) -> None: ...

    @property
    def robust(self) -> bool:
        """
        Register with the robust estimator (else the linear one on every feature).
        """

    @robust.setter
    def robust(self, arg: bool, /) -> None: ...

    @property
    def ransac(self) -> RansacOptions:
        """RansacOptions of the registration."""

    @ransac.setter
    def ransac(self, arg: RansacOptions, /) -> None: ...

    @property
    def matching(self) -> MatchOptions:
        """MatchOptions of consecutive frames."""

    @matching.setter
    def matching(self, arg: MatchOptions, /) -> None: ...

    @property
    def covariance(self) -> bool:
        """
        Also the covariance of each registered frame's pose (FrameResult.covariance); it costs one more refinement per frame.
        """

    @covariance.setter
    def covariance(self, arg: bool, /) -> None: ...

    @property
    def max_frame_gap(self) -> int:
        """
        How many frames back a frame is matched when the nearer ones share too few matches with it.
        """

    @max_frame_gap.setter
    def max_frame_gap(self, arg: int, /) -> None: ...

    def __repr__(self) -> str: ...

class FrameStatus(enum.Enum):
    """
    What the tracker made of a frame: GIVEN (its pose came with it), REGISTERED (registered against the window of keyframes), LOST (no pose: too little support; FrameResult.reason says why) or RESTARTED (a stereo tracker lost for longer began a new map here; FrameResult.map).
    """

    GIVEN = 0
    """The pose came with the frame."""

    REGISTERED = 1
    """Registered against the window of keyframes."""

    LOST = 2
    """No pose: too little support (see FrameResult.reason)."""

    RESTARTED = 3
    """
    A stereo tracker lost for more than max_frame_gap frames began a new map at this frame, placed at the last pose known until a place of an earlier map joins them (FrameResult.map).
    """

class FrameResult:
    """
    What the tracker made of one frame: status, the pose R, t (x_cam = R @ X + t; None when lost), features and inliers, keyframe, the time, why it was lost, and each feature's track.
    """

    @property
    def frame(self) -> int:
        """The frame's index, in the order given."""

    @property
    def status(self) -> FrameStatus:
        """FrameStatus.GIVEN, REGISTERED, LOST or RESTARTED."""

    @property
    def R(self) -> object:
        """The rotation (3, 3) of x_cam = R @ X + t; None when lost."""

    @property
    def t(self) -> object:
        """The translation (3,); None when lost."""

    @property
    def features(self) -> int:
        """Features the frame shares with at least two window keyframes."""

    @property
    def inliers(self) -> int:
        """Of them, those that agree with the pose."""

    @property
    def known_views(self) -> int:
        """Window keyframes registered against."""

    @property
    def keyframe(self) -> bool:
        """Later frames are registered against it."""

    @property
    def recognised_keyframe(self) -> int:
        """
        The keyframe of a place seen before through which the frame was registered: a loop it closed, or where the lost camera was found again; -1 for neither.
        """

    @property
    def map(self) -> int:
        """
        The map the pose is in: 0 (the world of the given poses) unless a stereo tracker restarted and has not yet joined its new map to an earlier one; then the new map's poses move into the earlier map (StereoTracker.pose and map_of give them as they are now).
        """

    @property
    def milliseconds(self) -> float:
        """Time of matching and registration."""

    @property
    def reason(self) -> str:
        """Why the frame is lost; empty otherwise."""

    @property
    def covariance(self) -> object:
        """
        With TrackerOptions.covariance, for a registered frame whose pose is determined: the (6, 6) covariance of its pose for 1 px noise, [rotation; translation], the window's poses held; multiply by noise_variance. None otherwise.
        """

    @property
    def noise_variance(self) -> object:
        """
        The noise variance (px^2) estimated from the inliers' residuals, with covariance; None otherwise.
        """

    @property
    def point_tracks(self) -> object:
        """Per point of the frame, its track (-1: none)."""

    @property
    def line_tracks(self) -> object:
        """Per segment of the frame, its track (-1: none)."""

    def __repr__(self) -> str: ...

class PoseResult:
    """
    The result of the candidate estimators (estimate_pose_line_point, estimate_pose_line_point_stereo, estimate_pose_multiview), the robust functions (estimate_pose_*_ransac), the refiners (refine_pose_*) and adjust_poses_multiview: R, t, num_inliers, point_inliers, line_inliers, rms, covariance, noise_variance, candidates, candidate_rms, ambiguous, points3d, lines3d, Rs, ts; None where the function does not give one. result['R'] reads a field as result.R does (the dictionaries of earlier releases); len(result), iterating and result[0] read the candidates of estimate_pose_* as the list of earlier releases (deprecated: read result.candidates).
    """

    @property
    def R(self, /) -> numpy.typing.NDArray[numpy.float64] | None:
        """
        Rotation (3, 3) of the pose, x_cam = R @ X + t (estimate_pose_*: the best candidate's); None when no pose was found.
        """

    @property
    def t(self, /) -> numpy.typing.NDArray[numpy.float64] | None:
        """Translation (3,) of the pose; None when no pose was found."""

    @property
    def num_inliers(self, /) -> int | None:
        """
        Robust functions: points + lines that agree with the pose (0 when no pose was found).
        """

    @property
    def point_inliers(self, /) -> numpy.typing.NDArray[numpy.bool_] | None:
        """Robust functions: bool (N,), the points that agree with the pose."""

    @property
    def line_inliers(self, /) -> numpy.typing.NDArray[numpy.bool_] | None:
        """Robust functions: bool (M,), the lines that agree with the pose."""

    @property
    def rms(self, /) -> float | None:
        """
        RMS reprojection error (px): over the inliers (robust functions; NaN without a pose), over every observation (refiners), the best candidate's (estimate_pose_*: candidate_rms[0]; None without one).
        """

    @property
    def covariance(self, /) -> numpy.typing.NDArray[numpy.float64] | None:
        """
        (6, 6) covariance of the pose for 1 px image noise, [rotation; translation] (help(tripose)); None when not asked for (robust functions: covariance=False), without refinement or not determined.
        """

    @property
    def noise_variance(self, /) -> float | None:
        """
        Estimate of the image noise variance (px^2) from the residuals; None with the covariance.
        """

    @property
    def candidates(self, /) -> list[tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]] | None:
        """
        Robust functions: the minima of the final refinement that the data cannot tell apart, as (R, t), the returned pose first; empty without refinement or without a pose. estimate_pose_*: every candidate as (R, t), best first (R, t the first); empty when the geometry determines no pose.
        """

    @property
    def candidate_rms(self, /) -> list[float] | None:
        """
        The RMS reprojection error (px) of each candidate: robust functions over the inliers; estimate_pose_* in the estimated view(s), or with refine=True over every view.
        """

    @property
    def ambiguous(self, /) -> bool | None:
        """Robust functions: more than one candidate (the pose is a coin toss)."""

    @property
    def points3d(self, /) -> numpy.typing.NDArray[numpy.float64] | None:
        """Refiners: the refined points (N, 3) in the world (view 1's) frame."""

    @property
    def lines3d(self, /) -> numpy.typing.NDArray[numpy.float64] | None:
        """Refiners: two refined points (M, 6) of each line."""

    @property
    def Rs(self, /) -> list[numpy.typing.NDArray[numpy.float64]] | None:
        """
        adjust_poses_multiview: every view's rotation (the fixed ones as given).
        """

    @property
    def ts(self, /) -> list[numpy.typing.NDArray[numpy.float64]] | None:
        """adjust_poses_multiview: every view's translation."""

    @overload
    def __getitem__(self, arg: str, /) -> object: ...

    @overload
    def __getitem__(self, index: int) -> object:
        """Deprecated: the candidate at index (result.candidates[index])."""

    @overload
    def __getitem__(self, index: slice) -> object:
        """Deprecated: the candidates of the slice (result.candidates[i:j])."""

    def __len__(self) -> int:
        """Deprecated: the number of candidates (len(result.candidates))."""

    def __iter__(self) -> Iterator:
        """Deprecated: the candidates as (R, t) (iter(result.candidates))."""

    def __bool__(self) -> bool:
        """
        True, except the result of estimate_pose_* without a candidate (deprecated: read result.R is not None).
        """

    def __contains__(self, arg: str, /) -> bool: ...

    def get(self, key: str, default: object | None = None) -> object: ...

    def keys(self) -> list:
        """The names of every field, as a dictionary's keys."""

    def __repr__(self) -> str: ...

def estimate_pose_line_point(points1: object | None, points2: object | None, points3: object | None, lines1: object | None, lines2: object | None, lines3: object | None, K: object | None, R12: object | None, t12: object | None, dist: object | None, refine: bool) -> PoseResult: ...

def estimate_pose_line_point_ransac(points1: object | None, points2: object | None, points3: object | None, lines1: object | None, lines2: object | None, lines3: object | None, K: object | None, R12: object | None, t12: object | None, dist: object | None, options: RansacOptions | None, options_name: str, covariance: bool) -> PoseResult: ...

def refine_pose_line_point(points1: object | None, points2: object | None, points3: object | None, lines1: object | None, lines2: object | None, lines3: object | None, K: object | None, R12: object | None, t12: object | None, R: object | None, t: object | None, dist: object | None, options: RefineOptions | None, options_name: str) -> PoseResult: ...

def estimate_pose_line_point_stereo(points1: object | None, points2: object | None, points3: object | None, points4: object | None, lines1: object | None, lines2: object | None, lines3: object | None, lines4: object | None, K: object | None, R12: object | None, t12: object | None, dist: object | None, refine: bool) -> PoseResult: ...

def estimate_pose_line_point_stereo_ransac(points1: object | None, points2: object | None, points3: object | None, points4: object | None, lines1: object | None, lines2: object | None, lines3: object | None, lines4: object | None, K: object | None, R12: object | None, t12: object | None, dist: object | None, options: RansacOptions | None, options_name: str, covariance: bool) -> PoseResult: ...

def refine_pose_line_point_stereo(points1: object | None, points2: object | None, points3: object | None, points4: object | None, lines1: object | None, lines2: object | None, lines3: object | None, lines4: object | None, K: object | None, R12: object | None, t12: object | None, R: object | None, t: object | None, dist: object | None, options: RefineOptions | None, options_name: str) -> PoseResult: ...

def estimate_pose_multiview(points: object | None, lines: object | None, K: object | None, Rs: object | None, ts: object | None, dist: object | None, refine: bool) -> PoseResult: ...

def estimate_pose_multiview_ransac(points: object | None, lines: object | None, K: object | None, Rs: object | None, ts: object | None, dist: object | None, options: RansacOptions | None, options_name: str, covariance: bool) -> PoseResult: ...

def refine_pose_multiview(points: object | None, lines: object | None, K: object | None, Rs: object | None, ts: object | None, R: object | None, t: object | None, dist: object | None, options: RefineOptions | None, options_name: str) -> PoseResult: ...

def adjust_poses_multiview(points: object | None, lines: object | None, K: object | None, fixed_views: Sequence[int], Rs: object | None, ts: object | None, dist: object | None, options: RefineOptions | None, options_name: str) -> PoseResult: ...

def triangulate_multiview(points: object | None, lines: object | None, K: object | None, Rs: object | None, ts: object | None, dist: object | None) -> dict: ...
