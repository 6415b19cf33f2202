# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Systematic offset of detected feature positions: a feature found in an image and in its mirror
image must come out at mirrored positions (x -> W - 1 - x, pixel centres at integers); half their
disagreement is the detector's offset along that axis.

    .venv/bin/python test/evaluation/feature_position_bias.py image [image ...]

Prints, per image and axis, the offset of OpenCV's SIFT key points and of EDLines segments (contrib
ximgproc, across their direction) as detected and as the image front end places them (the SIFT
offset corrected, the segments fitted to their edges: tripose.images.extract_features, as
samples/common/image_features.cpp; it needs the tripose package). First, the same for the segments on straight edges rendered at
known sub-pixel positions, which needs no mirror.
"""

import functools
import sys

import cv2
import numpy as np


def front_end(image, kinds):
    """The features of the image front end (tripose.images), positions in the image's pixels."""
    import tripose.images
    return tripose.images.extract_features(image, np.eye(3), None, tripose.images.FeatureOptions(kinds=kinds))


def pairs_by_position(a, b, radius=1.5):
    """Rows of a and b (N x 2, M x 2) nearest each other, within radius px."""
    if len(a) == 0 or len(b) == 0:
        return np.zeros(0, int), np.zeros(0, int)
    # OpenCV's brute-force matcher finds each nearest point (in float32: a tie within about 1e-4 px
    # may go either way); the whole N x M array of differences in numpy took seconds for the some
    # 8000 points SIFT finds in a Merton image.
    matches = cv2.BFMatcher(cv2.NORM_L2).match(a.astype(np.float32), b.astype(np.float32))
    i = np.array([m.queryIdx for m in matches])
    j = np.array([m.trainIdx for m in matches])
    keep = np.linalg.norm(a[i] - b[j], axis=1) < radius
    return i[keep], j[keep]


def sift_offset(image, mirrored, axis, corrected):
    if corrected:
        a = front_end(image, "points")["points"]
        b = front_end(mirrored, "points")["points"]
    else:
        sift = cv2.SIFT_create()
        a = np.array([k.pt for k in sift.detect(image, None)])
        b = np.array([k.pt for k in sift.detect(mirrored, None)])
    b = b.copy()
    b[:, axis] = image.shape[1 - axis] - 1 - b[:, axis]
    i, j = pairs_by_position(a, b)
    return float(np.median(a[i, axis] - b[j, axis]) / 2), len(i)


def detected_segments(image, corrected, min_length=30):
    """Segments (N x 4) longer than min_length, from contrib's EDLines as detected or as the front end
    places them."""
    if corrected:
        ends = front_end(image, "lines")["segments"]
    else:
        edge_drawing = cv2.ximgproc.createEdgeDrawing()
        edge_drawing.detectEdges(image)
        lines = edge_drawing.detectLines()
        ends = np.zeros((0, 4)) if lines is None else lines.reshape(-1, 4).astype(np.float64)
    return ends[np.hypot(ends[:, 2] - ends[:, 0], ends[:, 3] - ends[:, 1]) > min_length]


def segment_offset(image, mirrored, axis, corrected=False):
    a, b = detected_segments(image, corrected), detected_segments(mirrored, corrected)
    n = image.shape[1 - axis] - 1
    b = b.copy()
    b[:, [axis, axis + 2]] = n - b[:, [axis, axis + 2]]
    offsets = []
    mid_b = (b[:, :2] + b[:, 2:]) / 2
    dir_b = b[:, 2:] - b[:, :2]
    for s in a:
        d = s[2:] - s[:2]
        length = np.hypot(*d)
        normal = np.array([-d[1], d[0]]) / length
        if abs(normal[axis]) < 0.95:  # only segments across the axis
            continue
        near = np.hypot(*(mid_b - (s[:2] + s[2:]) / 2).T) < 10
        parallel = np.abs(dir_b @ d) / (np.hypot(*dir_b.T) * length) > 0.999
        c = np.nonzero(near & parallel)[0]
        if len(c) == 1:
            offsets.append(-((mid_b[c[0]] - s[:2]) @ normal) * np.sign(normal[axis]) / 2)
    return (float(np.median(offsets)) if offsets else float("nan")), len(offsets)


