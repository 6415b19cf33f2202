"""tripose.StereoTracker on synthetic stereo sequences, with no pose given.

Points and segments of a 3D scene are projected into both cameras of a rig moving along a smooth
path, with 0.5 px noise; each 3D feature has a descriptor (float32 values, or uint8 bytes) and each
observation a little noise on it. Every frame must be registered at metric scale (the rig's
baseline); a frame of noise must be lost and the next ones registered; bad input must raise naming
the argument. The program tripose-track --right tracks a rendered rig sequence (a textured box room)
from its images.
"""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tripose

REGISTERED, GIVEN, LOST = tripose.FrameStatus.REGISTERED, tripose.FrameStatus.GIVEN, tripose.FrameStatus.LOST
WIDTH, HEIGHT = 640, 480
K = np.array([[600.0, 0, 320], [0, 600, 240], [0, 0, 1]])
NOISE_PX = 0.5


def rotation(w):
    w = np.asarray(w, dtype=np.float64)
    angle = np.linalg.norm(w)
    if angle == 0:
        return np.eye(3)
    k = w / angle
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx


class StereoSequence:
    """A rig (the right camera 0.3 m to the right, turned 0.6 deg) moving 4.5 m forward along a
    gentle S with a slight yaw and pitch, and a scene 6-22 m in front of its start."""

    def __init__(self, frames, seed, binary=False):
        rng = np.random.default_rng(seed)
        self.rng = rng
        self.binary = binary
        self.rig_R = rotation([0, 0.01, 0])
        self.rig_t = -self.rig_R @ np.array([0.3, 0, 0])
        self.poses = []
        for k in range(frames):
            s = k / (frames - 1)
            centre = np.array([0.6 * np.sin(2 * np.pi * s), 0.1 * np.sin(np.pi * s), 4.5 * s])
            R = rotation([0.03 * np.sin(np.pi * s), 0.12 * np.sin(2 * np.pi * s), 0.02 * s])
            self.poses.append((R, -R @ centre))
        centres = np.array([-R.T @ t for R, t in self.poses])
        self.path_length = float(np.sum(np.linalg.norm(np.diff(centres, axis=0), axis=1)))
        low, high = np.array([-8, -4, 6]), np.array([8, 4, 22])
        self.points = rng.uniform(low, high, (300, 3))
        starts = rng.uniform(low, high, (80, 3))
        directions = rng.normal(size=(80, 3)) * [1, 1, 0.3]
        directions *= (rng.uniform(0.8, 2.0, 80) / np.linalg.norm(directions, axis=1))[:, None]
        self.segments = np.hstack([starts, starts + directions])
        if binary:
            self.point_descriptors = rng.integers(0, 256, (300, 32), dtype=np.uint8)
            self.line_descriptors = rng.integers(0, 256, (80, 32), dtype=np.uint8)
        else:
            self.point_descriptors = rng.uniform(0, 1, (300, 128)).astype(np.float32)
            self.line_descriptors = rng.uniform(0, 1, (80, 128)).astype(np.float32)

    def right_pose(self, k):
        R, t = self.poses[k]
        return self.rig_R @ R, self.rig_R @ t + self.rig_t

    def _descriptors(self, rows):
        if self.binary:
            # A few flipped bits per observation.
            flips = np.zeros(rows.shape, np.uint8)
            for i in range(len(rows)):
                for bit in self.rng.choice(rows.shape[1] * 8, 6, replace=False):
                    flips[i, bit // 8] |= np.uint8(1 << (bit % 8))
            return rows ^ flips
        return (rows + self.rng.normal(0, 0.03, rows.shape)).astype(np.float32)

    def _project(self, R, t, X, dist=None):
        c = X @ R.T + t
        n = c[:, :2] / c[:, 2:3]
        if dist is not None:
            # OpenCV's model with k1, k2 (and p1, p2) only.
            k1, k2, p1, p2 = dist
            r2 = np.sum(n * n, axis=1, keepdims=True)
            x, y = n[:, :1], n[:, 1:]
            n = n * (1 + k1 * r2 + k2 * r2 * r2) + np.hstack([2 * p1 * x * y + p2 * (r2 + 2 * x * x),
                                                               p1 * (r2 + 2 * y * y) + 2 * p2 * x * y])
        x = n @ K[:2, :2].T + K[:2, 2] + self.rng.normal(0, NOISE_PX, (len(X), 2))
        visible = (c[:, 2] > 1) & (x[:, 0] >= 0) & (x[:, 0] < WIDTH) & (x[:, 1] >= 0) & (x[:, 1] < HEIGHT)
        return x, visible

    def observe(self, R, t, dist=None):
        """A tripose.Features of what a camera at (R, t) with distortion dist sees, rows shuffled."""
        x, seen = self._project(R, t, self.points, dist)
        a, seen_a = self._project(R, t, self.segments[:, :3], dist)
        b, seen_b = self._project(R, t, self.segments[:, 3:], dist)
        points = np.flatnonzero(seen)
        lines = np.flatnonzero(seen_a & seen_b)
        points, lines = self.rng.permutation(points), self.rng.permutation(lines)
        return tripose.Features(points=x[points], point_descriptors=self._descriptors(self.point_descriptors[points]),
                                segments=np.hstack([a[lines], b[lines]]),
                                line_descriptors=self._descriptors(self.line_descriptors[lines]))

    def frame(self, k, dist_left=None, dist_right=None):
        return self.observe(*self.poses[k], dist_left), self.observe(*self.right_pose(k), dist_right)


def noise_features(rng, binary=False, points=200, segments=40):
    descriptors = ((lambda n: rng.integers(0, 256, (n, 32), dtype=np.uint8)) if binary
                   else (lambda n: rng.uniform(0, 1, (n, 128)).astype(np.float32)))
    return tripose.Features(points=rng.uniform(0, HEIGHT, (points, 2)), point_descriptors=descriptors(points),
                            segments=rng.uniform(0, HEIGHT, (segments, 4)), line_descriptors=descriptors(segments))


def errors(pose, truth):
    """(rotation error in degrees, position error in metres)."""
    R, t = pose
    R_true, t_true = truth
    c = np.clip((np.trace(R @ R_true.T) - 1) / 2, -1, 1)
    return np.degrees(np.arccos(c)), float(np.linalg.norm(-R.T @ t + R_true.T @ t_true))


def make_tracker(seq, options=None):
    return tripose.StereoTracker(K, K, seq.rig_R, seq.rig_t, options=options)


# About four times the worst errors of 20-frame sequences of seeds 0-9, float and binary descriptors.
ROTATION_BOUND_DEG = 0.3
POSITION_BOUND = 0.015  # of the path's length


@pytest.mark.parametrize("binary", [False, True], ids=["float", "binary"])
def test_every_frame_registered_at_metric_scale(binary):
    seq = StereoSequence(20, seed=1, binary=binary)
    tracker = make_tracker(seq)
    worst = np.zeros(2)
    for k in range(20):
        result = tracker.track(*seq.frame(k))
        assert result.frame == k
        if k == 0:
            assert result.status == GIVEN
            np.testing.assert_array_equal(result.R, np.eye(3))
            np.testing.assert_array_equal(result.t, np.zeros(3))
            continue
        assert result.status == REGISTERED, f"frame {k}: {result.reason}"
        assert result.inliers >= tracker.options.min_inliers
        assert result.known_views == 1
        worst = np.maximum(worst, errors((result.R, result.t), seq.poses[k]))
    assert worst[0] < ROTATION_BOUND_DEG
    assert worst[1] < POSITION_BOUND * seq.path_length
    trajectory = tracker.trajectory()
    assert len(trajectory) == tracker.num_frames == 20
    assert all(p is not None for p in trajectory)
    point_rows, segment_rows = tracker.stereo_matches(5)
    assert (point_rows >= 0).sum() > 50 and (segment_rows >= 0).sum() > 5


def test_first_pose_given_places_the_world():
    seq = StereoSequence(8, seed=2)
    # The world moved so that frame 0's left camera is at (R0, t0): every pose follows it.
    R0, t0 = rotation([0.1, -0.2, 0.3]), np.array([1.0, -2.0, 0.5])
    tracker = make_tracker(seq)
    for k in range(8):
        result = tracker.track(*seq.frame(k), *((R0, t0) if k == 0 else (None, None)))
        assert result.status == (GIVEN if k == 0 else REGISTERED), result.reason
        R, t = seq.poses[k]
        truth = (R @ R0, R @ t0 + t)
        rotation_error, position_error = errors((result.R, result.t), truth)
        assert rotation_error < ROTATION_BOUND_DEG and position_error < POSITION_BOUND * seq.path_length


def test_frames_of_noise_are_lost_and_tracking_goes_on():
    """One frame of noise, then a run of more than max_frame_gap: both lost, every other frame
    registered."""
    seq = StereoSequence(18, seed=3)
    tracker = make_tracker(seq)
    rng = np.random.default_rng(4)
    noise = {4} | set(range(8, 8 + tracker.options.max_frame_gap + 2))
    for k in range(18):
        if k in noise:
            result = tracker.track(noise_features(rng), noise_features(rng))
            assert result.status == LOST and result.R is None and result.reason
            assert tracker.pose(k) is None
            continue
        result = tracker.track(*seq.frame(k))
        if k == 0:
            continue
        assert result.status == REGISTERED, f"frame {k}: {result.reason}"
        rotation_error, position_error = errors((result.R, result.t), seq.poses[k])
        assert rotation_error < ROTATION_BOUND_DEG and position_error < POSITION_BOUND * seq.path_length
    # An unreadable image pair (None) is lost too.
    assert tracker.track(None, None).status == LOST


def test_a_rig_turning_on_the_spot_keeps_registering():
    """Standing still adds no keyframe; turning 1.4 rad on the spot adds them as the view leaves
    the keyframe's, and every frame is registered."""
    seq = StereoSequence(2, seed=6)
    rng = np.random.default_rng(7)
    points = rng.uniform([-30, -4, -30], [30, 4, 30], (3000, 3))
    seq.points = points[np.linalg.norm(points[:, [0, 2]], axis=1) > 6]
    seq.point_descriptors = rng.uniform(0, 1, (len(seq.points), 128)).astype(np.float32)
    seq.segments = seq.segments[:0]
    seq.line_descriptors = seq.line_descriptors[:0]
    R0, t0 = seq.poses[0]
    seq.poses = [(R0, t0)] * 4 + [(rotation([0, 0.06 * j, 0]) @ R0, rotation([0, 0.06 * j, 0]) @ t0)
                                  for j in range(1, 25)]
    tracker = make_tracker(seq)
    keyframes = []
    for k in range(len(seq.poses)):
        result = tracker.track(*seq.frame(k))
        if k == 0:
            continue
        assert result.status == REGISTERED, f"frame {k}: {result.reason}"
        rotation_error, position_error = errors((result.R, result.t), seq.poses[k])
        assert rotation_error < ROTATION_BOUND_DEG and position_error < 0.05, f"frame {k}"
        if result.keyframe:
            keyframes.append(k)
    assert keyframes and min(keyframes) > 3


def test_each_camera_undistorted_with_its_own_coefficients():
    seq = StereoSequence(10, seed=8)
    dist_left, dist_right = [-0.25, 0.08, 0.001, -0.002], [0.15, -0.05, -0.001, 0.001]

    def worst(given_left, given_right):
        tracker = tripose.StereoTracker(K, K, seq.rig_R, seq.rig_t, given_left, given_right)
        out, lost = np.zeros(2), 0
        for k in range(10):
            result = tracker.track(*seq.frame(k, dist_left, dist_right))
            if result.status == LOST:
                lost += 1
            elif k > 0:
                out = np.maximum(out, errors((result.R, result.t), seq.poses[k]))
        return out, lost

    right, lost = worst(dist_left, dist_right)
    assert lost == 0
    assert right[0] < ROTATION_BOUND_DEG and right[1] < POSITION_BOUND * seq.path_length
    swapped, lost = worst(dist_right, dist_left)
    assert lost > 0 or swapped[1] > 3 * right[1]


def _raises(error, match, f):
    with pytest.raises(error, match=match):
        f()


def test_bad_input_raises_naming_the_argument():
    seq = StereoSequence(3, seed=5)
    R, t = seq.rig_R, seq.rig_t
    _raises(ValueError, r"\bt\b.*non-zero", lambda: tripose.StereoTracker(K, K, R, np.zeros(3)))
    _raises(ValueError, r"\bR\b.*not a rotation", lambda: tripose.StereoTracker(K, K, 2 * R, t))
    _raises(ValueError, "R and t", lambda: tripose.StereoTracker(K, K, None, t))
    _raises(ValueError, "K_left", lambda: tripose.StereoTracker(np.eye(2), K, R, t))
    _raises(ValueError, "K_right", lambda: tripose.StereoTracker(K, np.zeros((3, 3)), R, t))
    _raises(ValueError, "dist_right", lambda: tripose.StereoTracker(K, K, R, t, dist_right=[0.1, 0.2, 0.3]))
    options = tripose.TrackerOptions()
    options.min_inliers = 0
    _raises(ValueError, "options.min_inliers", lambda: tripose.StereoTracker(K, K, R, t, options=options))
    _raises(TypeError, "options", lambda: tripose.StereoTracker(K, K, R, t, options="fast"))

    tracker = make_tracker(seq)
    left, right = seq.frame(0)
    fewer = tripose.Features(right.points, right.point_descriptors[:-1], right.segments, right.line_descriptors)
    _raises(ValueError, "right_features.point_descriptors", lambda: tracker.track(left, fewer))
    binary = tripose.Features(right.points, np.zeros((len(right.points), 32), np.uint8), right.segments,
                              right.line_descriptors)
    _raises(ValueError, "right.point_descriptors", lambda: tracker.track(left, binary))
    infinite = tripose.Features(left.points.copy(), left.point_descriptors, left.segments, left.line_descriptors)
    infinite.points[3, 1] = np.inf
    _raises(ValueError, r"left.points\[3\]", lambda: tracker.track(infinite, right))
    _raises(ValueError, "R and t", lambda: tracker.track(left, right, R=np.eye(3)))
    _raises(ValueError, "left_features has unknown keys", lambda: tracker.track({"pts": left.points}, right))
    assert tracker.num_frames == 0
    assert tracker.track(left, right).status == GIVEN
    with pytest.raises(IndexError):
        tracker.pose(1)


# --- the program on rendered images --------------------------------------------------------------------

REPO = Path(__file__).resolve().parents[2]
sys.path.append(str(REPO / "test" / "python"))  # real_sequences.py: the TUM reader
import real_sequences as rs  # noqa: E402

TEXTURES = [REPO / "test" / "data" / "sequences" / "fountain-P11" / "images" / f"{k:04d}.jpg" for k in (0, 5)]
RENDER_K = np.array([[400.0, 0, 240], [0, 400, 180], [0, 0, 1]])
RENDER_SIZE = (480, 360)


def render(cv2, textures, R, t):
    """The image of a box room (walls 4 m either side, 9 m ahead, floor and ceiling, a panel 5.5 m
    ahead) textured with photographs, seen by a camera at (R, t) with RENDER_K."""
    width, height = RENDER_SIZE
    planes = [  # (point, normal, u axis, v axis, u range, v range, texture)
        ((0, 0, 9), (0, 0, -1), (1, 0, 0), (0, 1, 0), (-5, 5), (-3, 3), 0),
        ((-4, 0, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0), (-2, 9), (-3, 3), 1),
        ((4, 0, 0), (-1, 0, 0), (0, 0, 1), (0, 1, 0), (-2, 9), (-3, 3), 1),
        ((0, 2, 0), (0, -1, 0), (1, 0, 0), (0, 0, 1), (-4, 4), (-2, 9), 0),
        ((0, -3, 0), (0, 1, 0), (1, 0, 0), (0, 0, 1), (-4, 4), (-2, 9), 1),
        ((-1, 0.5, 5.5), (0, 0, -1), (1, 0, 0), (0, 1, 0), (-1, 1), (-1, 1.5), 1),
    ]
    centre = -R.T @ t
    u, v = np.meshgrid(np.arange(width, dtype=np.float64), np.arange(height, dtype=np.float64))
    rays = np.stack([u, v, np.ones_like(u)], -1) @ np.linalg.inv(RENDER_K).T @ R
    nearest = np.full((height, width), np.inf)
    image = np.zeros((height, width), np.uint8)
    for point, normal, u_axis, v_axis, u_range, v_range, texture in planes:
        point, normal = np.array(point, np.float64), np.array(normal, np.float64)
        with np.errstate(divide="ignore", invalid="ignore"):
            depth = ((point - centre) @ normal) / (rays @ normal)
            X = centre + rays * depth[..., None]
            a, b = (X - point) @ np.array(u_axis, np.float64), (X - point) @ np.array(v_axis, np.float64)
            hit = ((depth > 0.1) & (depth < nearest) & (a >= u_range[0]) & (a <= u_range[1]) & (b >= v_range[0])
                   & (b <= v_range[1]))
        tex = textures[texture]
        mx = np.nan_to_num((a - u_range[0]) * 120.0) % tex.shape[1]
        my = np.nan_to_num((b - v_range[0]) * 120.0) % tex.shape[0]
        sample = cv2.remap(tex, mx.astype(np.float32), my.astype(np.float32), cv2.INTER_LINEAR)
        image[hit] = sample[hit]
        nearest[hit] = depth[hit]
    return image


@pytest.fixture(scope="module")
def rendered_rig(tmp_path_factory):
    """Six frames of a rig (0.25 m baseline) moving 1.2 m along a curve: left/ and right/ PNGs,
    calib.yml (K1, K2, R12, t12) and the left camera's true poses."""
    cv2 = pytest.importorskip("cv2")
    folder = tmp_path_factory.mktemp("rendered-rig")
    textures = [cv2.imread(str(p), cv2.IMREAD_GRAYSCALE) for p in TEXTURES]
    assert all(t is not None for t in textures), f"the textures {TEXTURES} cannot be read"
    rig_R = rotation([0, 0.005, 0])
    rig_t = -rig_R @ np.array([0.25, 0, 0])
    poses = []
    for camera in ("left", "right"):
        (folder / camera).mkdir()
    for k in range(6):
        s = k / 5
        centre = np.array([0.4 * np.sin(np.pi * s), 0.1 * s, 1.1 * s])
        R = rotation([0.02 * s, 0.08 * np.sin(np.pi * s), 0.01 * s])
        t = -R @ centre
        poses.append((R, t))
        assert cv2.imwrite(str(folder / "left" / f"{k:04d}.png"), render(cv2, textures, R, t))
        assert cv2.imwrite(str(folder / "right" / f"{k:04d}.png"), render(cv2, textures, rig_R @ R, rig_R @ t + rig_t))
    fs = cv2.FileStorage(str(folder / "calib.yml"), cv2.FILE_STORAGE_WRITE)
    fs.write("K1", RENDER_K)
    fs.write("K2", RENDER_K)
    fs.write("R12", rig_R)
    fs.write("t12", rig_t.reshape(3, 1))
    fs.release()
    return folder, poses


def run_program(*arguments):
    return subprocess.run([sys.executable, "-m", "tripose.track_cli", *map(str, arguments)], capture_output=True,
                          text=True, timeout=120)


def test_program_tracks_a_rendered_rig_from_its_images(tmp_path, rendered_rig):
    folder, truth = rendered_rig
    out = tmp_path / "trajectory.txt"
    proc = run_program("--images", folder / "left", "--right", folder / "right", "--calib", folder / "calib.yml",
                       "--output", out)
    assert proc.returncode == 0, proc.stderr
    assert "6 frames: 1 given, 5 registered, 0 lost" in proc.stdout
    _, tracked_Rs, tracked_ts = rs.read_tum(out)
    tracked = list(zip(tracked_Rs, tracked_ts))
    assert len(tracked) == 6
    centres = np.array([-R.T @ t for R, t in truth])
    path_length = np.sum(np.linalg.norm(np.diff(centres, axis=0), axis=1))
    for k, (pose, true_pose) in enumerate(zip(tracked, truth)):
        rotation_error, position_error = errors(pose, true_pose)
        assert rotation_error < ROTATION_BOUND_DEG and position_error < POSITION_BOUND * path_length, f"frame {k}"


def test_program_rejects_sources_of_different_lengths_and_a_calibration_without_the_rig(tmp_path, rendered_rig):
    folder, _ = rendered_rig
    short = tmp_path / "short"
    short.mkdir()
    for k in range(4):
        (short / f"{k:04d}.png").write_bytes((folder / "right" / f"{k:04d}.png").read_bytes())
    out = tmp_path / "trajectory.txt"
    proc = run_program("--images", folder / "left", "--right", short, "--calib", folder / "calib.yml", "--output", out)
    assert proc.returncode == 1
    assert "--images" in proc.stderr and "--right" in proc.stderr and "6 frames" in proc.stderr and "4" in proc.stderr
    assert not out.exists()
    calib = tmp_path / "no-right-camera.yml"
    calib.write_text((folder / "calib.yml").read_text().replace("K2:", "K3:"))
    proc = run_program("--images", folder / "left", "--right", folder / "right", "--calib", calib, "--output", out)
    assert proc.returncode == 1 and "K2" in proc.stderr, proc.stderr
    assert not out.exists()


def test_covariance_on_request_covers_the_first_registered_frame():
    # With TrackerOptions.covariance each registered frame carries the covariance of its world pose
    # (the keyframe's held); frame 1, registered against the exact origin, lies within four of its
    # standard deviations of the truth on every seed tried.
    for seed in range(3):
        seq = StereoSequence(3, seed=seed)
        options = tripose.TrackerOptions()
        options.covariance = True
        tracker = make_tracker(seq, options)
        tracker.track(*seq.frame(0))
        result = tracker.track(*seq.frame(1))
        assert result.status == REGISTERED
        C = result.covariance
        assert C.shape == (6, 6) and np.allclose(C, C.T, atol=1e-15) and np.all(np.linalg.eigvalsh(C) > 0)
        R_true, t_true = seq.poses[1]
        angle = np.degrees(np.arccos(np.clip((np.trace(result.R @ R_true.T) - 1) / 2, -1, 1)))
        sigma = np.degrees(np.sqrt(result.noise_variance * np.trace(C[:3, :3])))
        assert angle < 4 * sigma, (seed, angle, sigma)
        t_sigma = np.sqrt(result.noise_variance * np.trace(C[3:, 3:]))
        assert np.linalg.norm(result.t - t_true) < 4 * t_sigma, seed
    assert make_tracker(StereoSequence(2, seed=0)).track(*StereoSequence(2, seed=0).frame(0)).covariance is None


# --- restarting after a long loss, and joining the maps --------------------------------------------------

class SurroundingScene(StereoSequence):
    """Points and segments on a cylinder 8-16 m around the origin, all round: a rig facing one way
    sees nothing of what it sees facing the other way. Each frame's rig is given by its yaw (about
    the vertical) and its centre."""

    def __init__(self, seed):
        rng = np.random.default_rng(seed)
        self.rng = rng
        self.binary = False
        self.rig_R = rotation([0, 0.01, 0])
        self.rig_t = -self.rig_R @ np.array([0.3, 0, 0])
        self.poses = []

        def around(n):
            azimuth = rng.uniform(0, 2 * np.pi, n)
            radius = rng.uniform(8, 16, n)
            return np.column_stack([radius * np.sin(azimuth), rng.uniform(-3, 3, n), radius * np.cos(azimuth)])

        self.points = around(1500)
        starts = around(300)
        directions = rng.normal(size=(300, 3))
        directions *= (rng.uniform(0.8, 2.0, 300) / np.linalg.norm(directions, axis=1))[:, None]
        self.segments = np.hstack([starts, starts + directions])
        self.point_descriptors = rng.uniform(0, 1, (1500, 128)).astype(np.float32)
        self.line_descriptors = rng.uniform(0, 1, (300, 128)).astype(np.float32)

    def add(self, yaw_deg, centre):
        R = rotation([0, np.radians(yaw_deg), 0]).T  # the camera looks along azimuth yaw_deg
        self.poses.append((R, -R @ np.asarray(centre, np.float64)))
        return len(self.poses) - 1


def test_a_rig_lost_for_long_restarts_and_joins_its_maps():
    """Eight frames facing north, five of noise, then the rig faces south, where no keyframe looks:
    it restarts a map there (at the last pose known, on the second frame facing south), turns back
    north in steps of 8 deg, and on seeing the first frames' place joins the new map to the first:
    every pose then matches the truth."""
    scene = SurroundingScene(seed=11)
    tracker = make_tracker(scene)
    rng = np.random.default_rng(12)
    plan = [("scene", 3.0 * k, [0.05 * k, 0, 0.1 * k]) for k in range(8)]
    plan += [("noise", None, None)] * 5
    plan += [("scene", 180.0 + 8.0 * k, [0.35 + 0.02 * k, 0, 0.7 - 0.02 * k]) for k in range(26)]
    results, truth = [], {}
    for kind, yaw, centre in plan:
        if kind == "noise":
            results.append(tracker.track(noise_features(rng), noise_features(rng)))
            continue
        k = scene.add(yaw, centre)
        truth[len(results)] = scene.poses[k]
        results.append(tracker.track(scene.observe(*scene.poses[k]), scene.observe(*scene.right_pose(k))))

    statuses = [r.status for r in results]
    assert statuses[:8] == [GIVEN] + [REGISTERED] * 7
    # The first frame facing south is lost too: a new map needs the frame before it to register
    # against it.
    assert statuses[8:14] == [LOST] * 6
    restart = results[14]
    assert restart.status == tripose.FrameStatus.RESTARTED and restart.map == 1 and restart.keyframe
    np.testing.assert_allclose(restart.R, results[7].R)  # placed at the last pose known
    np.testing.assert_allclose(restart.t, results[7].t)
    joins = [r for r in results[15:] if r.recognised_keyframe >= 0]
    assert joins, [r.status for r in results]
    join = joins[0]
    assert results[join.recognised_keyframe].map == 0 and join.map == 0
    before_join = results[15:join.frame]
    assert before_join and all(r.status == REGISTERED and r.map == 1 for r in before_join)
    assert all(r.status == REGISTERED for r in results[15:]), [r.reason for r in results[15:]]
    # At the end every pose is in map 0, the first frame's world, and matches the truth.
    centres = np.array([-R.T @ t for R, t in truth.values()])
    path_length = float(np.sum(np.linalg.norm(np.diff(centres, axis=0), axis=1)))
    for frame, true_pose in truth.items():
        if frame == 13:
            continue  # lost
        assert tracker.map_of(frame) == 0, frame
        rotation_error, position_error = errors(tracker.pose(frame), true_pose)
        assert rotation_error < ROTATION_BOUND_DEG, (frame, rotation_error)
        assert position_error < POSITION_BOUND * path_length, (frame, position_error)
    for frame in range(8, 14):
        assert tracker.map_of(frame) == -1 and tracker.pose(frame) is None
