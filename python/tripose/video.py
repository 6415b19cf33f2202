"""Real-time tracking of a video: tripose.Tracker fed with points followed from frame to frame.

VideoTracker(K, dist, options) takes one image per call of track(). Instead of detecting and
matching features in every frame (tripose.images.extract_features and Tracker.track, the full mode),
it follows its points with pyramidal Lucas-Kanade optical flow (cv2.calcOpticalFlowPyrLK, kept only
when the flow back from the new frame returns within options.max_flow_error px of where the point
was), each point keeping its id, and gives them to tripose.Tracker.track_observations. New points
(cv2.goodFeaturesToTrack, options.min_distance px away from those followed) get new ids in the frame
after a keyframe (FrameResult.keyframe: the tracker decides it only once it has the frame's
observations) and whenever fewer than options.min_points survive. With options.segments, EDLines
segments are detected in those frames too and followed by the same flow at their two end points; a
segment is dropped when an end is lost or its length changes by more than options.max_length_change.

The first two frames need their poses (R, t; x_cam = R X + t), as for tripose.Tracker. Each call
returns a VideoFrame: the tracker's FrameResult and the milliseconds of each stage.

It needs OpenCV (pip install tripose[images]); the module imports it when a tracker is first built.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any, Dict, Optional

import numpy as np

from .tracking import FrameResult, StereoTracker, Tracker, TrackerOptions

__all__ = ["VideoOptions", "VideoFrame", "VideoTracker", "StereoVideoTracker", "video_tracker_options"]

# A video's frames are close: keyframes are spaced by this parallax (deg) instead of the full mode's
# 0.1 (a keyframe at nearly every frame, each triangulating from the narrow baselines of the last).
VIDEO_KEYFRAME_PARALLAX_DEG = 0.5

# The stages a VideoFrame times, in the order they run (a stereo rig's adds the right image's).
STAGES = ("flow", "detection", "registration")
STEREO_STAGES = ("flow", "detection", "stereo", "registration")

# A point found in the right image farther than this (px) from its epipolar line is not the left
# point: the flow slid along an edge or onto a repeated texture.
EPIPOLAR_TOLERANCE_PX = 2.0


def video_tracker_options() -> TrackerOptions:
    """The TrackerOptions a VideoTracker uses unless given others: the defaults, with keyframes
    spaced by VIDEO_KEYFRAME_PARALLAX_DEG and the local adjustment on (the window's frames and
    structure refined after each registration): followed points are seen from a few close keyframes
    only, and without it the structure and the poses drift together, every feature agreeing."""
    options = TrackerOptions()
    options.keyframe_parallax_deg = VIDEO_KEYFRAME_PARALLAX_DEG
    options.local_adjustment = True
    return options


@dataclass
class VideoOptions:
    """How a VideoTracker follows and renews its features.

    max_points: points followed at most; detection tops the followed ones up to it.
    min_points: fewer followed points than this start a detection in the next frame.
    min_distance: px between detected points, and from a new point to any followed one.
    quality_level: goodFeaturesToTrack's corner quality, relative to the frame's strongest corner.
    window_size: the Lucas-Kanade window's side (px, odd).
    pyramid_levels: pyramid levels above the image the flow is searched in (0: the image only).
    max_flow_error: px between a point and its position tracked forward and back; farther: lost.
    segments: detect EDLines segments where points are detected and follow their end points.
    max_segments: the longest segments kept at a detection.
    min_segment_length: shorter segments are neither detected nor kept (px).
    max_length_change: a segment whose length changes by more than this fraction is dropped.
    tracker: the TrackerOptions of the tracker the observations go to (video_tracker_options()).
    """
    max_points: int = 200
    min_points: int = 120
    min_distance: float = 10.0
    quality_level: float = 0.01
    window_size: int = 15
    pyramid_levels: int = 3
    max_flow_error: float = 1.0
    segments: bool = False
    max_segments: int = 100
    min_segment_length: float = 30.0
    max_length_change: float = 0.2
    tracker: TrackerOptions = field(default_factory=video_tracker_options)

    def check(self):
        """Raises ValueError (TypeError for a wrong type) naming the first option out of range."""
        for name, minimum in (("max_points", 1), ("min_points", 0), ("window_size", 3), ("pyramid_levels", 0),
                              ("max_segments", 0)):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
                raise TypeError(f"{name}: expected a whole number, got {value!r}")
            if value < minimum:
                raise ValueError(f"{name}: expected a whole number >= {minimum}, got {value}")
        if self.window_size % 2 == 0:
            raise ValueError(f"window_size: expected an odd number of px, got {self.window_size}")
        if self.min_points > self.max_points:
            raise ValueError(f"min_points: expected at most max_points ({self.max_points}), got {self.min_points}")
        for name in ("min_distance", "quality_level", "max_flow_error", "min_segment_length", "max_length_change"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
                raise TypeError(f"{name}: expected a number, got {value!r}")
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name}: expected a finite number > 0, got {value!r}")
        if self.quality_level >= 1:
            raise ValueError(f"quality_level: expected a fraction below 1, got {self.quality_level!r}")
        if not isinstance(self.segments, (bool, np.bool_)):
            raise TypeError(f"segments: expected True or False, got {self.segments!r}")
        if not isinstance(self.tracker, TrackerOptions):
            raise TypeError(f"tracker: expected a tripose.TrackerOptions, got {type(self.tracker).__name__}")


@dataclass
class VideoFrame:
    """One frame's outcome: result, the tracker's FrameResult (status, R, t, keyframe, ...);
    milliseconds per stage (flow: following the points and segments from the frame before;
    detection: new points and segments; registration: the tracker) and their total; points and
    segments: how many the frame gave the tracker; detected: whether new ones were looked for in it."""
    result: FrameResult
    milliseconds: Dict[str, float]
    points: int
    segments: int
    detected: bool


def _cv2():
    from .images import _cv2 as images_cv2
    return images_cv2()


class VideoTracker:
    """A monocular video tracked in real time: points (and optionally segments) followed by optical
    flow and given to a tripose.Tracker as linked observations (module docstring).

    VideoTracker(K, dist=None, options=None): K the (3, 3) camera matrix, dist OpenCV's distortion
    coefficients (the tracker undistorts the followed positions), options a VideoOptions.
    Bad input raises ValueError or TypeError naming the argument.
    """

    def __init__(self, K: Any, dist: Any = None, options: Optional[VideoOptions] = None):
        options = self._start(options)
        self._tracker = Tracker(K, dist, options.tracker)

    def _start(self, options: Optional[VideoOptions]) -> VideoOptions:
        """The checked options, OpenCV, and no feature followed yet."""
        if options is None:
            options = VideoOptions()
        if not isinstance(options, VideoOptions):
            raise TypeError(f"options: expected a tripose.video.VideoOptions, got {type(options).__name__}")
        options.check()
        self._cv2 = _cv2()
        self._options = options
        self._previous: Optional[np.ndarray] = None
        self._points = np.zeros((0, 2), np.float32)
        self._point_ids = np.zeros(0, np.int64)
        self._segments = np.zeros((0, 4), np.float32)
        self._line_ids = np.zeros(0, np.int64)
        self._next_id = 0
        self._renew = True
        cv2 = self._cv2
        self._flow_arguments = dict(winSize=(options.window_size, options.window_size), maxLevel=options.pyramid_levels,
                                    criteria=(cv2.TERM_CRITERIA_EPS | cv2.TERM_CRITERIA_COUNT, 30, 0.01))
        return options

    @property
    def options(self) -> VideoOptions:
        return self._options

    @property
    def tracker(self) -> Tracker:
        """The tripose.Tracker the observations go to (its pose(), tracks(), trajectory())."""
        return self._tracker

    @property
    def num_frames(self) -> int:
        return self._tracker.num_frames

    def trajectory(self):
        """Every frame's current pose, in order: a list of (R, t), None for a lost frame."""
        return self._tracker.trajectory()

    def _grey(self, image: Any, name: str = "image") -> Optional[np.ndarray]:
        if image is None:
            return None
        a = np.asarray(image)
        if a.dtype != np.uint8:
            raise TypeError(f"{name}: expected 8-bit pixels (uint8), got {a.dtype}")
        if a.ndim == 3 and a.shape[2] in (3, 4):
            a = self._cv2.cvtColor(a, self._cv2.COLOR_BGR2GRAY if a.shape[2] == 3 else self._cv2.COLOR_BGRA2GRAY)
        elif a.ndim == 3 and a.shape[2] == 1:
            a = a[:, :, 0]
        if a.ndim != 2 or min(a.shape) < 2:
            raise ValueError(f"{name}: expected a grey (H, W) or colour (H, W, 3) image, got shape {np.shape(image)}")
        if self._previous is not None and a.shape != self._previous.shape:
            raise ValueError(f"{name}: shape {a.shape} differs from the frames before ({self._previous.shape})")
        return np.ascontiguousarray(a)

    def _follow(self, grey: np.ndarray):
        """Points and segment ends moved from the frame before into grey; the lost ones dropped."""
        cv2, o = self._cv2, self._options
        ends = self._segments.reshape(-1, 2)
        start = np.vstack([self._points, ends]).astype(np.float32)
        if len(start) == 0:
            return
        moved, found, _ = cv2.calcOpticalFlowPyrLK(self._previous, grey, start.reshape(-1, 1, 2), None,
                                                   **self._flow_arguments)
        back, returned, _ = cv2.calcOpticalFlowPyrLK(grey, self._previous, moved, None, **self._flow_arguments)
        moved = moved.reshape(-1, 2)
        h, w = grey.shape
        kept = ((found.ravel() == 1) & (returned.ravel() == 1)
                & (np.linalg.norm(back.reshape(-1, 2) - start, axis=1) <= o.max_flow_error)
                & (moved[:, 0] >= 0) & (moved[:, 1] >= 0) & (moved[:, 0] <= w - 1) & (moved[:, 1] <= h - 1))
        n = len(self._points)
        self._points, self._point_ids = moved[:n][kept[:n]], self._point_ids[kept[:n]]
        if len(self._segments):
            segments = moved[n:].reshape(-1, 4)
            both = kept[n:].reshape(-1, 2).all(axis=1)
            before = np.hypot(*(self._segments[:, 2:] - self._segments[:, :2]).T)
            after = np.hypot(*(segments[:, 2:] - segments[:, :2]).T)
            steady = np.abs(after - before) <= o.max_length_change * before
            keep = both & steady & (after >= o.min_segment_length)
            self._segments, self._line_ids = segments[keep], self._line_ids[keep]

    def _new_ids(self, n: int) -> np.ndarray:
        ids = np.arange(self._next_id, self._next_id + n, dtype=np.int64)
        self._next_id += n
        return ids

    def _detect(self, grey: np.ndarray):
        """New points away from the followed ones up to options.max_points, and with options.segments
        new segments up to options.max_segments, each with a new id."""
        cv2, o = self._cv2, self._options
        wanted = o.max_points - len(self._points)
        if wanted > 0:
            mask = np.full(grey.shape, 255, np.uint8)
            radius = int(math.ceil(o.min_distance))
            for x, y in self._points:
                cv2.circle(mask, (int(round(x)), int(round(y))), radius, 0, -1)
            corners = cv2.goodFeaturesToTrack(grey, wanted, o.quality_level, o.min_distance, mask=mask)
            if corners is not None:
                corners = corners.reshape(-1, 2).astype(np.float32)
                self._points = np.vstack([self._points, corners])
                self._point_ids = np.concatenate([self._point_ids, self._new_ids(len(corners))])
        wanted = o.max_segments - len(self._segments)
        if o.segments and wanted > 0:
            detector = cv2.ximgproc.createEdgeDrawing()
            detector.detectEdges(grey)
            found = detector.detectLines()
            if found is not None:
                found = found.reshape(-1, 4).astype(np.float32)
                length = np.hypot(found[:, 2] - found[:, 0], found[:, 3] - found[:, 1])
                order = np.argsort(-length)
                order = order[length[order] >= o.min_segment_length]
                found = found[order]
                if len(self._segments):
                    # A segment already followed is not taken twice: new ones must lie off the followed
                    # ones' lines or away from them.
                    found = found[~_near_followed(found, self._segments, o.min_distance)]
                found = found[:wanted]
                self._segments = np.vstack([self._segments, found])
                self._line_ids = np.concatenate([self._line_ids, self._new_ids(len(found))])

    def _advance(self, grey: Optional[np.ndarray], times: Dict[str, float]) -> bool:
        """The followed features moved into grey (None: all dropped), topped up by a detection when
        due; times gets the flow's and the detection's milliseconds. True when it detected."""
        clock = time.perf_counter()
        detected = False
        if grey is None:
            return detected  # the features are followed on from the last image read
        if self._previous is not None:
            self._follow(grey)
        now = time.perf_counter()
        times["flow"], clock = 1e3 * (now - clock), now
        detected = self._renew or len(self._points) < self._options.min_points
        if detected:
            self._detect(grey)
        times["detection"] = 1e3 * (time.perf_counter() - clock)
        self._previous = grey
        return detected

    def _finish(self, result: FrameResult, unread: bool, times: Dict[str, float], detected: bool) -> VideoFrame:
        times["total"] = sum(times.values())
        # The tracker tells a keyframe only once it has the frame: the next frame is detected afresh.
        self._renew = self._renew if unread else bool(result.keyframe)
        if unread:
            return VideoFrame(result, times, 0, 0, detected)
        return VideoFrame(result, times, len(self._points), len(self._segments), detected)

    def _given(self, grey: Optional[np.ndarray]):
        """The points, their ids, the segments and their ids a frame gives the tracker: none for an
        image not read."""
        if grey is None:
            return np.zeros((0, 2)), np.zeros(0, np.int64), np.zeros((0, 4)), np.zeros(0, np.int64)
        return (self._points.astype(np.float64), self._point_ids, self._segments.astype(np.float64),
                self._line_ids)

    def track(self, image: Any, R: Any = None, t: Any = None) -> VideoFrame:
        """The next frame: an 8-bit grey or colour (BGR) image, None for a frame that could not be
        read (it is lost, and the points followed before it are followed on into the next image).
        R, t: the frame's pose when known (needed for the first two frames)."""
        times = dict.fromkeys(STAGES, 0.0)
        grey = self._grey(image)
        detected = self._advance(grey, times)
        clock = time.perf_counter()
        result = self._tracker.track_observations(*self._given(grey), R, t)
        times["registration"] = 1e3 * (time.perf_counter() - clock)
        return self._finish(result, grey is None, times, detected)


