"""Image front end of tripose: reading images and detecting their features, as the C++ samples do
(samples/common/image_input.cpp, image_features.cpp, segment_edge_fit.cpp).

* read_image(path): an 8-bit grey image; EXIF orientation applied, deeper images (16-bit, float)
  stretched from their lowest to their highest value onto 0-255.
* extract_features(image, K, dist, options): SIFT points with their descriptors and EDLines segments
  fitted to their edges and oriented with the brighter side on their right, with LBD descriptors;
  positions in the image's own pixels, undistorted when dist is given (not for tripose.Tracker,
  which undistorts the features with its own dist).
* open_frames(source): (timestamp, name, image) of a folder of images, a list file or a video.

It needs OpenCV with its contrib modules (ximgproc, line_descriptor): pip install tripose[images].
The rest of tripose never imports OpenCV; this module imports it when a function is first called.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Optional, Tuple

import numpy as np

__all__ = ["FeatureOptions", "tracking_feature_options", "read_image", "extract_features", "open_frames",
           "detection_scale", "fit_segments_to_edges", "IMAGE_EXTENSIONS"]

_MISSING_OPENCV = "tripose.images needs OpenCV's contrib modules: pip install tripose[images]"

# SIFT finds its finest key points in the image doubled by bilinear resize and halves their
# coordinates, which puts every position 0.25 px right of and below the feature (as the C++ front end).
_SIFT_UPSAMPLING_OFFSET = 0.25

# The file name extensions a folder of images is read by (compared in lower case), as the C++ samples.
IMAGE_EXTENSIONS = (".png", ".jpg", ".jpeg", ".pgm", ".ppm", ".bmp", ".tif", ".tiff")

# A video stops at this many frames in a row that cannot be decoded: a damaged file ends like that.
_MAX_LOST_VIDEO_FRAMES = 25

_KINDS = ("all", "points", "lines")


def _cv2():
    """OpenCV with the contrib modules the front end uses; ImportError naming the extra otherwise."""
    try:
        import cv2
    except ImportError as error:
        raise ImportError(_MISSING_OPENCV) from error
    if not hasattr(cv2, "ximgproc") or not hasattr(cv2.ximgproc, "createEdgeDrawing") \
            or not hasattr(cv2, "line_descriptor"):
        raise ImportError(_MISSING_OPENCV)
    return cv2


@dataclass
class FeatureOptions:
    """What extract_features() detects, with the C++ samples' defaults (FeatureOptions of
    samples/common/image_features.hpp).

    kinds: "all", "points" (SIFT only) or "lines" (segments only).
    max_points: the strongest SIFT key points kept (0: all).
    contrast_threshold: SIFT's contrast threshold (OpenCV's contrastThreshold): lower finds more,
        fainter points, which hold a trajectory better where texture is scarce, at more time per frame.
    min_segment_length: shorter segments are dropped (px of the detection image).
    max_image_size: images whose longer side exceeds this (px) are detected in a copy reduced to it
        (area averaging), their positions mapped back to the image's pixels; 0: always the full image.
    """
    kinds: str = "all"
    max_points: int = 4000
    contrast_threshold: float = 0.04
    min_segment_length: float = 20.0
    max_image_size: int = 1600

    def check(self):
        """Raises ValueError naming the first option out of range."""
        if self.kinds not in _KINDS:
            raise ValueError(f"kinds: expected one of {', '.join(_KINDS)}, got {self.kinds!r}")
        for name in ("max_points", "max_image_size"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
                raise ValueError(f"{name}: expected a whole number >= 0, got {value!r}")
        for name in ("min_segment_length", "contrast_threshold"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
                    or not math.isfinite(value) or value < 0:
                raise ValueError(f"{name}: expected a finite number >= 0, got {value!r}")


def tracking_feature_options() -> FeatureOptions:
    """The features a tripose.Tracker is fed: the FeatureOptions defaults with more and fainter SIFT
    points (contrast threshold 0.01, the strongest 8192 kept), as tripose-track detects them: a
    sequence's error accumulates from frame to frame, and more points hold it
    (doc/studies/front_end_and_tracker.md, "Against COLMAP")."""
    return FeatureOptions(contrast_threshold=0.01, max_points=8192)


# --- reading ---------------------------------------------------------------------------------------

def _jpeg_is_complete(data):
    """False for a JPEG stream cut short: no end-of-image marker after its first scan. (The decoder
    fills a truncated image's missing part with grey and reports nothing.) Data that does not start
    as a JPEG is left to the decoder."""
    if data[:2] != b"\xff\xd8":
        return True
    i = 2
    while i + 4 <= len(data):
        if data[i] != 0xFF:
            return False
        marker = data[i + 1]
        if marker == 0xFF:  # fill byte
            i += 1
        elif marker == 0x01 or 0xD0 <= marker <= 0xD8:  # markers without a length
            i += 2
        elif marker == 0xD9:  # end of image before any scan
            return False
        else:
            length = int.from_bytes(data[i + 2:i + 4], "big")
            if marker == 0xDA:  # start of scan: the entropy-coded data runs to the end marker
                return data.find(b"\xff\xd9", i + 2 + length) >= 0
            i += 2 + length
    return False


def _stretched_to_eight_bits(image, lowest, highest):
    """An image of more than 8 bits in 8: its values from lowest to highest stretched onto 0-255
    (keeping the top byte alone would leave a camera's 12 bits stored in 16 with 16 grey levels)."""
    scale = 255.0 / (float(highest) - float(lowest))
    return np.clip(np.rint((image.astype(np.float64) - float(lowest)) * scale), 0, 255).astype(np.uint8)


def _grey(cv2, image):
    if image.ndim == 2:
        return image
    code = {3: cv2.COLOR_BGR2GRAY, 4: cv2.COLOR_BGRA2GRAY}.get(image.shape[2])
    if code is None:
        return image[:, :, 0].copy() if image.shape[2] == 1 else None
    return cv2.cvtColor(image, code)


def read_image(path) -> np.ndarray:
    """The image at path as an 8-bit grey array (H, W), as the C++ samples read images: turned by its
    EXIF orientation tag, an image of more than 8 bits (16-bit PNG or TIFF, float TIFF) stretched from
    its lowest to its highest value onto 0-255 (in colour, then made grey). Raises ValueError naming
    the file when it is missing, cannot be read or decoded (a JPEG cut short included), holds values
    that are not finite numbers, or is blank (one value everywhere)."""
    cv2 = _cv2()
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"image {path}: no such file")
    try:
        data = path.read_bytes()
    except OSError as error:
        raise ValueError(f"image {path}: cannot be read ({error.strerror or error})") from None
    if not _jpeg_is_complete(data):
        raise ValueError(f"image {path}: cannot be decoded (the JPEG data is cut short)")
    # Not IMREAD_UNCHANGED, which ignores the EXIF orientation; depth and colour stay as stored.
    image = cv2.imdecode(np.frombuffer(data, np.uint8), cv2.IMREAD_ANYDEPTH | cv2.IMREAD_ANYCOLOR) if data else None
    if image is None or image.size == 0:
        raise ValueError(f"image {path}: cannot be decoded (not an image OpenCV reads)")
    if not np.all(np.isfinite(image)):
        raise ValueError(f"image {path}: holds values that are not finite numbers")
    lowest, highest = image.min(), image.max()
    if lowest == highest:
        raise ValueError(f"image {path}: blank (every pixel has the value {lowest:g})")
    if image.dtype != np.uint8:
        image = _stretched_to_eight_bits(image, lowest, highest)
    grey = _grey(cv2, image)
    if grey is None:
        raise ValueError(f"image {path}: has {image.shape[2]} channels (1, 3 or 4 are read)")
    return grey


# --- detection -------------------------------------------------------------------------------------

def detection_scale(shape, max_image_size=1600) -> float:
    """How many of the image's pixels one pixel of its detection image spans: the longer side over
    max_image_size when it exceeds it (and max_image_size > 0), else 1. Features are that much less
    precise in the image's pixels, so pixel tolerances downstream grow by it. shape: (H, W, ...)."""
    longer = max(shape[:2])
    return longer / max_image_size if 0 < max_image_size < longer else 1.0


def _detection_image(cv2, image, max_image_size):
    """The image features are detected in (reduced by area averaging to max_image_size on its longer
    side) and the factor (x, y) from its pixels to the image's."""
    scale = detection_scale(image.shape, max_image_size)
    if scale == 1.0:
        return image, np.ones(2)
    h, w = image.shape[:2]
    size = (max(1, int(w / scale + 0.5)), max(1, int(h / scale + 0.5)))  # rounded as the C++ front end
    return cv2.resize(image, size, interpolation=cv2.INTER_AREA), np.array([w / size[0], h / size[1]])


def _to_image_pixels(xy, factor):
    """Positions in the detection image as positions in the image: resize maps pixel centres onto pixel
    centres, x = (x' + 0.5) * factor - 0.5."""
    return xy if np.all(factor == 1.0) else (xy + 0.5) * factor - 0.5


def _undistorted(cv2, xy, K, dist):
    """Positions (N, 2) moved to the ideal pinhole image of K (cv2.undistortPoints, new camera K)."""
    if dist is None or len(xy) == 0:
        return xy
    return cv2.undistortPoints(xy.reshape(-1, 1, 2), K, dist, P=K).reshape(-1, 2).astype(np.float64)


def fit_segments_to_edges(image, segments, end_margin=2.0, search=2, max_distance=1.0, min_peaks=5):
    """Each segment (x0, y0, x1, y1) of the 8-bit grey image fitted to its edge and oriented with the
    brighter side on its right as drawn (x right, y down), as the C++ front end's fitSegmentsToEdges()
    (samples/common/segment_edge_fit.hpp): at every pixel row (column, for segments closer to
    horizontal) the segment crosses, the peak of the gradient (Gaussian sigma 1, Sobel) across it,
    placed between pixels by a parabola through three, within max_distance px of the segment and of
    the segment's dominant polarity; then the total-least-squares line through those peaks, the end
    points projected onto it. A segment with fewer than min_peaks peaks keeps its position and only
    gets the orientation; one of zero length is dropped. Returns (M, 4) float64."""
    cv2 = _cv2()
    smooth = cv2.GaussianBlur(image.astype(np.float32), (0, 0), 1.0)
    gx, gy = cv2.Sobel(smooth, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(smooth, cv2.CV_32F, 0, 1, ksize=3)
    segments = np.asarray(segments, np.float64).reshape(-1, 4)
    length = np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1])
    segments = segments[length > 0]
    length = length[length > 0]
    count = len(segments)
    if count == 0:
        return np.zeros((0, 4))
    # All segments' crossings are handled together in flat arrays, their per-segment sums by bincount.
    p0, p1 = segments[:, :2], segments[:, 2:]
    u = (p1 - p0) / length[:, None]
    n = np.stack([-u[:, 1], u[:, 0]], axis=1)
    walk = np.where(np.abs(n[:, 0]) >= np.abs(n[:, 1]), 1, 0)  # walk rows (y, 1) or columns (x, 0)
    across = 1 - walk
    segment = np.arange(count)
    p0w, p1w, p0a = p0[segment, walk], p1[segment, walk], p0[segment, across]
    uw, ua, na = u[segment, walk], u[segment, across], n[segment, across]
    walk_extent = np.array(image.shape)[1 - walk]  # rows for a walk along y, columns along x
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


