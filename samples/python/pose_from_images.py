#!/usr/bin/env python3
"""The pose of a third camera from three images, in Python: the steps of the C++ sample
tripose_images with OpenCV's Python bindings (opencv-contrib-python: SIFT, the EDLines segments of
ximgproc fitted to their edges, LBD of line_descriptor), the estimate from the tripose package.

    pose_from_images.py --calib calib.yml --images a.png b.png c.png --output result.yml
                        [--features points|lines|all] [--threshold px] [--max-image-size px]
                        [--problem-only]

calib.yml holds the calibration keys of a problem file: K or K1..K3, optional dist or
dist1..dist3, R12, t12 (view 2's pose; view 1 is the world frame). The result holds R, t,
num_inliers, point_inliers, line_inliers, rms, the numbers of point tracks and segment triplets,
pixel_scale, threshold and loss_scale (the estimate's tolerances in the images' pixels), and the
matched features as a problem (K.., R12, t12, points1..3, lines1..3, in undistorted
pixels). With --problem-only the matched problem is written without an estimate (the tripose
package is then not needed; tripose_estimate solves the file). Images larger than --max-image-size
(default 1600 px on the longer side; 0: no limit) are detected in a reduced copy: the positions
come back in the images' pixels, and the pixel tolerances (--threshold among them) grow by the
reduction. Images of more than 8 bits (16-bit PNG or TIFF, float TIFF) are stretched from their
lowest to their highest value onto 8 bits.

Exit status: 0 on success, 1 on bad input (the message names the file, key or argument), 2 when the
tripose package is missing, 3 when no reliable pose is found (fewer than MIN_INLIERS inliers, the
robust estimators' default floor); nothing is written on 1, 2 or 3.
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import cv2
import numpy as np

MIN_FEATURES = 4  # the estimators need four features
MIN_INLIERS = 15  # the fewest inliers of a reliable pose: min_inliers of the robust estimators
SIFT_UPSAMPLING_OFFSET = 0.25  # px, see extract()
# Images whose longer side exceeds this (px) are detected in a copy reduced to it, as the C++
# samples' --max-image-size (samples/common/image_features.hpp): the scale space of a 12-megapixel
# image takes gigabytes and tens of seconds.
MAX_IMAGE_SIZE = 1600
# The refinement's Cauchy loss scale (px) for detected features, as the C++ samples
# (samples/common/image_estimation.hpp): it keeps the tail of poorly placed features from pulling.
IMAGE_LOSS_SCALE = 0.5


class InputError(Exception):
    pass


class SolverRejection(Exception):
    """The tripose package refused its input (its ValueError or TypeError names the argument)."""


def whole_number(text):
    """An integer written as the C++ samples read one (1600, 1.6e3)."""
    value = float(text)
    if not value.is_integer():
        raise ValueError(text)
    return int(value)


class ArgumentParser(argparse.ArgumentParser):
    """Bad arguments are bad input: exit status 1, as the C++ samples (argparse's own is 2, which
    this script gives to a missing tripose package)."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


# --- input ---------------------------------------------------------------------------------------

def check_writable(path, option):
    """Raises InputError naming option and path when the file cannot be written there, checked before
    the work as the C++ samples do (checkWritable(), samples/common/file_output.hpp): an existing file
    must be writable, a new one is created and removed."""
    path = Path(path)
    folder = path.parent
    if not folder.is_dir():
        raise InputError(f"{option} {path}: cannot be written (no folder {folder})")
    if path.is_dir():
        raise InputError(f"{option} {path}: cannot be written (a folder of that name exists)")
    if path.is_file():
        if not os.access(path, os.W_OK):
            raise InputError(f"{option} {path}: cannot be written (no permission)")
        return
    try:
        path.open("wb").close()
        path.unlink()
    except OSError:
        raise InputError(f"{option} {path}: cannot be written (no file can be created in {folder})") from None