@functools.lru_cache(maxsize=None)
def rendered_edges(size=240, supersampling=10):
    """Straight edges rendered at known sub-pixel positions (pixel centres at integers, each pixel the
    mean of supersampling^2 samples), as (image, unit normal, signed distance of the edge from the
    image centre along it). The distances lie midway between two samples (tenths of a pixel), where
    the rendering places an edge along an axis exactly; at a sample it would be 0.05 px off. The edges cross the image within 12 deg of an axis, both polarities: the
    mirror measure's segments (segment_offset) are these. Two run along an axis: an edge detector that
    chains whole pixels places those up to half a pixel off."""
    edges = []
    centre = size / 2
    grid = (np.arange(size * supersampling) + 0.5) / supersampling - 0.5
    x, y = np.meshgrid(grid, grid)
    for offset in (-29.7, 0.0, 1.3, 17.6):
        for angle in np.radians([0.0, 3.0, -11.0, 7.0, 90.0, 88.0, 95.0, 81.0]):
            normal = np.array([np.cos(angle), np.sin(angle)])
            bright = ((x - centre) * normal[0] + (y - centre) * normal[1] > offset).astype(np.float32)
            image = (60 + 140 * bright.reshape(size, supersampling, size, supersampling).mean(axis=(1, 3)))
            image = image.astype(np.uint8)
            edges += [(image, normal, offset), (255 - image, normal, offset)]
    return tuple(edges)


def rendered_edge_shift(corrected):
    """The detector's constant shift (dx, dy) in px, fitted by least squares to the signed distances
    of the mid-points of the segments found on rendered_edges() (a shift moves a mid-point by
    dx nx + dy ny along the edge's normal n), and the distances left once it is taken off."""
    distances, normals = [], []
    for image, normal, offset in rendered_edges():
        segments = detected_segments(image, corrected)
        longest = segments[np.argmax(np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1]))]
        centre = image.shape[0] / 2
        distances.append(((longest[:2] + longest[2:]) / 2 - centre) @ normal - offset)
        normals.append(normal)
    distances, normals = np.array(distances), np.array(normals)
    shift = np.linalg.lstsq(normals, distances, rcond=None)[0]
    return shift, distances - normals @ shift


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for corrected, name in ((False, "as detected"), (True, "front end")):
        shift, left = rendered_edge_shift(corrected)
        print(f"Segments on rendered edges, {name}: shift ({shift[0]:+.3f}, {shift[1]:+.3f}) px; "
              f"{len(left)} segments, largest distance left {np.abs(left).max():.3f} px")
    print()
    print("| image | axis | SIFT as detected (px) | SIFT, front end (px) | key point pairs | EDLines as detected (px) "
          "| segments, front end (px) | segment pairs |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for path in sys.argv[1:]:
        image = cv2.imread(path, cv2.IMREAD_GRAYSCALE)
        if image is None:
            sys.exit(f"{path}: cannot be read as an image")
        for axis, name in ((0, "x"), (1, "y")):
            mirrored = cv2.flip(image, 1 if axis == 0 else 0)
            raw, n = sift_offset(image, mirrored, axis, False)
            fixed, _ = sift_offset(image, mirrored, axis, True)
            raw_segments, m = segment_offset(image, mirrored, axis)
            fitted, _ = segment_offset(image, mirrored, axis, corrected=True)
            print(f"| {Path(path).name} | {name} | {raw:+.3f} | {fixed:+.3f} | {n} | {raw_segments:+.3f} | {fitted:+.3f} "
                  f"| {m} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
