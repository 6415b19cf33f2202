"""Tracking a camera frame by frame: tripose.Tracker, its options and its results.

A monocular tracker is built from a camera (K, optional distortion) and TrackerOptions, and fed one
frame at a time: features (points and segments with descriptors, from tripose.images or any
detector), or observations of tracks the caller already linked. The first two frames need their
poses (they fix the world frame and the scale); every later frame is registered against a window of
keyframes and returns a FrameResult. A stereo tracker is built from the two cameras and the rig (the
right camera's pose relative to the left) and fed the features of both images of each frame; it
needs no pose.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Mapping, Optional, Tuple, Union

import numpy as np

from . import _tripose_ext as _ext

TrackerOptions = _ext.TrackerOptions
RansacOptions = _ext.RansacOptions
RefineOptions = _ext.RefineOptions
MatchOptions = _ext.MatchOptions
FrameStatus = _ext.FrameStatus
FrameResult = _ext.FrameResult

__all__ = ["Features", "match_triplets", "Tracker", "StereoTracker", "TrackerOptions", "RansacOptions", "RefineOptions", "MatchOptions",
           "FrameStatus", "FrameResult"]


def _rows(value: Any, name: str, width: int) -> np.ndarray:
    """(N, width) float64, C-contiguous; None or empty: (0, width)."""
    if value is None:
        return np.zeros((0, width))
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name} must be an array of numbers: {e}") from None
    if a.size == 0:
        return np.zeros((0, width))
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{name} must have shape (N, {width}), got {a.shape}")
    return np.ascontiguousarray(a)


def _ids(point_ids: Any, line_ids: Any, num_points: int, num_segments: int):
    """The point and line ids as int64 arrays, one per point and per segment."""
    ids = []
    for value, name, n in ((point_ids, "point_ids", num_points), (line_ids, "line_ids", num_segments)):
        a = np.zeros(0, np.int64) if value is None else np.asarray(value)
        if a.size and not np.issubdtype(a.dtype, np.integer):
            raise TypeError(f"{name} must be integers, got {a.dtype}")
        a = np.ascontiguousarray(a.reshape(-1), dtype=np.int64)
        if len(a) != n:
            raise ValueError(f"{name} must hold one id per feature: {len(a)} ids for {n} features")
        ids.append(a)
    return ids


def _descriptors(value: Any, name: str, rows: int) -> np.ndarray:
    """float32 rows (L2) or uint8 rows (Hamming), one per feature."""
    if value is None:
        if rows:
            raise ValueError(f"{name} is missing: one descriptor row per feature is needed")
        return np.zeros((0, 1), np.float32)
    a = np.asarray(value)
    if a.dtype == np.uint8:
        out = np.ascontiguousarray(a)
    elif np.issubdtype(a.dtype, np.floating):
        out = np.ascontiguousarray(a, dtype=np.float32)
    else:
        raise TypeError(f"{name} must be float (L2 distance) or uint8 (Hamming distance), got {a.dtype}")
    if a.size == 0 and rows == 0:
        return out.reshape(0, out.shape[-1] if out.ndim == 2 and out.shape[-1] else 1)
    if out.ndim != 2 or out.shape[0] != rows:
        raise ValueError(f"{name} must have shape ({rows}, D), one row per feature, got {a.shape}")
    return out


@dataclass
class Features:
    """What a detector found in one image: points (N, 2) and segments (M, 4: x0 y0 x1 y1) in
    pixels, each with a descriptor row (float: L2 distance, such as SIFT; uint8: Hamming distance,
    such as ORB, AKAZE or LBD). Segments of a front end that orients them by their edge's polarity
    are matched with that test."""

    points: Any = None
    point_descriptors: Any = None
    segments: Any = None
    line_descriptors: Any = None


FeaturesLike = Union[Features, Mapping[str, Any], None]


def _pose(R: Any, t: Any) -> Tuple[Optional[np.ndarray], Optional[np.ndarray]]:
    if R is None and t is None:
        return None, None
    if R is None or t is None:
        raise ValueError("R and t must be given together (the frame's pose), or neither")
    R = np.asarray(R, dtype=np.float64)
    if R.shape != (3, 3):
        raise ValueError(f"R must have shape (3, 3), got {R.shape}")
    t = np.asarray(t, dtype=np.float64).reshape(-1)
    if t.shape != (3,):
        raise ValueError(f"t must hold 3 elements, got {t.size}")
    return np.ascontiguousarray(R), np.ascontiguousarray(t.reshape(3, 1))


def _features(features: FeaturesLike, name: str) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """points, point_descriptors, segments, line_descriptors of a Features or a dict, checked."""
    if features is None:
        features = Features()
    if isinstance(features, Mapping):
        unknown = set(features) - {"points", "point_descriptors", "segments", "line_descriptors"}
        if unknown:
            raise ValueError(f"{name} has unknown keys {sorted(unknown)}: expected points, point_descriptors, "
                             "segments, line_descriptors")
        features = Features(**features)
    if not isinstance(features, Features):
        raise TypeError(f"{name} must be a tripose.Features or a dict, got {type(features).__name__}")
    points = _rows(features.points, f"{name}.points", 2)
    segments = _rows(features.segments, f"{name}.segments", 4)
    return (points, _descriptors(features.point_descriptors, f"{name}.point_descriptors", len(points)), segments,
            _descriptors(features.line_descriptors, f"{name}.line_descriptors", len(segments)))


def match_triplets(features1: FeaturesLike, features2: FeaturesLike, features3: FeaturesLike, K: Any, R12: Any,
                   t12: Any, options: Optional[MatchOptions] = None) -> Dict[str, Any]:
    """Point and segment triplets of three images whose views 1 and 2 have a known relative pose.

    Views 1 and 2 are matched under their epipolar geometry (view 2 at [R12 | t12], view 1 at the
    origin), then view 3 to those pairs' features in view 2 under the fundamental matrix of their
    descriptor matches (by descriptor alone when too few agree with one); every match mutual best
    with a ratio test. features*: tripose.Features or dicts (tripose.images.extract_features),
    positions undistorted. K: one (3, 3) matrix or a sequence of three.

    Returns a dict: points1..points3 (N, 2) and lines1..lines3 (M, 4), row i of each view the same
    feature, as estimate_pose_line_point_ransac takes them; point_rows1..3 and segment_rows1..3 (the
    rows of each view's features); point_pairs and segment_pairs (views 1-2 matched, before view 3);
    pair_agreement (matches, agreeing): of the points of views 1-2 matched by descriptor alone, how
    many lie on their epipolar lines under R12, t12 (under 30 % of 20 or more: the pose or the
    image order is wrong).
    """
    if options is None:
        options = MatchOptions()
    if not isinstance(options, MatchOptions):
        raise TypeError(f"options must be a tripose.MatchOptions, got {type(options).__name__}")
    views = [_features(f, f"features{v + 1}") for v, f in enumerate((features1, features2, features3))]
    Ks = [_camera(k, f"K[{v}]") for v, k in enumerate(K)] if isinstance(K, (list, tuple)) else [_camera(K)] * 3
    if len(Ks) != 3:
        raise ValueError(f"K must be one (3, 3) matrix or three, got {len(Ks)}")
    R12 = np.asarray(R12, dtype=np.float64)
    if R12.shape != (3, 3):
        raise ValueError(f"R12 must have shape (3, 3), got {R12.shape}")
    t12 = np.asarray(t12, dtype=np.float64).reshape(-1)
    if t12.shape != (3,):
        raise ValueError(f"t12 must hold 3 elements, got {t12.size}")
    out = _ext._match_triplets([v[0].tobytes() for v in views], [len(v[0]) for v in views],
                               [v[1].tobytes() for v in views], [v[1].shape[1] for v in views],
                               [bool(v[1].dtype == np.uint8) for v in views], [v[2].tobytes() for v in views],
                               [len(v[2]) for v in views], [v[3].tobytes() for v in views],
                               [v[3].shape[1] for v in views], [bool(v[3].dtype == np.uint8) for v in views],
                               [k.tobytes() for k in Ks], np.ascontiguousarray(R12).tobytes(),
                               np.ascontiguousarray(t12).tobytes(), options)
    for v in range(3):
        out[f"points{v + 1}"] = views[v][0][out[f"point_rows{v + 1}"]]
        out[f"lines{v + 1}"] = views[v][2][out[f"segment_rows{v + 1}"]]
    return out


def _pose_bytes(R: Optional[np.ndarray], t: Optional[np.ndarray]) -> Tuple[Optional[bytes], Optional[bytes]]:
    return (None, None) if R is None else (R.tobytes(), t.tobytes())


def _camera(K: Any, name: str = "K") -> np.ndarray:
    K = np.asarray(K, dtype=np.float64)
    if K.shape != (3, 3):
        raise ValueError(f"{name} must have shape (3, 3), got {K.shape}")
    return np.ascontiguousarray(K)


class Tracker:
    """A monocular camera tracked frame by frame from points and line segments.

    Tracker(K, dist=None, options=None): K the (3, 3) camera matrix, dist OpenCV's distortion
    coefficients (None: none; the features are undistorted with them), options a TrackerOptions.

    Each call of track() (features) or track_observations() (linked observations) takes the next
    frame and returns its FrameResult: status (FrameStatus.GIVEN, REGISTERED or LOST), R and t
    (x_cam = R @ X + t; None when lost), features and inliers, keyframe, and, per feature of the
    frame, its track. The first two frames need R and t; a later frame may have them too.
    Bad input raises ValueError or TypeError naming the argument; a frame with too little support
    is LOST (FrameResult.reason says why), never given a wrong pose.
    """

    def __init__(self, K: Any, dist: Any = None, options: Optional[TrackerOptions] = None):
        if options is None:
            options = TrackerOptions()
        if not isinstance(options, TrackerOptions):
            raise TypeError(f"options must be a tripose.TrackerOptions, got {type(options).__name__}")
        coefficients = [] if dist is None else [float(v) for v in np.asarray(dist, dtype=np.float64).ravel()]
        self._tracker = _ext._Tracker(_camera(K).tobytes(), coefficients, options)

    def track(self, features: FeaturesLike, R: Any = None, t: Any = None, K: Any = None) -> FrameResult:
        """The next frame from its features (a Features, or a dict with the same keys such as
        tripose.images.extract_features returns; None for a frame that could not be read, which is
        then lost). R, t: the frame's pose when known. K: this frame's camera matrix, when it differs."""
        points, point_descriptors, segments, line_descriptors = _features(features, "features")
        R, t = _pose(R, t)
        return self._tracker.add_features(points.tobytes(), len(points), point_descriptors.tobytes(),
                                          point_descriptors.shape[1], bool(point_descriptors.dtype == np.uint8),
                                          segments.tobytes(), len(segments), line_descriptors.tobytes(),
                                          line_descriptors.shape[1], bool(line_descriptors.dtype == np.uint8),
                                          *_pose_bytes(R, t), None if K is None else _camera(K).tobytes())

    def track_observations(self, points: Any, point_ids: Any, segments: Any = None, line_ids: Any = None,
                           R: Any = None, t: Any = None, K: Any = None) -> FrameResult:
        """The next frame from observations of tracks the caller linked: points (N, 2) with
        point_ids (N integers), segments (M, 4) with line_ids (M integers); an id names the same
        feature in every frame."""
        points = _rows(points, "points", 2)
        segments = _rows(segments, "segments", 4)
        ids = _ids(point_ids, line_ids, len(points), len(segments))
        R, t = _pose(R, t)
        return self._tracker.add_observations(points.tobytes(), ids[0].tolist(), segments.tobytes(), ids[1].tolist(),
                                              *_pose_bytes(R, t), None if K is None else _camera(K).tobytes())

    @property
    def num_frames(self) -> int:
        """Frames given so far."""
        return self._tracker.num_frames

    def pose(self, frame: int) -> Optional[Tuple[np.ndarray, np.ndarray]]:
        """The current (R, t) of frame `frame` (a local adjustment may have moved it since its
        result); None when the frame is lost."""
        return self._tracker.pose(int(frame))

    def tracks(self, frame: int) -> Tuple[np.ndarray, np.ndarray]:
        """(point_tracks, line_tracks) of frame `frame` as they are now: the track of each of its points
        and segments, -1 for none. A frame's features join tracks as later frames are matched to them
        (FrameResult holds them as they were when the frame was added)."""
        return self._tracker.tracks(int(frame))

    def trajectory(self):
        """Every frame's current pose, in order: a list of (R, t), None for a lost frame."""
        return [self._tracker.pose(k) for k in range(self.num_frames)]

    @property
    def options(self) -> TrackerOptions:
        return self._tracker.options

    @property
    def given_pair_agreement(self) -> Tuple[int, int]:
        """(matches, agreeing): of the points of frames 0 and 1 matched by descriptor alone, how many
        lie on their epipolar lines under the given poses. Under 30 % of 20 or more says the images
        are not in the poses' order or the calibration is wrong."""
        return self._tracker.given_pair_agreement


def _feature_bytes(features: Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]) -> list:
    """The arguments of the extension's add_* methods for one image's checked features."""
    points, point_descriptors, segments, line_descriptors = features
    return [points.tobytes(), len(points), point_descriptors.tobytes(), point_descriptors.shape[1],
            bool(point_descriptors.dtype == np.uint8), segments.tobytes(), len(segments), line_descriptors.tobytes(),
            line_descriptors.shape[1], bool(line_descriptors.dtype == np.uint8)]