def read_calibration(path):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ) if Path(path).is_file() else None
    if fs is None or not fs.isOpened():
        raise InputError(f"calibration {path}: cannot be read")

    def matrix(key):
        node = fs.getNode(key)
        return None if node.empty() else node.mat()

    def per_view(key, required):
        shared = matrix(key)
        views = [matrix(f"{key}{v}") for v in (1, 2, 3)]
        if shared is not None:
            return [shared] * 3
        if all(m is not None for m in views):
            return views
        if any(m is not None for m in views):
            missing = next(v for v, m in enumerate(views, 1) if m is None)
            raise InputError(f"calibration {path}: key '{key}{missing}': missing")
        if required:
            raise InputError(f"calibration {path}: key '{key}': missing (give {key} or {key}1..{key}3)")
        return None

    calib = {"K": per_view("K", True), "dist": per_view("dist", False)}
    for key, size in (("R12", (9, 3)), ("t12", (3,))):
        m = matrix(key)
        if m is None or m.size not in size:
            raise InputError(f"calibration {path}: key '{key}': " + ("missing" if m is None else "wrong size"))
        calib[key] = m
    if calib["R12"].size == 3:
        calib["R12"] = cv2.Rodrigues(calib["R12"])[0]
    calib["t12"] = calib["t12"].reshape(3, 1)
    # Views 1 and 2 are matched under their epipolar geometry and the structure is triangulated
    # between them: checked before the features' time is spent, as the solver would after it.
    if not np.linalg.norm(calib["t12"]) > 0:
        raise InputError(f"calibration {path}: key 't12': must be non-zero (views 1 and 2 need a baseline)")
    fs.release()
    return calib


def stretched_to_eight_bits(image, lowest, highest):
    """An image of more than 8 bits (16-bit PNG or TIFF, float TIFF) in 8 bits, its values from lowest
    to highest stretched onto 0-255, as the C++ samples (samples/common/image_input.cpp): keeping the
    top byte alone, as OpenCV's own conversion does, leaves a camera's 12 bits stored in 16 with 16
    grey levels, too few for SIFT."""
    scale = 255.0 / (float(highest) - float(lowest))
    return np.clip(np.rint((image.astype(np.float64) - float(lowest)) * scale), 0, 255).astype(np.uint8)


def read_image(path, K, key):
    if not Path(path).is_file():
        raise InputError(f"image {path}: no such file")
    image = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE | cv2.IMREAD_ANYDEPTH)
    if image is not None and image.dtype != np.uint8:
        # A deeper image is stretched in colour as a whole, then made grey, as the C++ samples do.
        image = cv2.imread(str(path), cv2.IMREAD_ANYCOLOR | cv2.IMREAD_ANYDEPTH)
    if image is None:
        raise InputError(f"image {path}: cannot be decoded")
    if not np.all(np.isfinite(image)):
        raise InputError(f"image {path}: holds values that are not finite numbers")
    lowest, highest = image.min(), image.max()
    if lowest == highest:
        raise InputError(f"image {path}: blank")
    if image.dtype != np.uint8:
        image = stretched_to_eight_bits(image, lowest, highest)
        if image.ndim == 3:
            image = cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)
    # The principal point of real cameras lies near the image centre; an image scaled against its
    # calibration moves it a quarter of the image or more away.
    h, w = image.shape
    cx, cy = K[0, 2] / K[2, 2], K[1, 2] / K[2, 2]
    if abs(cx - w / 2) > 0.2 * w or abs(cy - h / 2) > 0.2 * h:
        raise InputError(f"image {path} is {w}x{h} but the principal point of {key} is ({cx:.1f}, {cy:.1f}): "
                         "the calibration is for another image size")
    return image


# --- features ------------------------------------------------------------------------------------

def undistort(xy, K, dist):
    if dist is None or len(xy) == 0:
        return xy
    return cv2.undistortPoints(xy.reshape(-1, 1, 2), K, dist, P=K).reshape(-1, 2)


