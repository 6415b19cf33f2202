"""tripose-track: the trajectory of a calibrated camera through a sequence of images.

    tripose-track --images <folder | video | list file> --calib calib.yml [--poses initial.txt]
                  --output trajectory.txt [--yaml result.yml] [--window N] [--min-inliers N]
                  [--threshold PX] [--local-adjustment [0|1]] [--loop-closure [0|1]] [--max-image-size PX]
                  [--contrast-threshold C] [--max-points N] [--global-adjustment-interval N]
                  [--mode full | video]

The frames come from tripose.images.open_frames (a folder of images in natural name order, a list
file, or a video); each one's features from tripose.images.extract_features (SIFT points, EDLines
segments with LBD) with tracking_feature_options() (more and fainter SIFT points than the defaults;
--contrast-threshold and --max-points change them), given to tripose.Tracker with the calibration's K
and dist (the tracker undistorts them).

--mode video tracks a monocular video in real time instead (tripose.video.VideoTracker): points are
followed from frame to frame by optical flow and given to the tracker as linked observations, and
detected afresh only in the frame after a keyframe or when too few survive (no descriptors, no
matching). On the rendered courtyard (640x480) it takes a fraction of the full mode's time per frame
at the same accuracy (doc/studies/front_end_and_tracker.md, "Video mode"). Its keyframes are spaced
by 0.5 deg of parallax (tripose.video.VIDEO_KEYFRAME_PARALLAX_DEG); --window, --min-inliers,
--threshold, --local-adjustment and --global-adjustment-interval apply as in the full mode;
--max-image-size, --contrast-threshold, --max-points (the points are corners followed in the
full-size frames) and --loop-closure (they have no descriptors) do not.
With --right it tracks the rig with tripose.video.StereoVideoTracker: each followed point is found
in the right image by the same flow, and no pose is needed.

calib.yml (OpenCV FileStorage YAML, JSON or XML) holds K (3x3), optionally dist (OpenCV's
distortion coefficients), and the pose of frame 1 relative to frame 0 as R12 (3x3 rotation or
rotation vector) and t12 (x_1 = R12 x_0 + t12); frame 0 is then the world's origin and |t12| its
unit of length. Instead of R12 and t12, --poses gives a TUM trajectory (timestamp tx ty tz qx qy qz
qw per line: the camera's position and orientation in the world) whose lines are the poses of the
first frames, in order (at least two; its timestamps are not used); --poses takes precedence.

The output is a TUM trajectory of every frame with a pose (lost frames are left out), stamped with
the frames' timestamps; --yaml writes per frame its status (0 given, 1 registered, 2 lost, 3
restarted: a stereo rig lost for longer began a new map), keyframe, features, inliers, R and t
(x_cam = R X + t; absent for a lost frame), the reason it is lost, recognised_keyframe: the keyframe
of a place seen before through which the frame was registered (a loop it closed, a link to an older
place, a lost camera found again, or two maps joined), -1 for none, and map: the map its pose is in
at the end (0 the first; -1 lost). Poses of a map never joined to map 0 are in that map's own frame.

--loop-closure (tripose.TrackerOptions.loop_closure) looks, after each new keyframe, for a place seen
before among the keyframes older than the window, joins its tracks and, when more than two windows
of keyframes lie between the place and the frame, closes the loop through it (once per loop): a pose
graph corrects the frames since and every registered frame is adjusted with the structure. It costs
a place check per keyframe. A frame lost against the window is looked for among every keyframe's
places with or without it.

Pixel tolerances (--threshold, default 2 px, and the matching's epipolar distance) are those of
features detected at full size: when the images are detected in a reduced copy (--max-image-size),
they grow by the reduction factor, as the features are that much less precise in the images' pixels.

A frame that cannot be read or decoded is reported on stderr and lost (one with a given pose keeps
it); tracking goes on. A source, calibration or pose file that cannot be used, a source none of whose
frames can be decoded, an image whose size contradicts the calibration (K's principal point outside
the image: check_image_fits), or an output that cannot be written ends the program with exit status
1 and a message naming the option, file, key or frame, before anything is written: the outputs are
written only at the end, each through a temporary file renamed onto it.

With --right, --images are the left camera's frames of a calibrated stereo rig and --right the right
camera's (as many frames), tracked by tripose.StereoTracker: the calibration holds K1 (optionally
dist1) of the left camera, K2 (dist2) of the right (or K, dist for both), and the rig as R12, t12: the
right camera's pose relative to the left (x_2 = R12 x_1 + t12; |t12|, the baseline, is the unit of
length). No pose is needed: frame 0's left camera is the world's origin, or the first pose of
--poses when given. The poses written are the left camera's. --local-adjustment and --loop-closure
are not available.

Also run as `python -m tripose.track_cli`.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
from pathlib import Path
from typing import List, Optional, Sequence, Tuple

import numpy as np

PROGRAM = "tripose-track"

# A rotation read from a file is accepted when R R^T is this close to the identity (printed rotations
# carry a few digits less than double precision).
_ROTATION_TOLERANCE = 1e-6

# The given pair's check (Tracker.given_pair_agreement): with at least this many matches, fewer than
# this fraction on their epipolar lines means images out of the poses' order or a wrong calibration.
_AGREEMENT_MIN_MATCHES = 20
_AGREEMENT_MIN_FRACTION = 0.3

STATUS_CODES = {"GIVEN": 0, "REGISTERED": 1, "LOST": 2, "RESTARTED": 3}


class InputError(Exception):
    """Input the program cannot work with: the message names the option, file, key or frame."""


class _Parser(argparse.ArgumentParser):
    """argparse whose usage errors exit with status 1, as every other bad input of the program."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