def _distortion(dist: Any) -> list:
    return [] if dist is None else [float(v) for v in np.asarray(dist, dtype=np.float64).ravel()]


class StereoTracker:
    """A calibrated stereo rig tracked frame by frame from points and line segments, with no pose given.

    StereoTracker(K_left, K_right, R, t, dist_left=None, dist_right=None, options=None): the two
    (3, 3) camera matrices, the rig (R, t): the right camera's pose relative to the left
    (x_right = R @ x_left + t, t non-zero: the baseline, in the units the poses are wanted in),
    each camera's distortion coefficients (None: none; the features are undistorted with them) and
    TrackerOptions.

    Each call of track(left_features, right_features) takes the next frame and returns its
    FrameResult; a frame's pose is its left camera's. The first frame's left camera is the world's
    origin (status GIVEN) unless R, t are given. Every frame's left and right features are matched
    under the rig's epipolar geometry (segments within matching.min_epipolar_angle_deg of the
    epipolar lines are not), its left features linked to the frame before (as Tracker links them;
    past more lost frames than options.max_frame_gap, to the newest recent keyframe they match),
    and it is registered with the stereo-rig estimator against the stereo pair of the newest of
    the last options.window keyframes that gives it options.min_inliers inliers; otherwise it is
    LOST (FrameResult.reason says why) and the next frame looks back over the same keyframes. A
    registered frame is a keyframe when its structure subtends options.keyframe_parallax_deg
    between it and its keyframe, or when that keyframe's stereo pair sees less than half of its own
    stereo matches (a rig turning on the spot). options.local_adjustment is not used. In a
    FrameResult, features counts the features the frame shares with its keyframe's stereo pair
    (those with the newest keyframe when lost), and known_views is 1 (one stereo keyframe) for a
    registered frame.

    A frame no window keyframe registers is looked for among the older keyframes' places (FrameResult.
    recognised_keyframe). Lost for more than options.max_frame_gap frames in a row at a place no
    keyframe shows, the rig starts again: the next frame with twice options.min_inliers stereo matches,
    against whose stereo pair the frame before it registers, begins a new map (FrameStatus.RESTARTED, FrameResult.map), placed at the last pose known, and the
    frames after it are tracked in that map. When a later keyframe recognises a place of an earlier
    map, the two are joined: the newer map's poses move by one rigid motion into the earlier map,
    and pose(), map_of() and trajectory() give them as they are now. Bad input raises ValueError or
    TypeError naming the argument.
    """

    def __init__(self, K_left: Any, K_right: Any, R: Any, t: Any, dist_left: Any = None, dist_right: Any = None,
                 options: Optional[TrackerOptions] = None):
        if options is None:
            options = TrackerOptions()
        if not isinstance(options, TrackerOptions):
            raise TypeError(f"options must be a tripose.TrackerOptions, got {type(options).__name__}")
        if R is None or t is None:
            raise ValueError("R and t (the rig: the right camera's pose relative to the left) are required")
        R, t = _pose(R, t)
        self._tracker = _ext._StereoTracker(_camera(K_left, "K_left").tobytes(), _distortion(dist_left),
                                            _camera(K_right, "K_right").tobytes(), _distortion(dist_right),
                                            R.tobytes(), t.tobytes(), options)

    def track(self, left_features: FeaturesLike, right_features: FeaturesLike, R: Any = None,
              t: Any = None) -> FrameResult:
        """The next frame from the features of its left and right images (Features, or dicts with
        the same keys such as tripose.images.extract_features returns; None for an image that could
        not be read, whose frame is then lost unless the other image's features carry it through).
        R, t: the left camera's pose when known."""
        left = _features(left_features, "left_features")
        right = _features(right_features, "right_features")
        R, t = _pose(R, t)
        return self._tracker.add_frame(*_feature_bytes(left), *_feature_bytes(right), *_pose_bytes(R, t))

    def track_observations(self, points: Any, point_ids: Any, right_points: Any, segments: Any = None,
                           line_ids: Any = None, right_segments: Any = None, R: Any = None,
                           t: Any = None) -> FrameResult:
        """The next frame from observations of tracks the caller linked (a video's points followed
        by optical flow): the left image's points (N, 2) with point_ids (N integers) and
        right_points (N, 2), each point's position in the right image (a NaN row where the right
        camera does not see it); segments (M, 4) with line_ids and right_segments (M, 4, the same
        line's end points in the right image, any pair; NaN rows for none). An id names the same
        feature in every frame. No descriptors, so no place is recognised: a tracker fed this way
        restarts after a long loss without joining its maps. A tracker takes either features
        (track) or observations."""
        points = _rows(points, "points", 2)
        segments = _rows(segments, "segments", 4)
        right_points = _rows(right_points, "right_points", 2)
        right_segments = _rows(right_segments, "right_segments", 4)
        ids = _ids(point_ids, line_ids, len(points), len(segments))
        for rows, name, n in ((right_points, "right_points", len(points)),
                              (right_segments, "right_segments", len(segments))):
            if len(rows) != n:
                raise ValueError(f"{name} must hold one row per left feature (NaN: not seen): {len(rows)} rows "
                                 f"for {n}")
        R, t = _pose(R, t)
        return self._tracker.add_observations(points.tobytes(), ids[0].tolist(), right_points.tobytes(),
                                              segments.tobytes(), ids[1].tolist(), right_segments.tobytes(),
                                              *_pose_bytes(R, t))

    @property
    def num_frames(self) -> int:
        """Frames given so far."""
        return self._tracker.num_frames

    def pose(self, frame: int) -> Optional[Tuple[np.ndarray, np.ndarray]]:
        """The (R, t) of frame `frame`'s left camera; None when the frame is lost."""
        return self._tracker.pose(int(frame))

    def map_of(self, frame: int) -> int:
        """The map frame `frame`'s pose is in now (FrameResult.map; maps joined since take the earlier
        map's index); -1 when the frame is lost."""
        return self._tracker.map_of(int(frame))

    def tracks(self, frame: int) -> Tuple[np.ndarray, np.ndarray]:
        """(point_tracks, line_tracks) of frame `frame`'s left image as they are now: the track of
        each of its points and segments, -1 for none."""
        return self._tracker.tracks(int(frame))

    def stereo_matches(self, frame: int) -> Tuple[np.ndarray, np.ndarray]:
        """(point_rows, segment_rows) of frame `frame`: per point and segment of the left image, the
        row of its match in the right image, -1 for none."""
        return self._tracker.stereo_matches(int(frame))

    def trajectory(self):
        """Every frame's left-camera pose, in order: a list of (R, t), None for a lost frame."""
        return [self._tracker.pose(k) for k in range(self.num_frames)]

    @property
    def options(self) -> TrackerOptions:
        return self._tracker.options

    @property
    def rig(self) -> Tuple[np.ndarray, np.ndarray]:
        """(R, t): the right camera's pose relative to the left, R made an exact rotation."""
        return self._tracker.rig