def fit_segments_to_edges(image, segments, end_margin=2.0, search=2, max_distance=1.0, min_peaks=5):
    """Each segment (N x 4) fitted to its edge and oriented with the brighter side on its right, as
    the C++ front end (samples/common/segment_edge_fit.hpp): at every pixel row (column) it crosses,
    the gradient's peak across it between pixels (parabola through three), peaks of the dominant
    polarity within max_distance px; then their total-least-squares line. Zero-length segments are
    dropped. The crossings of all segments are handled together, in numpy arrays (per-segment sums
    by np.bincount): a loop over segments took ten times as long."""
    smooth = cv2.GaussianBlur(image.astype(np.float32), (0, 0), 1.0)
    gx, gy = cv2.Sobel(smooth, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(smooth, cv2.CV_32F, 0, 1, ksize=3)
    segments = np.asarray(segments, np.float64).reshape(-1, 4)
    length = np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1])
    segments = segments[length > 0]
    length = length[length > 0]
    count = len(segments)
    if count == 0:
        return np.zeros((0, 4))
    p0, p1 = segments[:, :2], segments[:, 2:]
    u = (p1 - p0) / length[:, None]
    n = np.stack([-u[:, 1], u[:, 0]], axis=1)
    walk = np.where(np.abs(n[:, 0]) >= np.abs(n[:, 1]), 1, 0)  # walk rows (y, 1) or columns (x, 0)
    across = 1 - walk
    segment = np.arange(count)
    p0w, p1w, p0a = p0[segment, walk], p1[segment, walk], p0[segment, across]
    uw, ua, na = u[segment, walk], u[segment, across], n[segment, across]
    walk_extent = np.array(image.shape)[1 - walk]      # rows for a walk along y, columns along x
    across_extent = np.array(image.shape)[1 - across]
    margin = end_margin * np.abs(uw)
    first = np.maximum(np.ceil(np.minimum(p0w, p1w) + margin), 0).astype(int)
    last = np.minimum(np.floor(np.maximum(p0w, p1w) - margin), walk_extent - 1).astype(int)
    crossings = np.maximum(last - first + 1, 0)
    # One entry per crossed row (column): its segment s and its coordinate r along the walk.
    s = np.repeat(segment, crossings)
    r = first[s] + np.arange(len(s)) - np.repeat(np.cumsum(crossings) - crossings, crossings)
    centre = p0a[s] + (r - p0w[s]) / uw[s] * ua[s]
    k0 = np.rint(centre).astype(int)
    inside = (k0 - search - 1 >= 0) & (k0 + search + 1 < across_extent[s])
    s, r, centre, k0 = s[inside], r[inside], centre[inside], k0[inside]
    k = k0[:, None] + np.arange(-search - 1, search + 2)[None, :]
    along_y = (walk[s] == 1)[:, None]
    rows = np.where(along_y, r[:, None], k)
    cols = np.where(along_y, k, r[:, None])
    g = gx[rows, cols] * n[s, 0][:, None] + gy[rows, cols] * n[s, 1][:, None]
    best = 1 + np.argmax(np.abs(g[:, 1:-1]), axis=1)
    i = np.arange(len(s))
    left, mid, right = np.abs(g[i, best - 1]), np.abs(g[i, best]), np.abs(g[i, best + 1])
    curvature = left - 2 * mid + right
    ok = curvature < 0
    at = k0 - search - 1 + best + 0.5 * (left - right) / np.where(ok, curvature, -1.0)
    ok &= np.abs(at - centre) * np.abs(na[s]) <= max_distance
    positive = g[i, best] > 0
    brighter_on_right = 2 * np.bincount(s, positive & ok, count) >= np.bincount(s, ok, count)
    ok &= positive == brighter_on_right[s]
    peaks = np.bincount(s, ok, count)
    fitted = peaks >= min_peaks
    # Total least squares of each fitted segment's peaks (x, y): centroid and principal direction.
    s, r, at = s[ok], r[ok], at[ok]
    xy = np.zeros((len(s), 2))
    xy[np.arange(len(s)), walk[s]] = r
    xy[np.arange(len(s)), across[s]] = at
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.stack([np.bincount(s, xy[:, c], count) for c in (0, 1)], axis=1) / peaks[:, None]
    d = xy - mean[s]
    sxy, sxx, syy = (np.bincount(s, w, count) for w in (d[:, 0] * d[:, 1], d[:, 0] ** 2, d[:, 1] ** 2))
    angle = 0.5 * np.arctan2(2 * sxy, sxx - syy)
    direction = np.stack([np.cos(angle), np.sin(angle)], axis=1)
    direction *= np.where(np.sum(direction * u, axis=1) >= 0, 1.0, -1.0)[:, None]
    q0 = mean + np.sum((p0 - mean) * direction, axis=1, keepdims=True) * direction
    q1 = mean + np.sum((p1 - mean) * direction, axis=1, keepdims=True) * direction
    q0, q1 = np.where(fitted[:, None], q0, p0), np.where(fitted[:, None], q1, p1)
    return np.where(brighter_on_right[:, None], np.hstack([q0, q1]), np.hstack([q1, q0]))