def _whole_number(minimum):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a whole number >= {minimum}, got {text!r}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"expected a whole number >= {minimum}, got {value}")
        return value
    return parse


def _switch(text):
    """A switch's value, 0 or 1, as the C++ program takes it; the switch alone means 1."""
    if text not in ("0", "1"):
        raise argparse.ArgumentTypeError(f"expected 0 or 1, got {text!r}")
    return text == "1"


def _positive_number(what):
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what} > 0, got {text!r}") from None
        if not (math.isfinite(value) and value > 0):
            raise argparse.ArgumentTypeError(f"expected a finite {what} > 0, got {text!r}")
        return value
    return parse


def _parser():
    p = _Parser(prog=PROGRAM, description="The trajectory of a calibrated camera through a sequence of images, "
                                          "from their points and line segments (tripose.Tracker).")
    p.add_argument("--images", required=True, help="a folder of images, a video, or a text file listing images")
    p.add_argument("--right", help="a stereo rig's right camera's frames (--images: the left camera's), as many; "
                                   "the calibration then holds K1, K2, R12, t12 (the rig) and no pose is needed")
    p.add_argument("--calib", required=True, type=Path,
                   help="OpenCV YAML with K, optional dist, and R12, t12 (frame 1's pose relative to frame 0)")
    p.add_argument("--poses", type=Path, help="TUM trajectory whose lines are the poses of the first frames (>= 2); "
                                              "replaces R12, t12")
    p.add_argument("--output", required=True, type=Path, help="the TUM trajectory written (frames with a pose)")
    p.add_argument("--yaml", type=Path, help="also write every frame's result to this YAML file")
    p.add_argument("--window", type=_whole_number(2), help="keyframes a frame is registered against (default 5)")
    p.add_argument("--min-inliers", type=_whole_number(1),
                   help="features that must agree with a frame's pose for it to be registered (default 15)")
    p.add_argument("--threshold", type=_positive_number("number of pixels"),
                   help="RANSAC inlier threshold in px of full-size detection (default 2; grows with the "
                        "reduction of --max-image-size)")
    p.add_argument("--local-adjustment", type=_switch, nargs="?", const=True, default=None, metavar="0|1",
                   help="refine the window's frames and structure after each registration (default 1)")
    p.add_argument("--loop-closure", type=_switch, nargs="?", const=True, default=False, metavar="0|1",
                   help="after each keyframe, look for a place seen before among the older keyframes, join its "
                        "tracks and close the loop through it (the least drift; a place check per keyframe, 2 to "
                        "3.3 times the time per frame)")
    p.add_argument("--global-adjustment-interval", type=_whole_number(0), metavar="N",
                   help="adjust every frame and the structure after each N keyframes (default 0: never)")
    p.add_argument("--mode", choices=("full", "video"), default="full",
                   help="full: features detected and matched in every frame (default); video: points followed "
                        "by optical flow, detected afresh after keyframes (real time; with --right, a stereo rig)")
    p.add_argument("--max-image-size", type=_whole_number(0),
                   help="detect features in images reduced to this longer side (px; default 1600, 0: full size)")
    p.add_argument("--contrast-threshold", type=_positive_number("number"),
                   help="SIFT's contrast threshold (default 0.01; lower finds more, fainter points)")
    p.add_argument("--max-points", type=_whole_number(0),
                   help="the strongest SIFT points kept per image (default 8192, 0: all)")
    return p


def _feature_options(args):
    """The detection options that --max-image-size, --contrast-threshold and --max-points set."""
    from . import images

    options = images.tracking_feature_options()
    if args.max_image_size is not None:
        options.max_image_size = args.max_image_size
    if args.contrast_threshold is not None:
        options.contrast_threshold = args.contrast_threshold
    if args.max_points is not None:
        options.max_points = args.max_points
    return options


# --- outputs -----------------------------------------------------------------------------------------

def _check_writable(path: Path, option: str):
    """InputError naming the option unless a file can be created at path (tried with a temporary
    file beside it, removed at once)."""
    if path.is_dir():
        raise InputError(f"{option} {path}: is a folder, not a file")
    folder = path.parent
    if not folder.is_dir():
        raise InputError(f"{option} {path}: the folder {folder} does not exist")
    if path.exists() and not os.access(path, os.W_OK):
        raise InputError(f"{option} {path}: cannot be written (permission denied)")
    try:
        handle, probe = tempfile.mkstemp(dir=folder, prefix=f".{path.name}.", suffix=".tmp")
    except OSError as error:
        raise InputError(f"{option} {path}: cannot be written ({error.strerror or error})") from None
    os.close(handle)
    os.unlink(probe)