def _keylines(cv2, segments, image_size):
    """Segments of the detection image as contrib's key lines of one octave, the image's own, for LBD."""
    keylines = []
    for index, s in enumerate(segments):
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
        keylines.append(k)
    return keylines


def _checked_image(image):
    if not isinstance(image, np.ndarray):
        raise TypeError(f"image: expected a numpy array, got {type(image).__name__}")
    if image.dtype != np.uint8:
        raise ValueError(f"image: expected 8-bit values (uint8), got {image.dtype} (read_image() converts)")
    if image.ndim not in (2, 3) or (image.ndim == 3 and image.shape[2] not in (1, 3, 4)) or image.size == 0:
        raise ValueError(f"image: expected a grey (H, W) or colour (H, W, 3 or 4) image, got shape {image.shape}")
    return np.ascontiguousarray(image)


def _checked_calibration(K, dist):
    K = np.asarray(K, np.float64)
    if K.shape != (3, 3) or not np.all(np.isfinite(K)):
        raise ValueError(f"K: expected a finite 3x3 camera matrix, got shape {K.shape}")
    if dist is None:
        return K, None
    dist = np.asarray(dist, np.float64).ravel()
    if dist.size == 0:
        return K, None
    if dist.size not in (4, 5, 8, 12, 14) or not np.all(np.isfinite(dist)):
        raise ValueError(f"dist: expected 4, 5, 8, 12 or 14 finite distortion coefficients, got {dist.size}")
    return K, dist


