# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Systematic offset of detected feature positions: a feature found in an image and in its mirror
image must come out at mirrored positions (x -> W - 1 - x, pixel centres at integers); half their
disagreement is the detector's offset along that axis.

    .venv/bin/python test/evaluation/feature_position_bias.py image [image ...]

Prints, per image and axis, the offset of OpenCV's SIFT key points as detected, after the image
front end's correction (samples/python/pose_from_images.py, as samples/common/image_features.cpp),
and of LSD segments (contrib line_descriptor, as the front end runs it) across their direction.
"""

import sys
from pathlib import Path

import cv2
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "samples" / "python"))
import pose_from_images  # noqa: E402


def pairs_by_position(a, b, radius=1.5):
    """Rows of a and b (N x 2, M x 2) nearest each other, within radius px."""
    d = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    j = d.argmin(axis=1)
    keep = d[np.arange(len(a)), j] < radius
    return np.nonzero(keep)[0], j[keep]


def sift_offset(image, mirrored, axis, corrected):
    if corrected:
        a = pose_from_images.extract(image, None, None, "points")["points"]
        b = pose_from_images.extract(mirrored, None, None, "points")["points"]
    else:
        sift = cv2.SIFT_create()
        a = np.array([k.pt for k in sift.detect(image, None)])
        b = np.array([k.pt for k in sift.detect(mirrored, None)])
    b = b.copy()
    b[:, axis] = image.shape[1 - axis] - 1 - b[:, axis]
    i, j = pairs_by_position(a, b)
    return float(np.median(a[i, axis] - b[j, axis]) / 2), len(i)


def segment_offset(image, mirrored, axis):
    detect = cv2.line_descriptor.LSDDetector.createLSDDetector()
    ends = [np.array([[k.startPointX, k.startPointY, k.endPointX, k.endPointY] for k in detect.detect(im, 2, 1)
                      if k.lineLength > 30]) for im in (image, mirrored)]
    a, b = ends
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


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print("| image | axis | SIFT as detected (px) | SIFT, front end (px) | key point pairs | LSD (px) | segment pairs |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for path in sys.argv[1:]:
        image = cv2.imread(path, cv2.IMREAD_GRAYSCALE)
        if image is None:
            sys.exit(f"{path}: cannot be read as an image")
        for axis, name in ((0, "x"), (1, "y")):
            mirrored = cv2.flip(image, 1 if axis == 0 else 0)
            raw, n = sift_offset(image, mirrored, axis, False)
            fixed, _ = sift_offset(image, mirrored, axis, True)
            lsd, m = segment_offset(image, mirrored, axis)
            print(f"| {Path(path).name} | {name} | {raw:+.3f} | {fixed:+.3f} | {n} | {lsd:+.3f} | {m} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