def _write_atomically(path: Path, text: str):
    """text as path's content, through a temporary file in path's folder renamed onto it: a reader
    never sees half a file, and a failure leaves no file."""
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


# --- rotations -----------------------------------------------------------------------------------------

def _quaternion_to_rotation(q):
    """The rotation of the unit quaternion (qx, qy, qz, qw), Hamilton convention."""
    x, y, z, w = np.asarray(q, np.float64) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _rotation_to_quaternion(R):
    """The unit quaternion (qx, qy, qz, qw) of the rotation R with qw >= 0; the component of largest
    magnitude is taken from the diagonal, the others from it, so that no division is by a small number."""
    R = np.asarray(R, np.float64)
    trace = R[0, 0] + R[1, 1] + R[2, 2]
    four_squares = [1 + 2 * R[0, 0] - trace, 1 + 2 * R[1, 1] - trace, 1 + 2 * R[2, 2] - trace, 1 + trace]
    k = int(np.argmax(four_squares))
    big = 0.5 * math.sqrt(max(four_squares[k], 0.0))
    f = 0.25 / big
    if k == 0:
        q = [big, (R[0, 1] + R[1, 0]) * f, (R[0, 2] + R[2, 0]) * f, (R[2, 1] - R[1, 2]) * f]
    elif k == 1:
        q = [(R[0, 1] + R[1, 0]) * f, big, (R[1, 2] + R[2, 1]) * f, (R[0, 2] - R[2, 0]) * f]
    elif k == 2:
        q = [(R[0, 2] + R[2, 0]) * f, (R[1, 2] + R[2, 1]) * f, big, (R[1, 0] - R[0, 1]) * f]
    else:
        q = [(R[2, 1] - R[1, 2]) * f, (R[0, 2] - R[2, 0]) * f, (R[1, 0] - R[0, 1]) * f, big]
    q = np.array(q) / np.linalg.norm(q)
    return q if q[3] >= 0 else -q


def _is_rotation(R):
    return bool(np.all(np.isfinite(R)) and np.abs(R @ R.T - np.eye(3)).max() < _ROTATION_TOLERANCE
                and np.linalg.det(R) > 0)


# --- inputs ------------------------------------------------------------------------------------------

def _cv2():
    from .images import _cv2 as images_cv2
    return images_cv2()


def _matrix(fs, key):
    """The numbers under key as an array (a matrix, a sequence or one number), or None when the key
    is absent or empty; InputError naming the key for anything else."""
    node = fs.getNode(key)
    if node.empty() or node.isNone():
        return None
    value = None
    if node.isMap():
        value = node.mat()
    elif node.isSeq():
        items = [node.at(i) for i in range(node.size())]
        if all(item.isReal() or item.isInt() for item in items):
            value = np.array([item.real() for item in items], np.float64)
    elif node.isReal() or node.isInt():
        value = np.array([node.real()])
    if value is None:
        raise InputError(f"key {key}: expected a matrix of numbers")
    return np.asarray(value, np.float64)


def _read_calibration_keys(path: Path, keys, present=()):
    """{key: array or None} of the calibration file's keys (_matrix), and for each key of present
    whether the file has it; InputError naming the file otherwise."""
    cv2 = _cv2()
    if not path.is_file():
        raise InputError(f"--calib {path}: no such file")
    try:
        fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    except (cv2.error, SystemError) as error:
        # cv2 reports a parse error as a SystemError whose cause is the cv2.error.
        error = error.__cause__ or error
        raise InputError(f"--calib {path}: cannot be parsed as OpenCV YAML, JSON or XML "
                         f"({str(error).strip().splitlines()[-1]})") from None
    if not fs.isOpened():
        raise InputError(f"--calib {path}: cannot be opened as OpenCV YAML, JSON or XML")
    try:
        values = {key: _matrix(fs, key) for key in keys}
        values.update({key: not fs.getNode(key).empty() for key in present})
        return values
    except InputError as error:
        raise InputError(f"--calib {path}: {error}") from None
    finally:
        fs.release()


def _camera_matrix(path: Path, key, K):
    """K (a calibration value under key) as a checked 3x3 camera matrix."""
    if K.size != 9 or not np.all(np.isfinite(K)):
        raise InputError(f"--calib {path}: key {key}: expected a finite 3x3 camera matrix, got {K.size} values")
    K = K.reshape(3, 3)
    if not (K[0, 0] > 0 and K[1, 1] > 0 and K[2, 2] != 0):
        raise InputError(f"--calib {path}: key {key}: the focal lengths K[0,0], K[1,1] must be > 0 and K[2,2] "
                         "non-zero")
    return K