class StereoVideoTracker(VideoTracker):
    """A stereo rig's video tracked in real time: the left camera's points (and optionally
    segments) followed by optical flow as VideoTracker follows them, each found in the right image
    by the same flow from the left image (kept when the flow back returns within
    options.max_flow_error px and the point lies within 2 px of its epipolar line), and given with
    their ids to a tripose.StereoTracker as observations. No pose is needed; the rig's baseline
    gives the scale.

    StereoVideoTracker(K_left, K_right, R, t, dist_left=None, dist_right=None, options=None): the
    cameras' matrices, the rig (the right camera's pose relative to the left: x_right = R @ x_left
    + t, t non-zero) and each camera's distortion coefficients, as tripose.StereoTracker takes
    them; options a VideoOptions (its tracker options go to the StereoTracker). Each call of
    track(left, right) returns a VideoFrame whose milliseconds add a "stereo" stage. Bad input
    raises ValueError or TypeError naming the argument.
    """

    def __init__(self, K_left: Any, K_right: Any, R: Any, t: Any, dist_left: Any = None, dist_right: Any = None,
                 options: Optional[VideoOptions] = None):
        options = self._start(options)
        self._tracker = StereoTracker(K_left, K_right, R, t, dist_left, dist_right, options.tracker)
        rig_R, rig_t = self._tracker.rig
        self._K = (np.asarray(K_left, np.float64), np.asarray(K_right, np.float64))
        self._dist = tuple(None if d is None else np.asarray(d, np.float64).reshape(-1) for d in (dist_left, dist_right))
        tx = np.array([[0, -rig_t[2], rig_t[1]], [rig_t[2], 0, -rig_t[0]], [-rig_t[1], rig_t[0], 0]])
        self._F = np.linalg.inv(self._K[1]).T @ tx @ rig_R @ np.linalg.inv(self._K[0])

    @property
    def tracker(self) -> StereoTracker:
        """The tripose.StereoTracker the observations go to (its pose(), map_of(), trajectory())."""
        return self._tracker

    def _undistorted(self, pixels: np.ndarray, camera: int) -> np.ndarray:
        if self._dist[camera] is None or not np.any(self._dist[camera]):
            return pixels.astype(np.float64)
        return self._cv2.undistortPoints(pixels.reshape(-1, 1, 2).astype(np.float64), self._K[camera],
                                         self._dist[camera], P=self._K[camera]).reshape(-1, 2)

    def _in_right(self, grey: np.ndarray, right: np.ndarray, pixels: np.ndarray) -> np.ndarray:
        """Each left pixel's position in the right image by the flow there and back; NaN where it
        is not found, does not come back, or lies off its epipolar line."""
        cv2, o = self._cv2, self._options
        out = np.full((len(pixels), 2), np.nan)
        if len(pixels) == 0:
            return out
        start = pixels.astype(np.float32).reshape(-1, 1, 2)
        moved, found, _ = cv2.calcOpticalFlowPyrLK(grey, right, start, None, **self._flow_arguments)
        back, returned, _ = cv2.calcOpticalFlowPyrLK(right, grey, moved, None, **self._flow_arguments)
        moved, start = moved.reshape(-1, 2), start.reshape(-1, 2)
        h, w = right.shape
        kept = ((found.ravel() == 1) & (returned.ravel() == 1)
                & (np.linalg.norm(back.reshape(-1, 2) - start, axis=1) <= o.max_flow_error)
                & (moved[:, 0] >= 0) & (moved[:, 1] >= 0) & (moved[:, 0] <= w - 1) & (moved[:, 1] <= h - 1))
        left_h = np.hstack([self._undistorted(start, 0), np.ones((len(start), 1))])
        right_h = np.hstack([self._undistorted(moved, 1), np.ones((len(moved), 1))])
        lines = left_h @ self._F.T
        distance = np.abs(np.sum(lines * right_h, axis=1)) / np.maximum(np.hypot(lines[:, 0], lines[:, 1]), 1e-12)
        kept &= distance <= EPIPOLAR_TOLERANCE_PX
        out[kept] = moved[kept]
        return out

    def track(self, left: Any, right: Any, R: Any = None, t: Any = None) -> VideoFrame:
        """The next stereo frame: the left and right 8-bit images (grey or BGR, the same size), None
        for an image that could not be read: without the left one the frame is lost and the points
        are followed on into the next image; without the right one they are registered as the left
        camera sees them. R, t: the left camera's pose when known."""
        times = dict.fromkeys(STEREO_STAGES, 0.0)
        grey = self._grey(left, "left")
        right_grey = self._grey(right, "right")
        if grey is not None and right_grey is not None and right_grey.shape != grey.shape:
            raise ValueError(f"right: shape {right_grey.shape} differs from the left image's ({grey.shape})")
        detected = self._advance(grey, times)
        clock = time.perf_counter()
        points, point_ids, segments, line_ids = self._given(grey)
        # Without the right image the frame's points are seen by the left camera only.
        right_points = np.full((len(points), 2), np.nan)
        right_segments = np.full((len(segments), 4), np.nan)
        if grey is not None and right_grey is not None:
            right_points = self._in_right(grey, right_grey, self._points)
            right_segments = self._in_right(grey, right_grey, self._segments.reshape(-1, 2)).reshape(-1, 4)
        times["stereo"] = 1e3 * (time.perf_counter() - clock)
        clock = time.perf_counter()
        result = self._tracker.track_observations(points, point_ids, right_points, segments, line_ids,
                                                  right_segments, R, t)
        times["registration"] = 1e3 * (time.perf_counter() - clock)
        return self._finish(result, grey is None, times, detected)


def _near_followed(candidates: np.ndarray, followed: np.ndarray, distance: float) -> np.ndarray:
    """Per candidate segment, whether its midpoint lies within distance px of a followed segment's
    line and between that segment's ends (the same edge seen again)."""
    mid = 0.5 * (candidates[:, :2] + candidates[:, 2:])
    a, b = followed[:, :2], followed[:, 2:]
    direction = b - a
    length = np.maximum(np.hypot(direction[:, 0], direction[:, 1]), 1e-9)
    unit = direction / length[:, None]
    rel = mid[:, None, :] - a[None, :, :]
    along = rel[..., 0] * unit[None, :, 0] + rel[..., 1] * unit[None, :, 1]
    across = np.abs(rel[..., 0] * unit[None, :, 1] - rel[..., 1] * unit[None, :, 0])
    return ((across <= distance) & (along >= 0) & (along <= length[None, :])).any(axis=1)
