"""Synthetic scenes for the package's tests, in numpy only: a random camera matrix, cameras of known
pose, 3D points and segments in front of every camera, and their pixel observations.

Poses follow the package's convention x_cam = R @ X + t. Three-view scenes are expressed in the
frame of view 1 (view 1 at [I|0]); multi-view scenes in a world frame.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np

IMAGE_SIZE = (640, 480)


def random_rotation(rng: np.random.Generator, max_angle: float) -> np.ndarray:
    """A rotation about a uniformly random axis by an angle uniform in [0, max_angle] (rad)."""
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    return rodrigues(axis * rng.uniform(0.0, max_angle))


def rodrigues(w: np.ndarray) -> np.ndarray:
    angle = float(np.linalg.norm(w))
    if angle == 0.0:
        return np.eye(3)
    k = np.asarray(w, dtype=np.float64) / angle
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1.0 - np.cos(angle)) * (Kx @ Kx)


def random_camera_matrix(rng: np.random.Generator) -> np.ndarray:
    f = rng.uniform(500.0, 1000.0)
    return np.array([[f, 0.0, IMAGE_SIZE[0] / 2 + rng.uniform(-20, 20)],
                     [0.0, f * rng.uniform(0.98, 1.02), IMAGE_SIZE[1] / 2 + rng.uniform(-20, 20)],
                     [0.0, 0.0, 1.0]])


def look_at_pose(rng: np.random.Generator, centre: np.ndarray, target: np.ndarray) -> tuple:
    """A pose whose optical axis points from centre to target, with a random roll of up to 0.3 rad."""
    z = target - centre
    z /= np.linalg.norm(z)
    up = np.array([0.0, 1.0, 0.0])
    x = np.cross(up, z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    R = np.vstack([x, y, z])
    roll = rodrigues(np.array([0.0, 0.0, rng.uniform(-0.3, 0.3)]))
    R = roll @ R
    return R, -R @ centre


def project(K: np.ndarray, R: np.ndarray, t: np.ndarray, X: np.ndarray) -> np.ndarray:
    x = (K @ (X @ R.T + t).T).T
    return x[:, :2] / x[:, 2:3]


def depths(R: np.ndarray, t: np.ndarray, X: np.ndarray) -> np.ndarray:
    return (X @ R.T + t)[:, 2]


def rotation_error(A: np.ndarray, B: np.ndarray) -> float:
    """Angle (rad) of A B^T, accurate near zero."""
    d = np.linalg.norm(np.asarray(A) - np.asarray(B)) / (2.0 * np.sqrt(2.0))
    return float(2.0 * np.arcsin(min(1.0, d)))


def translation_error(a: np.ndarray, b: np.ndarray) -> float:
    """|a - b| / |b|."""
    return float(np.linalg.norm(np.ravel(a) - np.ravel(b)) / np.linalg.norm(np.ravel(b)))


def pose_close(R: np.ndarray, t: np.ndarray, R_true: np.ndarray, t_true: np.ndarray, tol: float = 1e-6) -> bool:
    return rotation_error(R, R_true) < tol and translation_error(t, t_true) < tol


@dataclass
class Structure:
    points3d: np.ndarray          # (N, 3)
    lines3d: np.ndarray           # (M, 6): two 3D points of each line


def plane_angle(A: np.ndarray, B: np.ndarray, pose1: tuple, pose2: tuple) -> float:
    """Angle (rad, in [0, pi/2]) between the planes through the 3D line AB and the centres of two poses."""
    normals = []
    for R, t in pose1, pose2:
        C = -R.T @ t
        n = np.cross(A - C, B - C)
        normals.append(n / np.linalg.norm(n))
    return float(np.arccos(min(1.0, abs(normals[0] @ normals[1]))))


def random_structure(rng: np.random.Generator, num_points: int, num_lines: int, poses: list,
                     K: np.ndarray, min_line_plane_angle: float = 0.0) -> Structure:
    """Points and segments in a box 4-10 units in front of the origin, kept only where every pose in
    poses sees them at a depth above 0.5 and inside the image (with a margin of half an image).
    min_line_plane_angle > 0 also drops lines whose planes through the centres of two of the known
    poses (all but the last) meet at a smaller angle: such a line, nearly in an epipolar plane of
    those two views, is barely fixed by them, and a wrong observation of it in the new view can
    look right."""
    def visible(X):
        for R, t in poses:
            if np.any(depths(R, t, X) < 0.5):
                return False
            x = project(K, R, t, X)
            w, h = IMAGE_SIZE
            if np.any(x[:, 0] < -w / 2) or np.any(x[:, 0] > 1.5 * w) or np.any(x[:, 1] < -h / 2) or \
                    np.any(x[:, 1] > 1.5 * h):
                return False
        return True

    def sample_point():
        return np.array([rng.uniform(-2.5, 2.5), rng.uniform(-2.0, 2.0), rng.uniform(4.0, 10.0)])

    points = []
    while len(points) < num_points:
        X = sample_point()
        if visible(X[None]):
            points.append(X)
    lines = []
    while len(lines) < num_lines:
        A = sample_point()
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        B = A + rng.uniform(1.0, 3.0) * direction
        known = poses[:-1]
        if visible(np.vstack([A, B])) and all(plane_angle(A, B, known[i], known[j]) >= min_line_plane_angle
                                              for i in range(len(known)) for j in range(i)):
            lines.append(np.concatenate([A, B]))
    return Structure(np.array(points).reshape(-1, 3), np.array(lines).reshape(-1, 6))


def observe(K: np.ndarray, R: np.ndarray, t: np.ndarray, structure: Structure, rng: np.random.Generator):
    """Pixels of the points (N, 2) and segments (M, 4) in the view (R, t). Each view sees its own
    stretch of each 3D line (different end points per view), as a detector would."""
    points = project(K, R, t, structure.points3d)
    ends = []
    for L in structure.lines3d:
        A, B = L[:3], L[3:]
        s0, s1 = rng.uniform(-0.1, 0.3), rng.uniform(0.7, 1.1)
        ends.append(np.vstack([A + s0 * (B - A), A + s1 * (B - A)]))
    ends3d = np.array(ends).reshape(-1, 3)
    segments = project(K, R, t, ends3d).reshape(-1, 4) if len(ends3d) else np.zeros((0, 4))
    return points, segments, ends3d.reshape(-1, 6)


@dataclass
class ThreeViewScene:
    K: np.ndarray
    R12: np.ndarray
    t12: np.ndarray
    R: np.ndarray                 # true pose of view 3
    t: np.ndarray
    points: List[np.ndarray]      # per view, (N, 2)
    lines: List[np.ndarray]       # per view, (M, 4)
    structure: Structure
    line_ends3d: List[np.ndarray] = field(default_factory=list)  # per view, (M, 6): the observed stretch

    def args(self):
        """Positional arguments of estimate_pose_line_point up to t12."""
        return (*self.points, *self.lines, self.K, self.R12, self.t12)


def _orbit_pose(rng: np.random.Generator, radius: float) -> tuple:
    """A camera near the origin (view 1) looking at the centre of the structure box."""
    centre = rng.normal(size=3)
    centre *= radius * rng.uniform(0.5, 1.0) / np.linalg.norm(centre)
    target = np.array([rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 7.0])
    return look_at_pose(rng, centre, target)


def three_view_scene(seed: int, num_points: int, num_lines: int,
                     min_line_plane_angle: float = 0.0) -> ThreeViewScene:
    rng = np.random.default_rng(seed)
    K = random_camera_matrix(rng)
    R12, t12 = _orbit_pose(rng, 1.5)
    R, t = _orbit_pose(rng, 2.0)
    poses = [(np.eye(3), np.zeros(3)), (R12, t12), (R, t)]
    structure = random_structure(rng, num_points, num_lines, poses, K, min_line_plane_angle)
    points, lines, ends = [], [], []
    for Rk, tk in poses:
        p, l, e = observe(K, Rk, tk, structure, rng)
        points.append(p)
        lines.append(l)
        ends.append(e)
    return ThreeViewScene(K, R12, t12, R, t, points, lines, structure, ends)


@dataclass
class StereoScene:
    K: np.ndarray
    R12: np.ndarray               # the rig: right camera relative to the left one
    t12: np.ndarray
    R: np.ndarray                 # true pose of the left camera at time B
    t: np.ndarray
    points: List[np.ndarray]      # views 1-4; NaN rows in views 3 / 4 where unseen
    lines: List[np.ndarray]

    def args(self):
        return (*self.points, *self.lines, self.K, self.R12, self.t12)


def stereo_scene(seed: int, num_points: int, num_lines: int, missing: float = 0.3) -> StereoScene:
    """A rig with a 0.3-0.6 baseline; each feature is unseen by view 3 or by view 4 with probability
    missing (never by both)."""
    rng = np.random.default_rng(seed)
    K = random_camera_matrix(rng)
    baseline = rng.uniform(0.3, 0.6)
    R12 = random_rotation(rng, 0.05)
    t12 = -R12 @ np.array([baseline, rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02)])
    R, t = _orbit_pose(rng, 1.5)
    poses = [(np.eye(3), np.zeros(3)), (R12, t12), (R, t), (R12 @ R, R12 @ t + t12)]
    structure = random_structure(rng, num_points, num_lines, poses, K)
    points, lines = [], []
    for Rk, tk in poses:
        p, l, _ = observe(K, Rk, tk, structure, rng)
        points.append(p)
        lines.append(l)
    for observations in (points, lines):
        for i in range(len(observations[2])):
            if rng.uniform() < missing:
                observations[2 + int(rng.integers(2))][i] = np.nan
    return StereoScene(K, R12, t12, R, t, points, lines)


@dataclass
class MultiViewScene:
    K: np.ndarray
    Rs: List[np.ndarray]          # world poses of the known views
    ts: List[np.ndarray]
    R: np.ndarray                 # true world pose of the new view
    t: np.ndarray
    points: List[np.ndarray]      # known views, then the new view; NaN rows where unseen
    lines: List[np.ndarray]


def multiview_scene(seed: int, num_points: int, num_lines: int, num_known: int = 3,
                    missing: float = 0.3, min_line_plane_angle: float = 0.0) -> MultiViewScene:
    """num_known known views and a new one in a world frame (not that of any view); each feature is
    unseen by one known view with probability missing, as long as two known views still see it."""
    rng = np.random.default_rng(seed)
    K = random_camera_matrix(rng)
    # World frame: a random rigid motion away from the frame the structure is sampled in.
    Rw, tw = random_rotation(rng, np.pi), rng.normal(size=3)
    poses = [_orbit_pose(rng, 1.5) for _ in range(num_known + 1)]
    structure = random_structure(rng, num_points, num_lines, poses, K, min_line_plane_angle)
    # A pose (R, t) in the sampling frame is (R Rw^T, t - R Rw^T tw) in the world frame X_w = Rw X + tw.
    world = [(R @ Rw.T, t - R @ Rw.T @ tw) for R, t in poses]
    points, lines = [], []
    for R, t in poses:
        p, l, _ = observe(K, R, t, structure, rng)
        points.append(p)
        lines.append(l)
    if num_known > 2:
        for observations in (points, lines):
            for i in range(len(observations[0])):
                if rng.uniform() < missing:
                    observations[int(rng.integers(num_known))][i] = np.nan
    Rs = [R for R, _ in world[:num_known]]
    ts = [t for _, t in world[:num_known]]
    return MultiViewScene(K, Rs, ts, world[-1][0], world[-1][1], points, lines)


def perturb_pose(rng: np.random.Generator, R: np.ndarray, t: np.ndarray, angle: float = np.deg2rad(2.0),
                 relative_shift: float = 0.05) -> tuple:
    """(R, t) rotated by angle about a random axis and t moved by relative_shift * |t|."""
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    shift = rng.normal(size=3)
    shift *= relative_shift * np.linalg.norm(t) / np.linalg.norm(shift)
    return rodrigues(axis * angle) @ R, t + shift


def add_outliers(rng: np.random.Generator, points: np.ndarray, lines: np.ndarray, fraction: float,
                 shift_range=(30.0, 100.0)):
    """Copies of one view's observations where a fraction of the points and of the segments is
    moved by 30-100 px in a random direction (a segment: across its direction), far beyond any
    inlier threshold. Returns the copies and the true inlier masks."""
    points, lines = points.copy(), lines.copy()
    point_inliers = np.ones(len(points), bool)
    line_inliers = np.ones(len(lines), bool)
    for i in rng.choice(len(points), int(round(fraction * len(points))), replace=False):
        angle = rng.uniform(0, 2 * np.pi)
        points[i] += rng.uniform(*shift_range) * np.array([np.cos(angle), np.sin(angle)])
        point_inliers[i] = False
    for i in rng.choice(len(lines), int(round(fraction * len(lines))), replace=False):
        d = lines[i, 2:] - lines[i, :2]
        normal = np.array([-d[1], d[0]]) / np.linalg.norm(d)
        # Shifted across and turned a little.
        offset = rng.choice([-1, 1]) * rng.uniform(*shift_range) * normal
        lines[i, :2] += offset
        lines[i, 2:] += offset + rng.uniform(-0.03, 0.03) * np.linalg.norm(d) * normal
        line_inliers[i] = False
    return points, lines, point_inliers, line_inliers


def empty_or(array: np.ndarray) -> Optional[np.ndarray]:
    return array if array.size else None