def _distortion(path: Path, key, dist):
    """dist (a calibration value under key, or None) as OpenCV's coefficients, None when empty."""
    if dist is None:
        return None
    dist = dist.ravel()
    if dist.size == 0:
        return None
    if dist.size not in (4, 5, 8, 12, 14) or not np.all(np.isfinite(dist)):
        raise InputError(f"--calib {path}: key {key}: expected 4, 5, 8, 12 or 14 finite distortion coefficients, "
                         f"got {dist.size}")
    return dist


def _relative_pose(path: Path, R12, t12, zero_baseline):
    """(R12, t12), R12 a 3x3 rotation or a rotation vector, t12 non-zero (zero_baseline says why)."""
    if R12.size == 3:
        R12 = _cv2().Rodrigues(R12.reshape(3, 1))[0]
    if R12.size != 9 or not _is_rotation(R12.reshape(3, 3)):
        raise InputError(f"--calib {path}: key R12: expected a 3x3 rotation or a rotation vector")
    if t12.size != 3 or not np.all(np.isfinite(t12)):
        raise InputError(f"--calib {path}: key t12: expected 3 finite numbers, got {t12.size} values")
    if not np.any(t12):
        raise InputError(f"--calib {path}: key t12 is zero: {zero_baseline}")
    return np.ascontiguousarray(R12.reshape(3, 3)), t12.reshape(3).copy()


def read_calibration(path: Path):
    """(K, dist or None, (R12, t12) or None) of the calibration file; InputError naming the file and
    the key otherwise."""
    values = _read_calibration_keys(path, ("K", "dist", "R12", "t12"), present=("K1",))
    K = values["K"]
    if K is None:
        per_view = " (K1, K2, ... are per view of a triplet: a tracked sequence has one camera, K)" \
            if values["K1"] else ""
        raise InputError(f"--calib {path}: no key K (the 3x3 camera matrix){per_view}")
    K = _camera_matrix(path, "K", K)
    dist = _distortion(path, "dist", values["dist"])
    R12, t12 = values["R12"], values["t12"]
    relative = None
    if R12 is not None or t12 is not None:
        if R12 is None or t12 is None:
            raise InputError(f"--calib {path}: key {'R12' if R12 is None else 't12'} is missing "
                             f"({'t12' if R12 is None else 'R12'} is given; frame 1's pose needs both)")
        relative = _relative_pose(path, R12, t12, "frames 0 and 1 must be apart (their baseline fixes the scale)")
    return K, dist, relative


def read_stereo_calibration(path: Path):
    """(K (left, right), dist (left, right; None where absent), (R12, t12)) of a stereo rig's
    calibration file: K1 and K2 (or K for both), optional dist1 and dist2 (or dist), and R12, t12, the
    right camera's pose relative to the left; InputError naming the file and the key otherwise."""
    values = _read_calibration_keys(path, ("K", "K1", "K2", "dist", "dist1", "dist2", "R12", "t12"))

    def per_camera(key, required):
        shared, first, second = values[key], values[key + "1"], values[key + "2"]
        if shared is not None and (first is not None or second is not None):
            raise InputError(f"--calib {path}: key {key}: give either {key} (both cameras) or {key}1 and {key}2, "
                             "not both")
        if shared is not None:
            return [(key, shared), (key, shared)]
        if (first is None) != (second is None) or (required and first is None):
            missing, camera = (f"{key}1", "left") if first is None else (f"{key}2", "right")
            raise InputError(f"--calib {path}: no key {missing} (the {camera} camera's; with --right the "
                             f"calibration gives {key}1 and {key}2, or {key} for both)")
        return [(f"{key}1", first), (f"{key}2", second)]

    Ks = [_camera_matrix(path, key, K) for key, K in per_camera("K", True)]
    dists = [_distortion(path, key, dist) for key, dist in per_camera("dist", False)]
    for key in ("R12", "t12"):
        if values[key] is None:
            raise InputError(f"--calib {path}: no key {key} (with --right, R12 and t12 are the rig: the right "
                             "camera's pose relative to the left)")
    return Ks, dists, _relative_pose(path, values["R12"], values["t12"], "the rig's baseline fixes the scale")