def extract_features(image, K, dist=None, options: Optional[FeatureOptions] = None) -> dict:
    """The features of one 8-bit image (grey, or colour made grey), as the C++ front end's
    extractFeatures() (samples/common/image_features.cpp):

    points (N, 2) float64 and point_descriptors (N, 128) float32: SIFT, the options.max_points
        strongest;
    segments (M, 4) float64 (x0, y0, x1, y1) and line_descriptors (M, 32) uint8: EDLines segments of
        at least options.min_segment_length px, fitted to their edges and running with the brighter
        side on their right (fit_segments_to_edges()), described by LBD.

    Images larger than options.max_image_size are detected in a reduced copy; positions are in the
    image's own pixels either way. With dist (OpenCV's distortion coefficients), positions are
    undistorted with K (cv2.undistortPoints with new camera matrix K): they are those of an ideal
    pinhole camera K. Kinds not asked for (options.kinds) come back empty.

    For tripose.Tracker, call it without dist: the tracker undistorts the features it is given
    with its own dist (tripose.Tracker(K, dist)), so features undistorted here would be undistorted
    twice."""
    cv2 = _cv2()
    options = FeatureOptions() if options is None else options
    if not isinstance(options, FeatureOptions):
        raise TypeError(f"options: expected a FeatureOptions, got {type(options).__name__}")
    options.check()
    image = _checked_image(image)
    K, dist = _checked_calibration(K, dist)
    grey = _grey(cv2, image)
    grey, factor = _detection_image(cv2, grey, options.max_image_size)

    out = {"points": np.zeros((0, 2)), "point_descriptors": np.zeros((0, 128), np.float32),
           "segments": np.zeros((0, 4)), "line_descriptors": np.zeros((0, 32), np.uint8)}
    if options.kinds in ("points", "all"):
        keypoints, descriptors = cv2.SIFT_create(int(options.max_points), contrastThreshold=float(options.contrast_threshold)).detectAndCompute(grey, None)
        if keypoints:
            xy = np.array([k.pt for k in keypoints], np.float64) - _SIFT_UPSAMPLING_OFFSET
            out["points"] = _undistorted(cv2, _to_image_pixels(xy, factor), K, dist)
            out["point_descriptors"] = np.ascontiguousarray(descriptors, np.float32)
    if options.kinds in ("lines", "all"):
        edge_drawing = cv2.ximgproc.createEdgeDrawing()
        edge_drawing.detectEdges(grey)
        detected = edge_drawing.detectLines()
        ends = np.zeros((0, 4)) if detected is None else detected.reshape(-1, 4).astype(np.float64)
        long_enough = np.hypot(ends[:, 2] - ends[:, 0], ends[:, 3] - ends[:, 1]) >= options.min_segment_length
        ends = fit_segments_to_edges(grey, ends[long_enough])
        if len(ends):
            keylines = _keylines(cv2, ends, max(grey.shape))
            _, descriptors = cv2.line_descriptor.BinaryDescriptor.createBinaryDescriptor().compute(grey, keylines)
            # LBD keeps one descriptor per segment, in order: the rows of ends pair with them.
            if descriptors is None or len(descriptors) != len(ends):
                raise RuntimeError(f"LBD described {0 if descriptors is None else len(descriptors)} of "
                                   f"{len(ends)} segments")
            positions = _to_image_pixels(ends.reshape(-1, 2), factor)
            out["segments"] = _undistorted(cv2, positions, K, dist).reshape(-1, 4)
            out["line_descriptors"] = np.ascontiguousarray(descriptors, np.uint8)
    return out


