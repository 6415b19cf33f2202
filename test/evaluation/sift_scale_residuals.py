# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How precisely SIFT places a point, by the size of its key point (doc/studies/real_images.md, "Tracking
Model House from images"): on every consecutive triplet of a VGG sequence with images, the point
tracks of tripose.match_triplets (views 1-2 matched under their pose, view 3 under the fundamental
matrix of its descriptor matches) on tripose.images' SIFT points are triangulated at the sequence's
cameras (DLT) and each track's largest residual over its three views is binned by the largest key
point size (px). The library does not return the key point sizes: SIFT is run again here (cv2) on
the same image, its key points found at the library's point positions.

    python test/evaluation/sift_scale_residuals.py --data <VGG folder with images>

Needs the tripose package with its images extra (pip install ".[images]").
"""

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np
import tripose
import tripose.images as images

root = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "samples" / "python"))
sys.path.insert(0, str(root / "test" / "evaluation"))
import vgg  # noqa: E402
from track_observation_residuals import point_from_views, point_offset  # noqa: E402

BINS = (0, 3, 5, 8, 12, 20, np.inf)
# tripose.images' SIFT positions: 0.25 px up and left of cv2's key points (its doubled first octave).
SIFT_UPSAMPLING_OFFSET = 0.25


def key_point_sizes(image, points, options):
    """The diameter (px of the image) of the SIFT key point at each of points (tripose.images'
    positions of the image, not undistorted): SIFT with the same settings on the same detection image
    (reduced as extract_features reduces it when larger than options.max_image_size)."""
    scale = images.detection_scale(image.shape, options.max_image_size)
    factor = np.ones(2)
    if scale > 1:
        h, w = image.shape[:2]
        size = (max(1, int(w / scale + 0.5)), max(1, int(h / scale + 0.5)))
        image = cv2.resize(image, size, interpolation=cv2.INTER_AREA)
        factor = np.array([w / size[0], h / size[1]])
    keypoints, _ = cv2.SIFT_create(int(options.max_points)).detectAndCompute(image, None)
    xy = np.array([k.pt for k in keypoints], np.float64).reshape(-1, 2) - SIFT_UPSAMPLING_OFFSET
    if scale > 1:
        xy = (xy + 0.5) * factor - 0.5
    sizes = np.array([k.size for k in keypoints]) * factor.max()
    if xy.shape == points.shape and np.array_equal(xy, points):
        return sizes
    # Another order: each point's key point by position (several orientations of one key point share it).
    nearest = np.array([np.argmin(np.sum((xy - p) ** 2, axis=1)) for p in points], int).reshape(-1)
    offsets = np.linalg.norm(xy[nearest] - points, axis=1) if len(points) else np.zeros(0)
    if np.any(offsets > 1e-6):
        sys.exit(f"no SIFT key point at {int(np.sum(offsets > 1e-6))} of the {len(points)} points of tripose.images")
    return sizes[nearest]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True)
    a = ap.parse_args()
    files = sorted(p for p in Path(a.data).iterdir() if p.suffix.lower() in (".pgm", ".png", ".jpg", ".ppm"))
    options = images.FeatureOptions(kinds="points")
    sizes, residuals = [], []
    for first in range(len(files) - 2):
        t = vgg.load_triplet(a.data, (first, first + 1, first + 2))
        views, point_sizes = [], []
        for i in range(3):
            image = images.read_image(files[first + i])
            views.append(images.extract_features(image, t.K[i], None, options))
            point_sizes.append(key_point_sizes(image, views[i]["points"], options))
        triplets = tripose.match_triplets(*views, list(t.K), t.R12, t.t12)
        rows = [triplets[f"point_rows{i + 1}"] for i in range(3)]
        cameras = [t.K[0] @ np.eye(3, 4), t.K[1] @ np.c_[t.R12, t.t12], t.K[2] @ np.c_[t.R, t.t]]
        for j in range(len(rows[0])):
            xs = [views[i]["points"][rows[i][j]] for i in range(3)]
            X = point_from_views(xs, cameras)
            residuals.append(max(point_offset(cameras[i], X, xs[i]) for i in range(3)))
            sizes.append(max(point_sizes[i][rows[i][j]] for i in range(3)))
    sizes, residuals = np.array(sizes), np.array(residuals)
    print(f"{len(sizes)} point tracks")
    print("| key point size (px) | tracks | median of the largest residual (px) | 80th percentile | share > 2 px |")
    print("| --- | --- | --- | --- | --- |")
    for lo, hi in zip(BINS[:-1], BINS[1:]):
        m = (sizes >= lo) & (sizes < hi)
        if m.any():
            label = f"{lo}-{hi}" if np.isfinite(hi) else f">= {lo}"
            print(f"| {label} | {m.sum()} | {np.median(residuals[m]):.2f} | {np.percentile(residuals[m], 80):.2f} | "
                  f"{np.mean(residuals[m] > 2):.0%} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