def keyline(index, s, image_size):
    """A segment at full resolution as contrib's KeyLine, for LBD."""
    k = cv2.line_descriptor.KeyLine()
    k.startPointX, k.startPointY, k.endPointX, k.endPointY = map(float, s)
    k.sPointInOctaveX, k.sPointInOctaveY, k.ePointInOctaveX, k.ePointInOctaveY = map(float, s)
    k.lineLength = float(np.hypot(s[2] - s[0], s[3] - s[1]))
    k.numOfPixels = int(round(k.lineLength))
    k.angle = float(np.arctan2(s[3] - s[1], s[2] - s[0]))
    k.pt = (float(s[0] + s[2]) / 2, float(s[1] + s[3]) / 2)
    k.octave, k.class_id = 0, index
    k.response = k.lineLength / image_size
    k.size = float(abs((s[2] - s[0]) * (s[3] - s[1])))
    return k


def detection_scale(shape, max_size=MAX_IMAGE_SIZE):
    """How many of the image's pixels one pixel of the image its features are detected in spans (1 when
    the image is no larger than max_size, or max_size is 0): the factor of every pixel tolerance."""
    longer = max(shape[:2])
    return longer / max_size if 0 < max_size < longer else 1.0


def detection_image(image, max_size=MAX_IMAGE_SIZE):
    """The image the features are detected in (reduced by area averaging to max_size on its longer side)
    and the factor (x, y) from its pixels to the image's."""
    scale = detection_scale(image.shape, max_size)
    if scale == 1.0:
        return image, np.ones(2)
    h, w = image.shape[:2]
    size = (max(1, int(w / scale + 0.5)), max(1, int(h / scale + 0.5)))  # rounded as the C++ front end
    return cv2.resize(image, size, interpolation=cv2.INTER_AREA), np.array([w / size[0], h / size[1]])


def to_image_pixels(xy, factor):
    """Positions in the detection image as positions in the image: resize maps pixel centres onto pixel
    centres, (x + 0.5) * factor - 0.5."""
    return xy if np.all(factor == 1.0) else (xy + 0.5) * factor - 0.5


def extract(image, K, dist, kinds, max_points=4000, min_segment=20.0, max_size=MAX_IMAGE_SIZE):
    """Points and segments of one image, in its own (undistorted) pixels; detected in the image reduced
    to max_size (detection_image()) when it is larger. min_segment is in the detection image's pixels."""
    image, factor = detection_image(image, max_size)
    out = {"points": np.zeros((0, 2)), "point_desc": np.zeros((0, 128), np.float32), "point_size": np.zeros(0),
           "segments": np.zeros((0, 4)), "line_desc": np.zeros((0, 32), np.uint8)}
    if kinds in ("points", "all"):
        keypoints, desc = cv2.SIFT_create(max_points).detectAndCompute(image, None)
        if keypoints:
            # SIFT's doubled first octave puts every position 0.25 px right of and below the feature
            # (as the C++ front end, samples/common/image_features.cpp).
            xy = np.array([k.pt for k in keypoints], np.float64) - SIFT_UPSAMPLING_OFFSET
            out["points"] = undistort(to_image_pixels(xy, factor), K, dist)
            out["point_desc"] = desc
            out["point_size"] = np.array([k.size for k in keypoints]) * factor.max()  # diameters (px)
    if kinds in ("lines", "all"):
        edge_drawing = cv2.ximgproc.createEdgeDrawing()
        edge_drawing.detectEdges(image)
        detected = edge_drawing.detectLines()
        ends = np.zeros((0, 4)) if detected is None else detected.reshape(-1, 4).astype(np.float64)
        ends = fit_segments_to_edges(image, ends[np.hypot(*(ends[:, 2:] - ends[:, :2]).T) >= min_segment])
        if len(ends):
            keylines = [keyline(i, s, max(image.shape)) for i, s in enumerate(ends)]
            keylines, desc = cv2.line_descriptor.BinaryDescriptor.createBinaryDescriptor().compute(image, keylines)
            # LBD keeps one descriptor per segment, in order: the rows of ends pair with them (as the C++ front end).
            if desc is None or len(desc) != len(ends):
                raise RuntimeError(f"LBD described {0 if desc is None else len(desc)} of {len(ends)} segments")
            out["segments"] = undistort(to_image_pixels(ends.reshape(-1, 2), factor), K, dist).reshape(-1, 4)
            out["line_desc"] = desc
    return out


