"""Shared helpers of the Python tests: locating the built tools, making scenes with them, reading and
writing problem files, running tripose_estimate and checking its rejections."""
import importlib
import os
import struct
import subprocess
import sys
from pathlib import Path

import cv2
import numpy as np

REPO = Path(__file__).resolve().parents[2]


def build_dir():
    return Path(os.environ.get("TRIPOSE_BUILD_DIR", REPO / "build"))


def build_tool(name, folder="samples"):
    """Path of a built tool (a sample, or under `folder` of the build); a missing tool is an error,
    never a skip (the test command builds them all)."""
    path = build_dir() / folder / name
    if not path.exists():
        raise FileNotFoundError(f"{path} is not built; run scripts/test.sh or set TRIPOSE_BUILD_DIR")
    return path


def require_modules(*names):
    """Imports the Python packages a test needs; a missing one is an error, never a skip
    (requirements/python.txt pins them all)."""
    for name in names:
        try:
            importlib.import_module(name)
        except ImportError as e:
            raise ImportError(f"{name} is not installed; pip install -r requirements/python.txt") from e


def make_scene(tmp_path, points, lines, seed, noise=0.0, outliers=0.0, motion="large"):
    """A synthetic problem file with ground truth, written by tripose_make_scene."""
    out = Path(tmp_path) / f"scene_{points}p{lines}l_{seed}.yml"
    subprocess.run([str(build_tool("tripose_make_scene")), "--points", str(points), "--lines", str(lines),
                    "--motion", motion, "--noise", str(noise), "--outliers", str(outliers),
                    "--seed", str(seed), "--output", str(out)], check=True, capture_output=True, timeout=60)
    return out


def make_stereo_scene(tmp_path, points, lines, seed, noise=0.0, outliers=0.0, missing=0.0):
    """A synthetic stereo-rig problem file with ground truth, written by tripose_make_scene --stereo."""
    out = Path(tmp_path) / f"stereo_{points}p{lines}l_{seed}_{missing}.yml"
    subprocess.run([str(build_tool("tripose_make_scene")), "--stereo", "--points", str(points), "--lines", str(lines),
                    "--noise", str(noise), "--outliers", str(outliers), "--missing", str(missing),
                    "--seed", str(seed), "--output", str(out)], check=True, capture_output=True, timeout=60)
    return out


def rotation_error(A, B):
    """Angle (rad) of A B^T, accurate near zero."""
    d = np.linalg.norm(np.asarray(A) - np.asarray(B)) / (2.0 * np.sqrt(2.0))
    return 2.0 * np.arcsin(min(1.0, d))


def read_matrices(path, keys):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    out = {k: fs.getNode(k).mat() for k in keys if not fs.getNode(k).empty()}
    fs.release()
    return out


def write_problem(path, values):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    for key, value in values.items():
        if isinstance(value, str):
            fs.write(key, value)
        else:
            fs.write(key, np.asarray(value, dtype=np.float64))
    fs.release()


def run(*args):
    """tripose_estimate with these arguments."""
    return subprocess.run([str(build_tool("tripose_estimate")), *map(str, args)], capture_output=True, text=True,
                          timeout=60)


def estimate(tmp_path, problem, *extra, name="result.yml"):
    out = tmp_path / name
    proc = run("--input", problem, "--output", out, *extra)
    return proc, out


def setter(key, value):
    """A change that puts `value(values)` (or `value`) under `key`."""
    return lambda v: v.__setitem__(key, value(v) if callable(value) else value)


def edited(key, row, col, x):
    """A change that sets one element of the matrix under `key`."""
    def change(v):
        m = v[key].copy()
        m[row, col] = x
        v[key] = m
    return change


def all_of(*changes):
    def change(v):
        for c in changes:
            c(v)
    return change


def files_in(folder):
    return sorted(p.name for p in folder.iterdir())


def expect_rejected(tmp_path, problem, names, *extra):
    """Non-zero exit, stderr names the key or argument, and nothing written: neither the result
    nor a partial file."""
    before = files_in(tmp_path)
    proc, out = estimate(tmp_path, problem, *extra)
    assert proc.returncode != 0, proc.stdout
    assert names in proc.stderr, proc.stderr
    assert not out.exists()
    assert files_in(tmp_path) == before


