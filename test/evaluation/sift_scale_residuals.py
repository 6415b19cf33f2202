# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How precisely SIFT places a point, by the size of its key point (doc/studies/real_images.md, "Tracking
Model House from images"): on every consecutive triplet of a VGG sequence with images, the point
tracks of samples/python/pose_from_images.py (triplet_rows(): views 1-2 matched under their pose,
view 3 under the fundamental matrix of its descriptor matches) are triangulated at the sequence's cameras (DLT) and
each track's largest residual over its three views is binned by the largest key point size (px).

    .venv/bin/python test/evaluation/sift_scale_residuals.py --data <VGG folder with images>
"""

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np

root = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "samples" / "python"))
sys.path.insert(0, str(root / "test" / "evaluation"))
import pose_from_images as front  # noqa: E402
import vgg  # noqa: E402
from track_observation_residuals import point_from_views, point_offset  # noqa: E402

BINS = (0, 3, 5, 8, 12, 20, np.inf)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True)
    a = ap.parse_args()
    images = sorted(p for p in Path(a.data).iterdir() if p.suffix.lower() in (".pgm", ".png", ".jpg", ".ppm"))
    sizes, residuals = [], []
    for first in range(len(images) - 2):
        t = vgg.load_triplet(a.data, (first, first + 1, first + 2))
        views = []
        for i in range(3):
            image = cv2.imread(str(images[first + i]), cv2.IMREAD_GRAYSCALE)
            views.append(front.extract(image, t.K[i], None, "points"))
        rows = front.triplet_rows(views, t.K, t.R12, t.t12)["points"]
        cameras = [t.K[0] @ np.eye(3, 4), t.K[1] @ np.c_[t.R12, t.t12], t.K[2] @ np.c_[t.R, t.t]]
        for j in range(len(rows[0])):
            xs = [views[i]["points"][rows[i][j]] for i in range(3)]
            X = point_from_views(xs, cameras)
            residuals.append(max(point_offset(cameras[i], X, xs[i]) for i in range(3)))
            sizes.append(max(views[i]["point_size"][rows[i][j]] for i in range(3)))
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
