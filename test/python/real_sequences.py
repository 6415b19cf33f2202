"""Readers for the real-image benchmark sequences with ground-truth cameras (Strecha fountain-P11 and
Herz-Jesus-P8, Middlebury templeRing, a few KITTI 06 frames) and helpers to compare poses.

The data lives outside the repository, in shared/data/real-images beside the checkout (../shared, as
on the CI clone), or wherever the environment variable TRIPOSE_REAL_IMAGES points; its PROVENANCE.txt
describes every file format read here.

Every reader returns a Sequence in the project's convention: x_cam = R X + t (world to camera), R an
exact rotation (the nearest one to the printed matrix), views in ring or temporal order.
"""
from __future__ import annotations

import math
import os
import struct
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]

# The ring order of templeRing as PROVENANCE.txt lists it: temple_ring() derives the order from the
# cameras and refuses data that disagrees with this list.
TEMPLE_RING_ORDER = ([34, 33, 32, 47, 46, 45, 44, 43, 42] + list(range(13, 31)) + [1, 31, 2, 3, 4, 5, 41, 40]
                     + list(range(6, 13)) + [39, 38, 37, 36, 35])

KITTI_FORWARD_FRAMES = (12, 13, 14, 17)
KITTI_STEREO_FRAME = 12


@dataclass
class Sequence:
    """Views of one scene: view i is image_paths[i] taken by a camera K[i] at [R[i] | t[i]]
    (x_cam = R X + t, t of shape (3,)); ids[i] names the view in the data set (file or frame number)."""
    name: str
    image_paths: list
    K: list
    R: list
    t: list
    width: int
    height: int
    ids: list = field(default_factory=list)

    def __len__(self):
        return len(self.image_paths)

    def centres(self):
        """The camera centres in the world, (N, 3)."""
        return np.array([camera_centre(R, t) for R, t in zip(self.R, self.t)])

    def subset(self, indices, name=None):
        """The views at `indices`, in that order."""
        indices = list(indices)
        return Sequence(name or self.name, [self.image_paths[i] for i in indices], [self.K[i] for i in indices],
                        [self.R[i] for i in indices], [self.t[i] for i in indices], self.width, self.height,
                        [self.ids[i] for i in indices] if self.ids else [])


class DataMissing(FileNotFoundError):
    pass


def data_dir():
    """The folder of the real-image data sets: $TRIPOSE_REAL_IMAGES, else ../shared/data/real-images
    beside the repository. A missing folder is an error that says where the data was looked for."""
    env = os.environ.get("TRIPOSE_REAL_IMAGES")
    folder = Path(env) if env else REPO.parent / "shared" / "data" / "real-images"
    if not (folder / "PROVENANCE.txt").is_file():
        raise DataMissing(f"the real-image data is not at {folder} (no PROVENANCE.txt there): put shared/ beside "
                          "the checkout or set TRIPOSE_REAL_IMAGES to the folder")
    return folder


# --- geometry --------------------------------------------------------------------------------------

def nearest_rotation(M):
    """The rotation closest to M in the Frobenius norm (M's polar factor, with determinant +1)."""
    U, _, Vt = np.linalg.svd(np.asarray(M, np.float64))
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))])
    return U @ D @ Vt


def camera_centre(R, t):
    """The centre of the camera x_cam = R X + t in the world: -R^T t."""
    return -np.asarray(R).T @ np.asarray(t, np.float64).reshape(3)


def rotation_error_deg(Ra, Rb):
    """The angle (degrees) of the rotation Ra Rb^T, accurate near zero (from the chord ||Ra - Rb||)."""
    chord = np.linalg.norm(np.asarray(Ra, np.float64) - np.asarray(Rb, np.float64)) / (2.0 * math.sqrt(2.0))
    return math.degrees(2.0 * math.asin(min(1.0, chord)))


def position_error(Ra, ta, Rb, tb):
    """The distance between the centres of the cameras [Ra | ta] and [Rb | tb]."""
    return float(np.linalg.norm(camera_centre(Ra, ta) - camera_centre(Rb, tb)))