def write_turned_jpeg(image, path):
    """@p image stored as a phone stores a portrait photo: turned a quarter counter-clockwise, with the
    EXIF orientation 6 ("turn 90 degrees clockwise to view") that makes a reader turn it back."""
    ok, jpeg = cv2.imencode(".jpg", cv2.rotate(image, cv2.ROTATE_90_COUNTERCLOCKWISE), [cv2.IMWRITE_JPEG_QUALITY, 95])
    assert ok
    # A big-endian TIFF header and one IFD entry: tag 0x0112 (Orientation), SHORT, count 1, value 6.
    tiff = b"MM\x00\x2a" + struct.pack(">I", 8) + struct.pack(">H", 1) + struct.pack(">HHIHH", 0x0112, 3, 1, 6, 0) \
        + struct.pack(">I", 0)
    exif = b"Exif\x00\x00" + tiff
    jpeg = jpeg.tobytes()
    Path(path).write_bytes(jpeg[:2] + b"\xff\xe1" + struct.pack(">H", len(exif) + 2) + exif + jpeg[2:])
    return path


MERTON = REPO / "test" / "data" / "vgg" / "Merton-College-I"
MERTON_CALIB = REPO / "test" / "data" / "images" / "merton_college_i_calib.yml"


def enlarged_merton(folder, factor, suffix=".png", write_params=(cv2.IMWRITE_PNG_COMPRESSION, 1)):
    """The bundled Merton College I triplet enlarged @p factor times (bicubic) into @p folder, and its
    calibration, whose K puts the original's pixel centre x at factor x + (factor - 1) / 2:
    (calibration path, image paths)."""
    values = read_matrices(MERTON_CALIB, ["K1", "K2", "K3", "R12", "t12"])
    offset = (factor - 1) / 2
    to_enlarged = np.array([[factor, 0, offset], [0, factor, offset], [0, 0, 1]])
    for k in (1, 2, 3):
        values[f"K{k}"] = to_enlarged @ values[f"K{k}"]
    calib = Path(folder) / "calib.yml"
    write_problem(calib, values)
    images = []
    for k in (1, 2, 3):
        images.append(Path(folder) / f"enlarged{k}{suffix}")
        image = cv2.resize(cv2.imread(str(MERTON / f"00{k}.jpg")), None, fx=factor, fy=factor,
                           interpolation=cv2.INTER_CUBIC)
        cv2.imwrite(str(images[-1]), image, list(write_params))
    return calib, images


def merton_greys_in_bits(folder, bits):
    """The bundled Merton College I triplet's grey images stored as a camera of @p bits bits per pixel
    stores them in 16-bit PNGs (grey level g as g 2^(bits - 8) + 2^(bits - 8) - 1, so that the
    darkest pixel is not 0), and the same greys as 8-bit PNGs: (deeper image paths, 8-bit image
    paths). The greys span 0-255, so a reader that stretches a deeper image from its lowest to its
    highest value gets the 8-bit images back exactly; one that ignores the lowest does not."""
    deeper, eight = [], []
    step = 1 << (bits - 8)
    for k in (1, 2, 3):
        grey = cv2.imread(str(MERTON / f"00{k}.jpg"), cv2.IMREAD_GRAYSCALE)
        assert grey.min() == 0 and grey.max() == 255
        deeper.append(Path(folder) / f"grey{k}_{bits}bit.png")
        eight.append(Path(folder) / f"grey{k}_8bit.png")
        assert cv2.imwrite(str(deeper[-1]), (grey.astype(np.uint16) * step + step - 1).astype(np.uint16))
        assert cv2.imwrite(str(eight[-1]), grey)
    return deeper, eight


def write_nan_tiff(path):
    """The third Merton image as a float TIFF with one NaN pixel."""
    image = cv2.imread(str(MERTON / "003.jpg"), cv2.IMREAD_GRAYSCALE).astype(np.float32)
    image[10, 20] = np.nan
    assert cv2.imwrite(str(path), image)
    return path


def write_inverted_pose_calibration(path):
    """The Merton calibration with view 2's pose given as its inverse, the usual convention mistake."""
    values = read_matrices(MERTON_CALIB, ["K1", "K2", "K3", "R12", "t12"])
    values["R12"], values["t12"] = values["R12"].T, -values["R12"].T @ values["t12"]
    write_problem(path, values)
    return path


def run_with_peak_memory(command, timeout=None):
    """The exit status, output and peak resident memory (MiB) of @p command, run from a fresh Python so
    that no earlier child counts."""
    probe = ("import resource, subprocess, sys; p = subprocess.run(sys.argv[1:], capture_output=True, text=True); "
             "print(p.returncode); print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024); "
             "print(p.stdout + p.stderr)")
    proc = subprocess.run([sys.executable, "-c", probe, *map(str, command)], capture_output=True, text=True,
                          timeout=timeout)
    status, peak, output = proc.stdout.split("\n", 2)
    return int(status), float(peak), output


def offsets_to_nearest(points, reference):
    """Each of @p points (N x 2) minus the nearest of @p reference (M x 2)."""
    matches = cv2.BFMatcher(cv2.NORM_L2).match(points.astype(np.float32), reference.astype(np.float32))
    return np.array([points[m.queryIdx] - reference[m.trainIdx] for m in matches])