# --- frame sources ---------------------------------------------------------------------------------

def _natural_key(name):
    """Sorts file names by the numbers in them as numbers (frame2 before frame10)."""
    return [int(part) if part.isdigit() else part.lower() for part in re.split(r"(\d+)", name)], name


def _image_or_none(path):
    try:
        return read_image(path)
    except ValueError:
        return None


def _folder_files(folder):
    try:
        files = [p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in IMAGE_EXTENSIONS]
    except OSError as error:
        raise ValueError(f"folder {folder}: cannot be read ({error.strerror or error})") from None
    if not files:
        raise ValueError(f"folder {folder}: holds no images ({', '.join(IMAGE_EXTENSIONS)})")
    return sorted(files, key=lambda p: _natural_key(p.name))


def _folder_frames(files):
    for index, path in enumerate(files):
        yield float(index), path.name, _image_or_none(path)


def _is_text(path):
    try:
        with open(path, "rb") as f:
            head = f.read(4096)
    except OSError as error:
        raise ValueError(f"{path}: cannot be read ({error.strerror or error})") from None
    if b"\x00" in head:
        return False
    try:
        head.decode("utf-8")
    except UnicodeDecodeError as error:
        return error.start >= len(head) - 3  # a character cut at the end of the block
    return True


def _list_entries(list_file):
    """(timestamp or None, path as written) of each entry of a list file: one image path per line,
    optionally after a timestamp ("t path"); blank lines and lines starting with # are skipped."""
    try:
        text = list_file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ValueError(f"list {list_file}: cannot be read ({error})") from None
    entries = []
    for number, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        fields = line.split(maxsplit=1)
        stamp = None
        if len(fields) == 2:
            try:
                stamp = float(fields[0])
            except ValueError:
                stamp = None
        if stamp is not None and not math.isfinite(stamp):
            raise ValueError(f"list {list_file}:{number}: the timestamp {fields[0]} is not a finite number")
        entries.append((number, stamp, fields[1].strip() if stamp is not None else line))
    if not entries:
        raise ValueError(f"list {list_file}: lists no images")
    stamped = [stamp is not None for _, stamp, _ in entries]
    if any(stamped) and not all(stamped):
        number = entries[stamped.index(False) if stamped[0] else stamped.index(True)][0]
        raise ValueError(f"list {list_file}:{number}: some lines have a timestamp and some do not")
    return [(stamp, name) for _, stamp, name in entries]


