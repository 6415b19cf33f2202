# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How well the tracks that tripose_track builds from images fit the sequence's own cameras
(doc/studies/real_images.md, "Tracking Model House from images").

    build/test/evaluation/tripose_track_vgg --data <VGG folder with images> --from-images --output track.yml \
        --observations tracks.yml
    .venv/bin/python test/evaluation/track_observation_residuals.py --data <VGG folder> --observations tracks.yml

Each point track is triangulated from all frames that see it with the sequence's cameras (DLT), each
segment track seen in three frames or more gets the 3D line that best fits its frames' planes; per
frame the table gives the residuals of the observations at those cameras (px): median, and the
shares above 1 and 2 px. A wrong link of a track shows as a residual of pixels in some frame.
"""

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np


def read_observations(path):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    if not fs.isOpened():
        sys.exit(f"{path}: cannot be read")
    points, lines = [], []
    while not fs.getNode(f"points{len(points)}").empty():
        frame = len(points)
        # A sequence without one kind of feature writes it as an empty matrix.
        for name, columns, kind in (("points", 2, points), ("lines", 4, lines)):
            rows = fs.getNode(f"{name}{frame}").mat()
            kind.append(np.zeros((0, columns)) if rows is None else rows)
    fs.release()
    return points, lines


def point_from_views(xs, cameras):
    """The homogeneous point (4-vector) whose projections by cameras (3x4) best fit xs (pixels, one per
    camera): DLT, each row normalised."""
    A = np.array([row for x, P in zip(xs, cameras) for row in (x[0] * P[2] - P[0], x[1] * P[2] - P[1])])
    return np.linalg.svd(A / np.linalg.norm(A, axis=1, keepdims=True))[2][-1]


def point_offset(P, X, x):
    """Distance (px) of x from the projection of X by P (the sequence's camera matrices come with
    either sign, so no side of the camera is told apart)."""
    h = P @ X
    return float(np.linalg.norm(h[:2] / h[2] - x))


def line_from_views(segments, cameras):
    """Two homogeneous points spanning the 3D line that best fits the planes through each camera and
    its segment (x0 y0 x1 y1)."""
    planes = []
    for s, P in zip(segments, cameras):
        line = np.cross([s[0], s[1], 1.0], [s[2], s[3], 1.0])
        planes.append(P.T @ (line / np.hypot(line[0], line[1])))
    planes = np.array(planes)
    return np.linalg.svd(planes / np.linalg.norm(planes[:, :3], axis=1, keepdims=True))[2][-2:]


def segment_offsets(P, A, B, s):
    """Distances (px) of the segment's end points from the projection of the line through A and B."""
    line = np.cross(P @ A, P @ B)
    line /= np.hypot(line[0], line[1])
    return abs(line @ [s[0], s[1], 1.0]), abs(line @ [s[2], s[3], 1.0])


def residuals_per_frame(rows, cameras, min_views, fit, offset):
    """(frames x features) residuals (px) of each feature's observations (rows: one array per frame,
    NaN where unseen) at the structure fitted to those of the features seen min_views times or more;
    NaN elsewhere."""
    res = np.full((len(rows), len(rows[0])), np.nan)
    for i in range(len(rows[0])):
        seen = [k for k in range(len(rows)) if np.isfinite(rows[k][i, 0])]
        if len(seen) < min_views:
            continue
        structure = fit([rows[k][i] for k in seen], [cameras[k] for k in seen])
        for k in seen:
            res[k, i] = offset(cameras[k], structure, rows[k][i])
    return res


def point_residuals(points, cameras):
    return residuals_per_frame(points, cameras, 2, point_from_views, point_offset)


def segment_residuals(lines, cameras):
    """Segments seen in three frames or more (two always fit a line); the RMS of the two end points."""
    return residuals_per_frame(lines, cameras, 3, line_from_views,
                               lambda P, AB, s: np.sqrt(np.mean(np.square(segment_offsets(P, AB[0], AB[1], s)))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, help="the VGG sequence folder (its *.P cameras)")
    ap.add_argument("--observations", required=True, help="tripose_track --observations output")
    a = ap.parse_args()
    # Residuals do not depend on the world frame: the sequence's camera matrices serve as they are.
    cameras = [np.loadtxt(p) for p in sorted(Path(a.data).glob("*.P"))]
    points, lines = read_observations(a.observations)
    if len(points) != len(cameras):
        sys.exit(f"{a.observations} has {len(points)} frames, {a.data} {len(cameras)} cameras")
    rp, rl = point_residuals(points, cameras), segment_residuals(lines, cameras)
    print("| frame | points | median (px) | > 1 px | > 2 px | segments (3+ frames) | median (px) | > 1 px | > 2 px |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for k in range(len(cameras)):
        row = [str(k)]
        for r in (rp[k], rl[k]):
            r = r[np.isfinite(r)]
            row += [str(len(r))] + ([f"{np.median(r):.2f}", f"{np.mean(r > 1):.0%}", f"{np.mean(r > 2):.0%}"]
                                    if len(r) else ["-"] * 3)
        print("| " + " | ".join(row) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