# --- matching ------------------------------------------------------------------------------------

def mutual_best(distance, ratio):
    """(row, column) pairs of a distance matrix (inf: not a candidate): each the other's best, and the
    best below `ratio` times the row's second best (a lone candidate passes)."""
    if distance.size == 0:
        return np.zeros((0, 2), int)
    rows = np.arange(distance.shape[0])
    best = np.argmin(distance, axis=1)
    best_d = distance[rows, best]
    # The second best: the row's minimum with the best taken out (a copy, cheaper than sorting rows).
    others = distance.copy()
    others[rows, best] = np.inf
    second_d = others.min(axis=1)
    mutual = np.argmin(distance, axis=0)[best] == rows
    keep = np.isfinite(best_d) & mutual & (~np.isfinite(second_d) | (best_d < ratio * second_d))
    return np.stack([rows[keep], best[keep]], axis=1)


POPCOUNT = np.array([bin(i).count("1") for i in range(256)], np.uint8)


def hamming(a, b):
    """Hamming distances of binary (uint8) descriptors a and b, broadcast along all but their last
    axis; float32."""
    return POPCOUNT[a ^ b].sum(axis=-1, dtype=np.int32).astype(np.float32)


def descriptor_distances(a, b):
    """Hamming distances of binary (uint8) descriptors, else L2; float32, rows of a by rows of b."""
    if a.dtype == np.uint8:
        return hamming(a[:, None, :], b[None, :, :])
    a, b = a.astype(np.float32), b.astype(np.float32)
    d2 = (a * a).sum(1)[:, None] + (b * b).sum(1)[None, :] - 2.0 * a @ b.T
    return np.sqrt(np.maximum(d2, 0.0))


def fundamental(K1, K2, R12, t12):
    t = t12.ravel()
    tx = np.array([[0, -t[2], t[1]], [t[2], 0, -t[0]], [-t[1], t[0], 0]])
    return np.linalg.inv(K2).T @ tx @ R12 @ np.linalg.inv(K1)


def homogeneous(xy):
    return np.hstack([xy, np.ones((len(xy), 1))])


def normalised_lines(lines):
    return lines / np.maximum(np.hypot(lines[:, :1], lines[:, 1:2]), 1e-300)


def match_points_epipolar(a, b, F, max_distance=2.0, ratio=0.8):
    xa, xb = homogeneous(a["points"]), homogeneous(b["points"])
    in_b = normalised_lines(xa @ F.T)   # epipolar lines of a's points in image b
    in_a = normalised_lines(xb @ F)     # and of b's points in image a
    distance = np.full((len(xa), len(xb)), np.inf, np.float32)
    for start in range(0, len(xa), 512):  # in blocks: a full float64 matrix of 4000 x 4000 is 128 MB
        rows = slice(start, start + 512)
        near = (np.abs(in_b[rows] @ xb.T) <= max_distance) & (np.abs(xa[rows] @ in_a.T) <= max_distance)
        distance[rows] = np.where(near, descriptor_distances(a["point_desc"][rows], b["point_desc"]), np.inf)
    return mutual_best(distance, ratio)