def _list_frames(list_file, entries):
    for index, (stamp, name) in enumerate(entries):
        path = Path(name)
        if not path.is_absolute():
            path = list_file.parent / path
        yield (float(index) if stamp is None else stamp), name, _image_or_none(path)


def _video_frames(cv2, video, capture):
    fps = capture.get(cv2.CAP_PROP_FPS)
    period = 1.0 / fps if fps > 0 and math.isfinite(fps) else float("nan")
    frame_count = capture.get(cv2.CAP_PROP_FRAME_COUNT)
    index, lost, last_stamp = 0, 0, None
    try:
        while True:
            ok, frame = capture.read()
            if not ok or frame is None:
                # A frame that cannot be decoded is told from the end of the video by a frame after it.
                lost += 1
                if lost > _MAX_LOST_VIDEO_FRAMES:
                    break
                continue
            stamp = capture.get(cv2.CAP_PROP_POS_MSEC) / 1000.0
            for k in range(lost):
                before = stamp - (lost - k) * period
                yield before, f"{video.name}:{index}", None
                index += 1
            lost = 0
            yield stamp, f"{video.name}:{index}", _grey(cv2, frame)
            last_stamp = stamp
            index += 1
        # Frames the container counts beyond the last one decoded are lost ones too.
        for _ in range(min(lost, max(0, int(frame_count) - index))):
            stamp = (last_stamp if last_stamp is not None else -period) + period
            yield stamp, f"{video.name}:{index}", None
            last_stamp = stamp
            index += 1
    finally:
        capture.release()


def open_frames(source) -> Iterator[Tuple[float, str, Optional[np.ndarray]]]:
    """The frames of source, in order, as (timestamp in seconds, name, 8-bit grey image):

    * a folder: its image files (IMAGE_EXTENSIONS) sorted by name with the numbers in names compared
      as numbers (frame2 before frame10); timestamp the position in that order, name the file name;
    * a text file listing images: one path per line, relative to the list file's folder, optionally
      after a timestamp ("1403636579.76 images/0001.png"; all lines or none); blank lines and lines
      starting with # are skipped; name the path as listed, timestamp the given one or the position;
    * a video (anything else OpenCV's VideoCapture opens): timestamp the frame's position in the video
      (CAP_PROP_POS_MSEC), name "<file name>:<frame index>".

    A frame that cannot be read or decoded comes as (timestamp, name, None) and the frames after it
    follow, so that the caller can count it lost (a video frame whose damage the decoder conceals
    comes as the decoder's picture). A source that cannot be opened (no such path, an
    empty folder or list, a file that is no video) raises ValueError naming it; so does a list with
    timestamps on some lines only, before any frame."""
    cv2 = _cv2()
    path = Path(source)
    if path.is_dir():
        return _folder_frames(_folder_files(path))
    if not path.is_file():
        raise ValueError(f"{path}: no such folder, list or video")
    if path.suffix.lower() in IMAGE_EXTENSIONS:
        raise ValueError(f"{path}: an image, not a folder, list or video (give the folder that holds it)")
    if path.suffix.lower() in (".txt", ".lst", ".list") or _is_text(path):
        return _list_frames(path, _list_entries(path))
    capture = cv2.VideoCapture(str(path))
    if not capture.isOpened():
        raise ValueError(f"video {path}: cannot be opened (not a video OpenCV reads)")
    return _video_frames(cv2, path, capture)