def path_length(Rs, ts):
    """The length of the polyline through the camera centres of the poses, in order."""
    centres = np.array([camera_centre(R, t) for R, t in zip(Rs, ts)])
    return float(np.linalg.norm(np.diff(centres, axis=0), axis=1).sum()) if len(centres) > 1 else 0.0


def relative_pose(Ra, ta, Rb, tb):
    """The pose of camera b in camera a's frame: x_b = R x_a + t."""
    R = np.asarray(Rb) @ np.asarray(Ra).T
    return R, np.asarray(tb, np.float64).reshape(3) - R @ np.asarray(ta, np.float64).reshape(3)


def relative_to_first(seq):
    """The sequence with its world moved to the first camera's frame (view 0 at R = I, t = 0); lengths
    stay in the data set's unit."""
    poses = [relative_pose(seq.R[0], seq.t[0], R, t) for R, t in zip(seq.R, seq.t)]
    return Sequence(seq.name, list(seq.image_paths), list(seq.K), [p[0] for p in poses], [p[1] for p in poses],
                    seq.width, seq.height, list(seq.ids))


def fundamental_matrix(K1, R1, t1, K2, R2, t2):
    """F with x2^T F x1 = 0 for the pixels x1, x2 of one point in cameras K1 [R1 | t1], K2 [R2 | t2]."""
    R, t = relative_pose(R1, t1, R2, t2)
    tx = np.array([[0, -t[2], t[1]], [t[2], 0, -t[0]], [-t[1], t[0], 0]])
    return np.linalg.inv(K2).T @ tx @ R @ np.linalg.inv(K1)


# --- readers ---------------------------------------------------------------------------------------