def match_segments_epipolar(a, b, F, min_overlap=0.5, min_angle_deg=5.0, ratio=0.8, max_distance=80):
    sa, sb = a["segments"], b["segments"]
    if len(sa) == 0 or len(sb) == 0:
        return np.zeros((0, 2), int)
    la, lb = homogeneous(sa[:, :2]) @ F.T, homogeneous(sa[:, 2:]) @ F.T  # epipolar lines of a's end points
    p, d = sb[:, :2], sb[:, 2:] - sb[:, :2]
    length = np.hypot(d[:, 0], d[:, 1])
    params = []
    ok = np.ones((len(sa), len(sb)), bool)
    for l in (la, lb):
        across = l[:, :1] * d[None, :, 0] + l[:, 1:2] * d[None, :, 1]
        normal = np.hypot(l[:, :1], l[:, 1:2])
        # A segment near the epipolar direction crosses the band at no defined place.
        ok &= np.abs(across) > np.sin(np.radians(min_angle_deg)) * normal * length[None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            params.append(-(l[:, :1] * p[None, :, 0] + l[:, 1:2] * p[None, :, 1] + l[:, 2:3]) / across)
    # Segments run with the brighter side on their right (fit_segments_to_edges), as every view of an
    # edge sees it, and a view keeps the order along a line: a's first end's band comes first along b.
    lo, hi = params
    ok &= lo < hi
    overlap = np.minimum(hi, 1.0) - np.maximum(lo, 0.0)
    ok &= (overlap > 0) & (overlap >= min_overlap * np.minimum(1.0, hi - lo))
    # Hamming distances of the candidate pairs only: the geometry leaves a few in a hundred.
    i, j = np.nonzero(ok)
    desc = hamming(a["line_desc"][i], b["line_desc"][j])
    distance = np.full(ok.shape, np.inf, np.float32)
    distance[i, j] = np.where(desc <= max_distance, desc, np.inf)
    return mutual_best(distance, ratio)


def match_by_descriptor(a, b, ratio=0.8, max_distance=np.inf):
    if len(a) == 0 or len(b) == 0:
        return np.zeros((0, 2), int)
    distance = descriptor_distances(a, b)
    return mutual_best(np.where(distance <= max_distance, distance, np.inf), ratio)


def estimate_fundamental(a, b, max_distance=2.0, ratio=0.8, min_inliers=30):
    """F (x_b^T F x_a = 0) of two views of unknown relative pose from their descriptor matches
    (RANSAC); None with fewer than min_inliers matches consistent with it."""
    m = match_by_descriptor(a["point_desc"], b["point_desc"], ratio)
    if len(m) < min_inliers:
        return None
    F, inliers = cv2.findFundamentalMat(a["points"][m[:, 0]], b["points"][m[:, 1]], cv2.FM_RANSAC, max_distance, 0.999)
    if F is None or F.shape != (3, 3) or int(inliers.sum()) < min_inliers:
        return None
    return F


AGREEMENT_SAMPLE = 300


def epipolar_agreement(a, b, F, max_distance=2.0, ratio=0.8):
    """(descriptor matches, of them within max_distance of their epipolar lines both ways) for an
    evenly spread subset of a's points (at most AGREEMENT_SAMPLE) matched to b without F, as the C++
    samples' epipolarAgreement() (samples/common/feature_matching.hpp): 73-88 % agree on the VGG
    pairs with their own cameras, 0-11 % with view 2's pose inverted, the images swapped or one image
    twice (test/evaluation/calibration_agreement.py)."""
    rows = np.arange(0, len(a["points"]), max(1, -(-len(a["points"]) // AGREEMENT_SAMPLE)))
    m = match_by_descriptor(a["point_desc"][rows], b["point_desc"], ratio)
    if len(m) == 0:
        return 0, 0
    xa, xb = homogeneous(a["points"][rows[m[:, 0]]]), homogeneous(b["points"][m[:, 1]])
    to_b, to_a = normalised_lines(xa @ F.T), normalised_lines(xb @ F)
    agreeing = (np.abs((to_b * xb).sum(1)) <= max_distance) & (np.abs((to_a * xa).sum(1)) <= max_distance)
    return len(m), int(agreeing.sum())


def contradicts(matches, agreeing):
    """Too few matches agree for the calibration to be the images': under 30 % of 20 or more."""
    return matches >= 20 and agreeing < 0.3 * matches


def agreement_summary(matches, agreeing):
    """The words of the C++ samples' EpipolarAgreement::summary() for the warning."""
    return (f"of {matches} point matches found without the poses, {agreeing} ({100 * agreeing / matches:.0f} %) "
            "lie on their epipolar lines (73-88 % where the poses are right)")


def triplets(views, K, R12, t12, pixel_scale=1.0):
    """Views 1-2 under their pose, view 3 against the pairs' view-2 features under the fundamental
    matrix of their descriptor matches (by descriptor alone without one): (points1..3, lines1..3).
    pixel_scale multiplies the pixel tolerances (detection_scale())."""
    rows = triplet_rows(views, K, R12, t12, pixel_scale)
    return tuple([views[v][kind][rows[kind][v]] for v in range(3)] for kind in ("points", "segments"))


def triplet_rows(views, K, R12, t12, pixel_scale=1.0):
    """The matching of triplets(), as each triplet's row in every view's features: {"points":
    (rows1, rows2, rows3), "segments": (...)}."""
    F = fundamental(K[0], K[1], R12, t12)
    tolerance = 2.0 * pixel_scale
    pairs = {"points": match_points_epipolar(views[0], views[1], F, tolerance),
             "segments": match_segments_epipolar(views[0], views[1], F)}
    in2 = {"points": views[1]["points"][pairs["points"][:, 1]],
           "point_desc": views[1]["point_desc"][pairs["points"][:, 1]],
           "segments": views[1]["segments"][pairs["segments"][:, 1]],
           "line_desc": views[1]["line_desc"][pairs["segments"][:, 1]]}
    F23 = estimate_fundamental(in2, views[2], tolerance)
    if F23 is not None:
        to3 = {"points": match_points_epipolar(in2, views[2], F23, tolerance),
               "segments": match_segments_epipolar(in2, views[2], F23)}
    else:
        to3 = {"points": match_by_descriptor(in2["point_desc"], views[2]["point_desc"]),
               "segments": match_by_descriptor(in2["line_desc"], views[2]["line_desc"], max_distance=80)}
    return {kind: (pairs[kind][to3[kind][:, 0], 0], pairs[kind][to3[kind][:, 0], 1], to3[kind][:, 1])
            for kind in ("points", "segments")}


# --- estimate ------------------------------------------------------------------------------------

def estimate_pose(points, lines, K, R12, t12, threshold, seed, loss_scale=IMAGE_LOSS_SCALE):
    """The tripose package's robust estimator (RANSAC, then refinement), the refinement over the
    inliers repeated under the Cauchy loss of the C++ samples (the package's RANSAC refines by least
    squares). threshold and loss_scale are in the images' pixels (see main()). The estimate is asked
    for without a floor on its inliers: the caller judges them against MIN_INLIERS and reports them."""
    import tripose
    try:
        pose = tripose.estimate_pose_line_point_ransac(points[0], points[1], points[2], lines[0], lines[1], lines[2],
                                                       K, R12, t12, threshold=threshold, refine=True, seed=seed,
                                                       min_inliers=0)
    except (ValueError, TypeError) as e:
        raise SolverRejection(str(e)) from None
    pose = {key: pose[key] for key in pose.keys()}  # a PoseResult is read-only
    if pose["num_inliers"] == 0:
        return pose
    p, l = np.asarray(pose["point_inliers"], bool), np.asarray(pose["line_inliers"], bool)
    refined = tripose.refine_pose_line_point(points[0][p], points[1][p], points[2][p], lines[0][l], lines[1][l],
                                             lines[2][l], K, R12, t12, pose["R"], pose["t"], loss="cauchy",
                                             loss_scale=loss_scale)
    # The robust estimate's other entries (inlier masks, counts) stay; its RMS is the refinement's now.
    pose["R"], pose["t"], pose["rms"] = refined["R"], refined["t"], refined["rms"]
    return pose


def write_result(path, calib, points, lines, pose, tolerances):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    if not fs.isOpened():
        raise InputError(f"cannot write {path}")
    if pose is not None:
        fs.write("num_solutions", 1)
        fs.write("R", np.asarray(pose["R"], np.float64))
        fs.write("t", np.asarray(pose["t"], np.float64).reshape(3, 1))
        fs.write("rms", float(pose["rms"]))
        fs.write("num_inliers", int(pose["num_inliers"]))
        fs.write("point_inliers", np.asarray(pose["point_inliers"], np.int32).reshape(-1, 1))
        fs.write("line_inliers", np.asarray(pose["line_inliers"], np.int32).reshape(-1, 1))
    fs.write("num_point_tracks", len(points[0]))
    for key, value in tolerances.items():  # pixel_scale, and the estimate's in the images' pixels
        fs.write(key, float(value))
    fs.write("num_segment_triplets", len(lines[0]))
    for v in range(3):
        fs.write(f"K{v + 1}", calib["K"][v])
    fs.write("R12", calib["R12"])
    fs.write("t12", calib["t12"])
    for kind, rows in (("points", points), ("lines", lines)):
        if len(rows[0]):
            for v in range(3):
                fs.write(f"{kind}{v + 1}", np.ascontiguousarray(rows[v], np.float64))
    fs.release()


def main(argv=None):
    parser = ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--calib", required=True)
    parser.add_argument("--images", nargs=3, required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--features", choices=("points", "lines", "all"), default="all")
    parser.add_argument("--threshold", type=float, default=2.0)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-image-size", type=whole_number, default=MAX_IMAGE_SIZE,
                        help="detect features in images reduced to this longer side (px; 0: full size)")
    parser.add_argument("--problem-only", action="store_true",
                        help="write the matched problem without an estimate")
    args = parser.parse_args(argv)
    if not args.threshold > 0:
        parser.error("argument --threshold: expected a positive number of pixels")
    if args.max_image_size < 0:
        parser.error("argument --max-image-size: expected 0 (full size) or a positive number of pixels")
    try:
        check_writable(args.output, "--output")
        calib = read_calibration(args.calib)
        keys = ["K"] * 3 if calib["K"][0] is calib["K"][1] else ["K1", "K2", "K3"]
        images = [read_image(p, calib["K"][v], keys[v]) for v, p in enumerate(args.images)]
        dist = calib["dist"] or [None] * 3
        # One thread per image: OpenCV's detectors release the GIL, so the images share the cores.
        with ThreadPoolExecutor(max_workers=3) as pool:
            views = list(pool.map(lambda v: extract(images[v], calib["K"][v], dist[v], args.features,
                                                    max_size=args.max_image_size), range(3)))
        # Features found in reduced images are that much less precise in the images' pixels: every
        # pixel tolerance, the matching's and the estimate's, grows by the reduction.
        pixel_scale = max(detection_scale(image.shape, args.max_image_size) for image in images)
        tolerances = {"pixel_scale": pixel_scale, "threshold": args.threshold * pixel_scale,
                      "loss_scale": IMAGE_LOSS_SCALE * pixel_scale}
        reduction = (f"features detected in the images reduced by {pixel_scale:.2f} "
                     f"(--max-image-size {args.max_image_size})" if pixel_scale > 1 else "")
        if reduction:
            print(f"pose_from_images: {reduction}; pixel tolerances scaled by it")
        # The most common calibration mistake, view 2's pose inverted (or the images in another
        # order), still yields matches and a wrong pose: matches found without the calibration tell it.
        matches, agreeing = epipolar_agreement(views[0], views[1], fundamental(calib["K"][0], calib["K"][1],
                                                                               calib["R12"], calib["t12"]),
                                               2.0 * pixel_scale)
        if contradicts(matches, agreeing):
            print(f"pose_from_images: warning: images 1 and 2 do not follow R12, t12 of {args.calib}: "
                  f"{agreement_summary(matches, agreeing)}. Is [R12 | t12] view 2's pose in view 1's frame "
                  "(x2 = R12 x1 + t12, not its inverse), and are the images in the calibration's order?",
                  file=sys.stderr)
        points, lines = triplets(views, calib["K"], calib["R12"], calib["t12"], pixel_scale)
        print(f"pose_from_images: {len(points[0])} point tracks, {len(lines[0])} segment triplets")
        if len(points[0]) + len(lines[0]) < MIN_FEATURES:
            raise InputError(f"too few features seen in all three images ({', '.join(args.images)}): "
                             f"{len(points[0])} point tracks and {len(lines[0])} segment triplets"
                             + (f" ({reduction})" if reduction else ""))
        pose = None
        if not args.problem_only:
            try:
                pose = estimate_pose(points, lines, calib["K"], calib["R12"], calib["t12"], tolerances["threshold"],
                                     args.seed, tolerances["loss_scale"])
            except ImportError:
                print("pose_from_images: the tripose package is not installed (pip install tripose); "
                      "--problem-only writes the matched problem for tripose_estimate", file=sys.stderr)
                return 2
            except SolverRejection as e:
                raise InputError(f"the solver rejected the input of {args.calib}: {e}") from None
            if pose["R"] is None or pose["num_inliers"] < MIN_INLIERS:
                print(f"pose_from_images: no reliable pose: {len(points[0])} point tracks and {len(lines[0])} "
                      f"segment triplets matched, {pose['num_inliers']} inliers, fewer than the {MIN_INLIERS} a "
                      "pose needs; nothing written", file=sys.stderr)
                return 3
            print(f"pose_from_images: {pose['num_inliers']} inliers")
        write_result(args.output, calib, points, lines, pose, tolerances)
    except InputError as e:
        print(f"pose_from_images: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