def read_initial_poses(path: Path, minimum: int = 2) -> List[Tuple[np.ndarray, np.ndarray]]:
    """The poses (R, t), x_cam = R X + t, of a TUM trajectory's lines (camera-to-world: position
    and orientation of the camera in the world); InputError naming the file and line otherwise."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise InputError(f"--poses {path}: cannot be read ({getattr(error, 'strerror', None) or error})") from None
    poses = []
    for number, line in enumerate(text.splitlines(), 1):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        try:
            values = [float(v) for v in fields]
        except ValueError:
            values = []
        if len(values) != 8 or not all(math.isfinite(v) for v in values):
            raise InputError(f"--poses {path}:{number}: expected 8 finite numbers (timestamp tx ty tz qx qy qz qw)")
        q = np.array(values[4:8])
        if abs(np.linalg.norm(q) - 1) > 1e-3:
            raise InputError(f"--poses {path}:{number}: the quaternion (qx qy qz qw) is not of unit length "
                             f"({np.linalg.norm(q):.6g})")
        R = _quaternion_to_rotation(q).T
        poses.append((R, -R @ np.array(values[1:4])))
    if not poses and minimum == 1:
        raise InputError(f"--poses {path}: holds no pose")
    if len(poses) < minimum:
        raise InputError(f"--poses {path}: holds {len(poses)} pose(s); the first two frames need theirs (they fix "
                         "the world frame and the scale)")
    centres = np.array([-R.T @ t for R, t in poses])
    if minimum > 1 and np.all(np.abs(centres - centres[0]).max(axis=1) == 0):
        raise InputError(f"--poses {path}: every pose is at the same position: the given frames must be apart "
                         "(their baseline fixes the scale)")
    return poses


def check_image_fits(K, shape, frame: int, name: str, calib: Path):
    """InputError unless K's principal point lies inside the image (at most half the image's width
    and height from its centre). A calibrated camera's optical axis meets its image, so the rule
    rejects no real calibration; it catches one made for another image size, such as a full-size K
    with images reduced to a third."""
    cx, cy = K[0, 2] / K[2, 2], K[1, 2] / K[2, 2]
    height, width = shape[:2]
    if not (0 <= cx <= width and 0 <= cy <= height):
        raise InputError(f"frame {frame} ({name}) is {width}x{height} but the principal point of K in {calib} is "
                         f"({cx:.1f}, {cy:.1f}), outside it: the calibration is for another image size")


# --- tracking --------------------------------------------------------------------------------------

def tracker_options(args, pixel_scale: float = 1.0, options=None):
    """tripose.TrackerOptions of the command line (over options, by default the library's), the pixel
    tolerances grown by pixel_scale (the reduction of the detection images)."""
    import tripose

    options = tripose.TrackerOptions() if options is None else options
    if args.window is not None:
        options.window = args.window
    if args.min_inliers is not None:
        options.min_inliers = args.min_inliers
    if args.threshold is not None:
        options.ransac.threshold = args.threshold
    if args.local_adjustment is not None:
        options.local_adjustment = bool(args.local_adjustment)
    options.loop_closure = options.loop_closure or bool(args.loop_closure)
    if args.global_adjustment_interval is not None:
        options.global_adjustment_interval = args.global_adjustment_interval
    options.ransac.threshold *= pixel_scale
    options.matching.epipolar_distance *= pixel_scale
    return options


def _tum_text(rows):
    lines = ["# timestamp tx ty tz qx qy qz qw"]
    for stamp, R, t in rows:
        values = [*(-R.T @ t), *_rotation_to_quaternion(R.T)]
        lines.append(f"{stamp:.9f} " + " ".join(f"{v:.17g}" for v in values))
    return "\n".join(lines) + "\n"


def _yaml_text(args, pixel_scale, options, frames, poses):
    cv2 = _cv2()
    fs = cv2.FileStorage("", cv2.FILE_STORAGE_WRITE | cv2.FILE_STORAGE_MEMORY | cv2.FILE_STORAGE_FORMAT_YAML)
    fs.write("images", str(args.images))
    if getattr(args, "right", None) is not None:
        fs.write("right", str(args.right))
    fs.write("calib", str(args.calib))
    if args.poses is not None:
        fs.write("poses", str(args.poses))
    counts = [sum(1 for f in frames if f["status"] == code) for code in (0, 1, 2, 3)]
    fs.write("num_frames", len(frames))
    fs.write("given", counts[0])
    fs.write("registered", counts[1])
    fs.write("lost", counts[2])
    fs.write("restarted", counts[3])
    fs.write("window", options.window)
    fs.write("min_inliers", options.min_inliers)
    fs.write("threshold", options.ransac.threshold)
    fs.write("local_adjustment", int(options.local_adjustment))
    fs.write("loop_closure", int(options.loop_closure))
    fs.write("global_adjustment_interval", int(options.global_adjustment_interval))
    fs.write("pixel_scale", float(pixel_scale))
    fs.startWriteStruct("frames", cv2.FileNode_SEQ)
    for f, pose in zip(frames, poses):
        fs.startWriteStruct("", cv2.FileNode_MAP)
        fs.write("frame", f["frame"])
        fs.write("name", f["name"])
        fs.write("timestamp", f["timestamp"])
        fs.write("status", f["status"])
        fs.write("keyframe", int(f["keyframe"]))
        fs.write("features", f["features"])
        fs.write("inliers", f["inliers"])
        if pose is not None:
            fs.write("R", np.ascontiguousarray(pose[0]))
            fs.write("t", np.ascontiguousarray(pose[1]).reshape(3, 1))
        fs.write("reason", f["reason"])
        fs.write("recognised_keyframe", f["recognised_keyframe"])
        fs.write("map", f.get("map", -1 if pose is None else 0))
        fs.endWriteStruct()
    fs.endWriteStruct()
    return fs.releaseAndGetString()


def _frame_count(source) -> Optional[int]:
    """The number of frames of a folder or list source without reading them; None for a video."""
    from . import images

    path = Path(source)
    try:
        if path.is_dir():
            return len(images._folder_files(path))
        if path.is_file() and (path.suffix.lower() in (".txt", ".lst", ".list") or images._is_text(path)):
            return len(images._list_entries(path))
    except ValueError:
        return None
    return None


def run_stereo(args) -> int:
    """run() for a stereo rig (--right): tripose.StereoTracker on both sources' frames in lockstep."""
    import itertools

    import tripose
    from . import images

    if args.local_adjustment:
        raise InputError("--local-adjustment: not available with --right (the stereo tracker has none)")
    if args.loop_closure:
        raise InputError("--loop-closure: not available with --right (the stereo tracker has none)")
    if args.global_adjustment_interval:
        raise InputError("--global-adjustment-interval: not available with --right (the stereo tracker has none)")
    (K, K_right), (dist, dist_right), (R12, t12) = read_stereo_calibration(args.calib)
    given = read_initial_poses(args.poses, minimum=1)[:1] if args.poses is not None else []
    try:
        tripose.StereoTracker(K, K_right, R12, t12, dist, dist_right, tracker_options(args))
    except (ValueError, TypeError) as error:
        raise InputError(f"--calib {args.calib}: {error}") from None
    counts = (_frame_count(args.images), _frame_count(args.right))
    if None not in counts and counts[0] != counts[1]:
        raise InputError(f"--images {args.images} holds {counts[0]} frames but --right {args.right} holds "
                         f"{counts[1]}: a rig's two sources must hold the same number of frames")
    sources = []
    for option, source in (("--images", args.images), ("--right", args.right)):
        try:
            sources.append(images.open_frames(source))
        except ValueError as error:
            raise InputError(f"{option} {error}") from None
    if args.mode == "video":
        return run_stereo_video(args, (K, K_right), (dist, dist_right), (R12, t12), given, sources)
    feature_options = _feature_options(args)

    tracker, pixel_scale, options = None, 1.0, None
    frames = []
    print(f"{'frame':>5}  {'name':<28} {'status':<10} {'inliers/features':>16} {'ms':>7}")
    ended = object()
    for index, (left, right) in enumerate(itertools.zip_longest(*sources, fillvalue=ended)):
        if left is ended or right is ended:
            longer, shorter = (("--right", args.right), ("--images", args.images)) if left is ended else \
                (("--images", args.images), ("--right", args.right))
            raise InputError(f"{longer[0]} {longer[1]} holds more frames than {shorter[0]} {shorter[1]} ({index}): "
                             "a rig's two sources must hold the same number of frames")
        stamp, name, image = left
        features = []
        for (_, frame_name, frame_image), camera, option in ((left, K, "--images"), (right, K_right, "--right")):
            if frame_image is None:
                if index == 0:
                    raise InputError(f"frame 0 ({frame_name}, {option}): cannot be read or decoded; the first frame "
                                     "fixes the world and must be read")
                print(f"{PROGRAM}: frame {index} ({frame_name}, {option}): cannot be read or decoded", file=sys.stderr)
                features.append(None)
                continue
            check_image_fits(camera, frame_image.shape, index, frame_name, args.calib)
            features.append(images.extract_features(frame_image, camera, options=feature_options))
        if tracker is None:
            pixel_scale = images.detection_scale(image.shape, feature_options.max_image_size)
            options = tracker_options(args, pixel_scale)
            tracker = tripose.StereoTracker(K, K_right, R12, t12, dist, dist_right, options)
        result = tracker.track(*features, *(given[0] if index < len(given) else (None, None)))
        status, reason = result.status.name, result.reason
        if features[0] is None and status == "LOST":
            reason = "the left image cannot be read or decoded"
        frames.append({"frame": index, "name": name, "timestamp": stamp, "status": STATUS_CODES[status],
                       "keyframe": bool(result.keyframe), "features": result.features, "inliers": result.inliers,
                       "reason": reason, "recognised_keyframe": result.recognised_keyframe})
        share = f"{result.inliers}/{result.features}"
        print(f"{index:>5}  {name:<28} {status:<10} {share:>16} {result.milliseconds:>7.0f}"
              + (f"  {reason}" if reason else "") + _place_note(result), flush=True)

    for f in frames:
        f["map"] = tracker.map_of(f["frame"])  # as the maps stand at the end
    _write_outputs(args, pixel_scale, options, frames, tracker.trajectory())
    return 0


def _write_outputs(args, pixel_scale, options, frames, poses):
    """The TUM trajectory (and with --yaml the per-frame results), each written atomically, and the
    summary line."""
    rows = [(f["timestamp"], R, t) for f, pose in zip(frames, poses) if pose is not None for R, t in [pose]]
    texts = [(args.output, _tum_text(rows))]
    if args.yaml is not None:
        texts.append((args.yaml, _yaml_text(args, pixel_scale, options, frames, poses)))
    for path, text in texts:
        try:
            _write_atomically(path, text)
        except OSError as error:
            raise InputError(f"{path}: cannot be written ({error.strerror or error})") from None
    counts = [sum(1 for f in frames if f["status"] == code) for code in (0, 1, 2, 3)]
    restarts = f", {counts[3]} restarted" if counts[3] else ""
    print(f"{len(frames)} frames: {counts[0]} given, {counts[1]} registered, {counts[2]} lost{restarts}; "
          f"{len(rows)} poses written to {args.output}" + (f", the results to {args.yaml}" if args.yaml else ""))


def _place_note(result) -> str:
    """A frame line's note of the place seen before that registered the frame, if any."""
    place = result.recognised_keyframe
    return f"  (place of keyframe {place})" if place >= 0 else ""


def _record_video_frame(frames, index, stamp, name, frame, unread: bool):
    """Appends a video frame's outcome to frames and prints its line (times per stage)."""
    result = frame.result
    status, reason = result.status.name, result.reason
    if unread and status == "LOST":
        reason = "the image cannot be read or decoded"
    frames.append({"frame": index, "name": name, "timestamp": stamp, "status": STATUS_CODES[status],
                   "keyframe": bool(result.keyframe), "features": result.features, "inliers": result.inliers,
                   "reason": reason, "recognised_keyframe": result.recognised_keyframe})
    ms = frame.milliseconds
    stages = " / ".join(f"{ms[stage]:.1f}" for stage in ms if stage != "total")
    print(f"{index:>5}  {name:<28} {status:<10} {f'{result.inliers}/{result.features}':>16} {ms['total']:>7.1f}  "
          f"{stages}" + (f"  {reason}" if reason else "") + _place_note(result), flush=True)


def run_stereo_video(args, cameras, distortions, rig, given, sources) -> int:
    """run_stereo() with --mode video: tripose.video.StereoVideoTracker on both sources in lockstep."""
    import itertools

    from . import video

    options = video.VideoOptions(tracker=tracker_options(args, options=video.video_tracker_options()))
    tracker = video.StereoVideoTracker(cameras[0], cameras[1], *rig, *distortions, options)
    frames = []
    print(f"{'frame':>5}  {'name':<28} {'status':<10} {'inliers/features':>16} {'ms':>7}  flow / detection / "
          "stereo / registration ms")
    ended = object()
    for index, (left, right) in enumerate(itertools.zip_longest(*sources, fillvalue=ended)):
        if left is ended or right is ended:
            raise InputError(f"--images {args.images} and --right {args.right} hold different numbers of frames: "
                             "a rig's two sources must hold the same number")
        stamp, name, image = left
        for (_, frame_name, frame_image), camera, option in ((left, cameras[0], "--images"),
                                                             (right, cameras[1], "--right")):
            if frame_image is None:
                print(f"{PROGRAM}: frame {index} ({frame_name}, {option}): cannot be read or decoded", file=sys.stderr)
            else:
                check_image_fits(camera, frame_image.shape, index, frame_name, args.calib)
        try:
            frame = tracker.track(image, right[2], *(given[0] if index < len(given) else (None, None)))
        except ValueError as error:
            raise InputError(f"frame {index} ({name}): {error}") from None
        _record_video_frame(frames, index, stamp, name, frame, image is None or right[2] is None)
    if not frames:
        raise InputError(f"--images {args.images}: holds no frames")
    for f in frames:
        f["map"] = tracker.tracker.map_of(f["frame"])  # as the maps stand at the end
    _write_outputs(args, 1.0, options.tracker, frames, tracker.trajectory())
    return 0


def run_video(args, K, dist, given, source) -> int:
    """run() with --mode video: tripose.video.VideoTracker on the frames of one camera."""
    from . import video

    options = video.VideoOptions(tracker=tracker_options(args, options=video.video_tracker_options()))
    tracker = video.VideoTracker(K, dist, options)
    frames, index = [], 0
    print(f"{'frame':>5}  {'name':<28} {'status':<10} {'inliers/features':>16} {'ms':>7}  flow / detection / "
          "registration ms")
    for stamp, name, image in source:
        if image is None:
            outcome = "its given pose is kept, without features" if index < len(given) else "lost"
            print(f"{PROGRAM}: frame {index} ({name}): cannot be read or decoded; {outcome}", file=sys.stderr)
        else:
            check_image_fits(K, image.shape, index, name, args.calib)
        try:
            frame = tracker.track(image, *(given[index] if index < len(given) else (None, None)))
        except ValueError as error:
            raise InputError(f"frame {index} ({name}): {error}") from None
        _record_video_frame(frames, index, stamp, name, frame, image is None)
        index += 1
    if index == 0:
        raise InputError(f"--images {args.images}: holds no frames")
    if args.poses is not None and len(given) > len(frames):
        print(f"{args.poses}: {len(given)} poses for {len(frames)} frames; the rest are not used.")
    _write_outputs(args, 1.0, options.tracker, frames, tracker.trajectory())
    return 0


def run(args) -> int:
    import tripose
    from . import images

    _check_writable(args.output, "--output")
    if args.yaml is not None:
        _check_writable(args.yaml, "--yaml")
        if args.yaml.resolve() == args.output.resolve():
            raise InputError(f"--yaml {args.yaml}: the same file as --output")
    if args.mode == "video" and args.max_image_size is not None:
        raise InputError("--max-image-size: not used by --mode video (the points are followed in the full-size "
                         "frames)")
    for value, option in ((args.contrast_threshold, "--contrast-threshold"), (args.max_points, "--max-points")):
        if args.mode == "video" and value is not None:
            raise InputError(f"{option}: not used by --mode video (its points are corners, not SIFT's)")
    if args.mode == "video" and args.loop_closure:
        raise InputError("--loop-closure: not used by --mode video (its points have no descriptors to recognise a "
                         "place by)")
    if args.right is not None:
        return run_stereo(args)
    K, dist, relative = read_calibration(args.calib)
    if args.poses is not None:
        given = read_initial_poses(args.poses)
        if relative is not None:
            print(f"The first poses come from {args.poses} (--poses), not from R12, t12 of {args.calib}.")
    elif relative is not None:
        given = [(np.eye(3), np.zeros(3)), relative]
    else:
        raise InputError(f"--calib {args.calib}: no key R12 (with t12), the pose of frame 1 relative to frame 0; "
                         "give them there or the first frames' poses with --poses")
    feature_options = _feature_options(args)
    try:
        tripose.Tracker(K, dist, tracker_options(args))  # K and dist as the tracker checks them
    except (ValueError, TypeError) as error:
        raise InputError(f"--calib {args.calib}: {error}") from None
    try:
        source = images.open_frames(args.images)
    except ValueError as error:
        raise InputError(f"--images {error}") from None
    if args.mode == "video":
        return run_video(args, K, dist, given, source)

    tracker, pixel_scale, options = None, 1.0, None
    frames, waiting = [], []

    def start(image_shape):
        nonlocal tracker, pixel_scale, options
        pixel_scale = images.detection_scale(image_shape, feature_options.max_image_size)
        options = tracker_options(args, pixel_scale)
        tracker = tripose.Tracker(K, dist, options)
        if pixel_scale != 1.0:
            print(f"Features detected in images reduced by {pixel_scale:.2f}; pixel tolerances grown by as much "
                  f"(threshold {options.ransac.threshold:.3g} px).")
        print(f"{'frame':>5}  {'name':<28} {'status':<10} {'inliers/features':>16} {'ms':>7}")

    def track(index, stamp, name, features):
        pose = given[index] if index < len(given) else (None, None)
        result = tracker.track(features, *pose)
        status = result.status.name
        reason = result.reason
        if features is None and status == "LOST":
            reason = "the image cannot be read or decoded"
        frames.append({"frame": index, "name": name, "timestamp": stamp, "status": STATUS_CODES[status],
                       "keyframe": bool(result.keyframe), "features": result.features, "inliers": result.inliers,
                       "reason": reason, "recognised_keyframe": result.recognised_keyframe})
        share = f"{result.inliers}/{result.features}"
        print(f"{index:>5}  {name:<28} {status:<10} {share:>16} {result.milliseconds:>7.0f}"
              + (f"  {reason}" if reason else "") + _place_note(result), flush=True)
        if index == 1 and features is not None:
            matches, agreeing = tracker.given_pair_agreement
            if matches >= _AGREEMENT_MIN_MATCHES and agreeing < _AGREEMENT_MIN_FRACTION * matches:
                print(f"{PROGRAM}: warning: of {matches} matches between frames 0 and 1 only {agreeing} agree with "
                      "their given poses: are the images in the poses' order, and the calibration theirs?",
                      file=sys.stderr)

    index = 0
    for stamp, name, image in source:
        features = None
        if image is None:
            outcome = "its given pose is kept, without features" if index < len(given) else "lost"
            print(f"{PROGRAM}: frame {index} ({name}): cannot be read or decoded; {outcome}", file=sys.stderr)
        else:
            check_image_fits(K, image.shape, index, name, args.calib)
            # The tracker undistorts the features with dist: they are extracted without it.
            features = images.extract_features(image, K, options=feature_options)
        if tracker is None:
            if features is None:
                waiting.append((index, stamp, name))
                index += 1
                continue
            start(image.shape)
            for w in waiting:
                track(*w, None)
        track(index, stamp, name, features)
        index += 1
    if tracker is None:
        raise InputError(f"--images {args.images}: none of its {index} frame(s) can be read or decoded")
    if args.poses is not None and len(given) > len(frames):
        print(f"{args.poses}: {len(given)} poses for {len(frames)} frames; the rest are not used.")

    _write_outputs(args, pixel_scale, options, frames, tracker.trajectory())
    return 0


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The program: exit status 0 when the sequence was tracked (frames may be lost), 1 on bad input
    (the message on stderr names the option, file, key or frame; nothing is written)."""
    args = _parser().parse_args(argv)
    try:
        return run(args)
    except InputError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 1
    except ImportError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