def _png_size(path):
    """(width, height) from a PNG's header."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise ValueError(f"{path}: not a PNG file")
    return struct.unpack(">II", head[16:24])


def _numbers(path):
    rows = []
    for line in Path(path).read_text().splitlines():
        if line.strip() and not line.lstrip().startswith("#"):
            rows.append(line.split())
    return rows


def read_strecha_camera(path):
    """K, R (world to camera), t and (width, height) of a Strecha gt_dense_cameras/*.camera file, whose
    rotation is camera-to-world and whose line 8 is the camera centre C: x ~ K R_file^T (X - C)."""
    values = [float(v) for row in _numbers(path) for v in row]
    if len(values) != 26:
        raise ValueError(f"{path}: expected 26 numbers (K, distortion, R, C, width height), found {len(values)}")
    K = np.array(values[0:9]).reshape(3, 3)
    R = nearest_rotation(np.array(values[12:21]).reshape(3, 3).T)
    C = np.array(values[21:24])
    return K, R, -R @ C, (int(values[24]), int(values[25]))


def _strecha(folder_name, name):
    folder = data_dir() / folder_name
    cameras = sorted((folder / "gt_dense_cameras").glob("*.jpg.camera"))
    if not cameras:
        raise DataMissing(f"{folder}/gt_dense_cameras holds no *.jpg.camera files")
    seq = Sequence(name, [], [], [], [], 0, 0, [])
    for path in cameras:
        image = folder / "images" / path.name[:-len(".camera")]
        if not image.is_file():
            raise DataMissing(f"{image}: missing (its camera is {path})")
        K, R, t, size = read_strecha_camera(path)
        seq.image_paths.append(image)
        seq.K.append(K)
        seq.R.append(R)
        seq.t.append(t)
        seq.ids.append(image.stem)
        seq.width, seq.height = size
    return seq


def fountain_p11():
    """Strecha's fountain-P11: 11 views, 3072 x 2048, in file order (neighbouring viewpoints); metres."""
    return _strecha("strecha-fountain-P11", "fountain-P11")


def herz_jesus_p8():
    """Strecha's Herz-Jesus-P8: 8 views, 3072 x 2048, in file order (neighbouring viewpoints); metres."""
    return _strecha("strecha-Herz-Jesus-P8", "Herz-Jesus-P8")


def read_middlebury_par(path):
    """{file name: (K, R, t)} of a Middlebury *_par.txt (first line the count, then
    "name k11..k33 r11..r33 t1 t2 t3" with P = K [R | t])."""
    rows = _numbers(path)
    count = int(rows[0][0])
    cameras = {}
    for row in rows[1:]:
        if len(row) != 22:
            raise ValueError(f"{path}: a camera line has {len(row)} fields, expected 22: {' '.join(row[:2])} ...")
        values = np.array([float(v) for v in row[1:]])
        cameras[row[0]] = (values[0:9].reshape(3, 3), nearest_rotation(values[9:18].reshape(3, 3)), values[18:21])
    if len(cameras) != count:
        raise ValueError(f"{path}: announces {count} cameras, holds {len(cameras)}")
    return cameras


def ring_order(centres, viewing_directions):
    """Indices of cameras on a ring in the order of their azimuth about the ring's centre (the mean of
    the centres), counter-clockwise (right-hand rule) about the ring's axis pointed against the cameras'
    viewing directions, and the azimuth (degrees) of each; cameras at the same azimuth (within 1e-6 degrees) keep a fixed
    order, the higher index first."""
    centres = np.asarray(centres, np.float64)
    offsets = centres - centres.mean(axis=0)
    _, _, Vt = np.linalg.svd(offsets)
    axis = -Vt[2] if np.mean(np.asarray(viewing_directions) @ Vt[2]) > 0 else Vt[2]
    e1 = Vt[0]
    e2 = np.cross(axis, e1)
    azimuth = np.degrees(np.arctan2(offsets @ e2, offsets @ e1))
    order = sorted(range(len(centres)), key=lambda i: (round(float(azimuth[i]), 6), -i))
    return order, azimuth


def temple_ring(start=34):
    """Middlebury templeRing, 47 views of 640 x 480 in ring order starting at file `start` (34, as
    PROVENANCE.txt lists the ring). The order is derived from the cameras' azimuth and checked against
    TEMPLE_RING_ORDER; a mismatch is an error. Units are the data set's (metres)."""
    folder = data_dir() / "middlebury-templeRing"
    cameras = read_middlebury_par(folder / "templeR_par.txt")
    names = sorted(cameras)
    numbers = [int(Path(n).stem[len("templeR"):]) for n in names]
    centres = [camera_centre(cameras[n][1], cameras[n][2]) for n in names]
    order, _ = ring_order(centres, [cameras[n][1][2] for n in names])
    ring = [numbers[i] for i in order]
    first = ring.index(start)
    ring = ring[first:] + ring[:first]
    documented = TEMPLE_RING_ORDER[TEMPLE_RING_ORDER.index(start):] + TEMPLE_RING_ORDER[:TEMPLE_RING_ORDER.index(start)]
    if ring != documented:
        raise ValueError(f"{folder}: the cameras' ring order {ring} is not the one PROVENANCE.txt lists {documented}")
    seq = Sequence("templeRing", [], [], [], [], 0, 0, [])
    for number in ring:
        name = names[numbers.index(number)]
        K, R, t = cameras[name]
        image = folder / name
        if not image.is_file():
            raise DataMissing(f"{image}: missing")
        seq.image_paths.append(image)
        seq.K.append(K)
        seq.R.append(R)
        seq.t.append(t)
        seq.ids.append(number)
        seq.width, seq.height = _png_size(image)
    return seq


def read_kitti_calib(path):
    """{"P0": 3x4, ...} of a KITTI calib.txt ("P0: p11 .. p34")."""
    out = {}
    for row in _numbers(path):
        key = row[0].rstrip(":")
        out[key] = np.array([float(v) for v in row[1:]]).reshape(3, 4)
    return out


def read_kitti_poses(path):
    """{frame: (R, t)} (world to cam0, x_cam0 = R X + t) of the poses.txt of kitti-06-frames, whose rows
    are "frame" then the row-major 3x4 [Rw | tw] with x_world = [Rw | tw] x_cam0."""
    out = {}
    for row in _numbers(path):
        if len(row) != 13:
            raise ValueError(f"{path}: a pose line has {len(row)} fields, expected 13 (frame and 12 numbers)")
        M = np.array([float(v) for v in row[1:]]).reshape(3, 4)
        Rw = nearest_rotation(M[:, :3])
        out[int(row[0])] = (Rw.T, -Rw.T @ M[:, 3])
    return out


def kitti_camera(P):
    """K and the offset o of a rectified KITTI camera P = K [I | o] in cam0's frame: x_cam = x_cam0 + o."""
    K = P[:, :3] / P[2, 2]
    return K, np.linalg.solve(K, P[:, 3] / P[2, 2])


# The image files of each KITTI camera of kitti-06-frames, by frame number.
KITTI_IMAGE_NAMES = {0: "kitti06-{:02d}.png", 1: "kitti06-{:02d}-R.png", 2: "kitti06-{:02d}-color.png",
                     3: "kitti06-{:02d}-R-color.png"}


def _kitti_view(folder, calib, poses, frame, camera):
    image = folder / KITTI_IMAGE_NAMES[camera].format(frame)
    if not image.is_file():
        raise DataMissing(f"{image}: missing (camera {camera} at frame {frame})")
    if frame not in poses:
        raise DataMissing(f"{folder / 'poses.txt'}: no pose for frame {frame}")
    K, offset = kitti_camera(calib[f"P{camera}"])
    R, t = poses[frame]
    return image, K, R, t + offset


def _kitti(name, views):
    folder = data_dir() / "kitti-06-frames"
    calib = read_kitti_calib(folder / "calib.txt")
    poses = read_kitti_poses(folder / "poses.txt")
    seq = Sequence(name, [], [], [], [], 0, 0, [])
    for frame, camera in views:
        image, K, R, t = _kitti_view(folder, calib, poses, frame, camera)
        seq.image_paths.append(image)
        seq.K.append(K)
        seq.R.append(R)
        seq.t.append(t)
        seq.ids.append(f"{frame}" if camera == 0 else f"{frame}-cam{camera}")
        seq.width, seq.height = _png_size(image)
    return seq


def kitti_06_forward(frames=KITTI_FORWARD_FRAMES, camera=2):
    """KITTI 06 frames 12, 13, 14, 17 of one left camera (1226 x 370, about 1.2 m apart, driving
    forward); metres, KITTI's world (cam0 at frame 0). The left colour camera (cam2) is the default
    because it is the only camera with an image at all four frames (the grey cam0, camera=0, lacks
    frame 17); its K is P2's (the same intrinsics as P0) and its pose is cam0's shifted by P2's offset."""
    return _kitti(f"kitti-06-forward-cam{camera}", [(frame, camera) for frame in frames])


def kitti_06_stereo(frame=KITTI_STEREO_FRAME):
    """The rectified grey stereo pair of KITTI 06 at frame 12: view 0 the left camera (cam0, K from P0),
    view 1 the right (cam1, K from P1), 0.537 m apart along x; relative_to_first() gives the rig
    (R = I, t = (-0.537, 0, 0): x_cam1 = x_cam0 + t)."""
    return _kitti(f"kitti-06-stereo-{frame}", [(frame, 0), (frame, 1)])


def vgg_dir():
    """The folder of the VGG multi-view sequences: $TRIPOSE_VGG_MULTIVIEW, else ../shared/data/vgg-multiview
    beside the repository."""
    env = os.environ.get("TRIPOSE_VGG_MULTIVIEW")
    folder = Path(env) if env else REPO.parent / "shared" / "data" / "vgg-multiview"
    if not (folder / "PROVENANCE.txt").is_file():
        raise DataMissing(f"the VGG multi-view data is not at {folder} (no PROVENANCE.txt there): put shared/ "
                          "beside the checkout or set TRIPOSE_VGG_MULTIVIEW to the folder")
    return folder


def _vgg_table(folder, name):
    """Rows of a VGG table named `name` or `<prefix>.name` in `folder`; '*' read as None."""
    paths = [folder / name] + sorted(folder.glob(f"*.{name}"))
    paths = [p for p in paths if p.is_file()]
    if not paths:
        raise DataMissing(f"{folder}: no {name} file")
    return [[None if v == "*" else float(v) for v in row] for row in _numbers(paths[0])]


def decompose_vgg_camera(P, points):
    """K (K[2, 2] = 1, positive diagonal), R and t of a VGG camera matrix P = lambda K [R | t], and whether
    its world frame is mirrored: P's sign is chosen so that most of `points` (the 3D points the view sees,
    (N, 3)) are in front of it; a mirrored world (det P[:, :3] < 0 then) is read with its Z axis flipped, so
    that R and t map Z-flipped world points."""
    import cv2

    P = np.asarray(P, np.float64).copy()
    X = np.hstack([np.asarray(points, np.float64).reshape(-1, 3), np.ones((len(points), 1))])
    if np.count_nonzero(X @ P[2] > 0) < np.count_nonzero(X @ P[2] < 0):
        P = -P
    mirrored = bool(np.linalg.det(P[:, :3]) < 0)
    if mirrored:
        P[:, 2] = -P[:, 2]
    K, R, C = cv2.decomposeProjectionMatrix(P)[:3]
    # The decomposition is unique up to the signs of K's diagonal: make them positive.
    signs = np.diag(np.sign(np.diag(K)))
    K, R = K @ signs, signs @ R
    if np.linalg.det(R) < 0 or K[2, 2] <= 0:
        raise ValueError(f"P: not a camera in front of its points ({P.tolist()})")
    C = C[:3, 0] / C[3, 0]
    R = nearest_rotation(R)
    return K / K[2, 2], R, -R @ C, mirrored


def vgg_sequence(name):
    """A VGG multi-view sequence with images (Model-House: 10 views of 768 x 576; Merton-College-I: 3 of
    1024 x 768), cameras from its .P files (each view its own K), in file order. A mirrored world frame
    (Model House's) is read Z-flipped; units are the data set's."""
    folder = vgg_dir() / name
    cameras = sorted(folder.glob("*.P"))
    if not cameras:
        raise DataMissing(f"{folder}: no *.P camera files")
    points = np.array(_vgg_table(folder, "p3d"))
    seen = _vgg_table(folder, "nview-corners")
    seq = Sequence(name, [], [], [], [], 0, 0, [])
    handedness = set()
    import cv2

    for view, path in enumerate(cameras):
        images = [path.with_suffix(s) for s in (".pgm", ".jpg", ".png") if path.with_suffix(s).is_file()]
        if not images:
            raise DataMissing(f"{path}: no image beside it (.pgm, .jpg or .png)")
        P = np.array(_vgg_table(folder, path.name))
        if P.shape != (3, 4):
            raise ValueError(f"{path}: expected 3 rows of 4 numbers")
        rows = [i for i, row in enumerate(seen) if row[view] is not None]
        K, R, t, mirrored = decompose_vgg_camera(P, points[rows])
        handedness.add(mirrored)
        image = cv2.imread(str(images[0]), cv2.IMREAD_UNCHANGED)
        if image is None:
            raise ValueError(f"{images[0]}: cannot be read")
        seq.image_paths.append(images[0])
        seq.K.append(K)
        seq.R.append(R)
        seq.t.append(t)
        seq.ids.append(path.stem)
        seq.height, seq.width = image.shape[:2]
    if len(handedness) > 1:
        raise ValueError(f"{folder}: some cameras see a mirrored world frame and some do not")
    return seq


def model_house():
    """VGG Model House from its 10 images (768 x 576)."""
    return vgg_sequence("Model-House")


def merton_college_1():
    """VGG Merton College I from its 3 images (1024 x 768)."""
    return vgg_sequence("Merton-College-I")


# --- output ----------------------------------------------------------------------------------------

def write_calibration_yaml(path, K, dist=None, **poses):
    """Writes a calibration in the problem-file keys the tools read (OpenCV YAML): K (one 3x3 matrix, or
    a list written as K1, K2, ...), dist when given (one vector, or a list written as dist1, ...), and
    every keyword as its own key: a rotation (3x3) as is, a translation or other vector as a column,
    e.g. write_calibration_yaml(p, K, R12=R, t12=t) or (p, K, R0=..., t0=..., R1=..., t1=...)."""
    import cv2

    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    if not fs.isOpened():
        raise OSError(f"{path}: cannot be written")

    def matrix(value):
        m = np.asarray(value, np.float64)
        return m.reshape(-1, 1) if m.ndim == 1 or (m.ndim == 2 and 1 in m.shape and m.shape != (3, 3)) else m

    def many(key, value):
        if isinstance(value, (list, tuple)):
            for i, v in enumerate(value, 1):
                fs.write(f"{key}{i}", matrix(v))
        else:
            fs.write(key, matrix(value))

    many("K", K)
    if dist is not None:
        many("dist", dist)
    for key, value in poses.items():
        fs.write(key, matrix(value))
    fs.release()


# --- TUM trajectories --------------------------------------------------------------------------------

def rotation_to_quaternion(R):
    """The unit quaternion (qx, qy, qz, qw) of the rotation R (Hamilton convention), qw >= 0."""
    R = np.asarray(R, np.float64)
    trace = np.trace(R)
    # The largest of the four squared components is computed first: the others follow without
    # dividing by a number near zero.
    squares = np.array([1 + 2 * R[0, 0] - trace, 1 + 2 * R[1, 1] - trace, 1 + 2 * R[2, 2] - trace, 1 + trace])
    k = int(np.argmax(squares))
    q = np.empty(4)
    q[k] = 0.5 * math.sqrt(max(squares[k], 0.0))
    f = 0.25 / q[k]
    if k == 3:
        q[0], q[1], q[2] = (R[2, 1] - R[1, 2]) * f, (R[0, 2] - R[2, 0]) * f, (R[1, 0] - R[0, 1]) * f
    elif k == 0:
        q[1], q[2], q[3] = (R[0, 1] + R[1, 0]) * f, (R[0, 2] + R[2, 0]) * f, (R[2, 1] - R[1, 2]) * f
    elif k == 1:
        q[0], q[2], q[3] = (R[0, 1] + R[1, 0]) * f, (R[1, 2] + R[2, 1]) * f, (R[0, 2] - R[2, 0]) * f
    else:
        q[0], q[1], q[3] = (R[0, 2] + R[2, 0]) * f, (R[1, 2] + R[2, 1]) * f, (R[1, 0] - R[0, 1]) * f
    q /= np.linalg.norm(q)
    return q if q[3] >= 0 else -q


def quaternion_to_rotation(q):
    """The rotation of the quaternion (qx, qy, qz, qw) (Hamilton convention; normalised first)."""
    x, y, z, w = np.asarray(q, np.float64) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def write_tum(path, timestamps, Rs, ts):
    """Writes poses x_cam = R X + t as a TUM trajectory: one line "timestamp tx ty tz qx qy qz qw" per
    pose, the camera's pose in the world (position -R^T t, orientation the quaternion of R^T)."""
    if not len(timestamps) == len(Rs) == len(ts):
        raise ValueError(f"{len(timestamps)} timestamps, {len(Rs)} rotations and {len(ts)} translations")
    lines = ["# timestamp tx ty tz qx qy qz qw"]
    for stamp, R, t in zip(timestamps, Rs, ts):
        R = np.asarray(R, np.float64)
        values = [*camera_centre(R, t), *rotation_to_quaternion(R.T)]
        lines.append(f"{float(stamp):.9f} " + " ".join(f"{v:.17g}" for v in values))
    Path(path).write_text("\n".join(lines) + "\n")


def read_tum(path):
    """(timestamps, Rs, ts) of a TUM trajectory, the poses as x_cam = R X + t (write_tum()'s inverse).
    Lines starting with # and blank lines are skipped."""
    timestamps, Rs, ts = [], [], []
    for number, line in enumerate(Path(path).read_text().splitlines(), 1):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        if len(fields) != 8:
            raise ValueError(f"{path}:{number}: expected 8 numbers (timestamp tx ty tz qx qy qz qw), "
                             f"found {len(fields)}")
        values = [float(v) for v in fields]
        R = quaternion_to_rotation(values[4:8]).T
        timestamps.append(values[0])
        Rs.append(R)
        ts.append(-R @ np.array(values[1:4]))
    return np.array(timestamps), Rs, ts
