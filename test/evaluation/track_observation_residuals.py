# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How well the tracks that tripose_track builds from images fit the sequence's own cameras
(doc/real_images.md, "Tracking Model House from images").

    build/samples/tripose_track --data <VGG folder with images> --from-images --output track.yml \
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
        points.append(fs.getNode(f"points{len(points)}").mat())
        lines.append(fs.getNode(f"lines{len(lines)}").mat())
    fs.release()
    return points, lines


def point_residuals(points, cameras):
    res = np.full((len(points), len(points[0])), np.nan)
    for i in range(len(points[0])):
        seen = [k for k in range(len(points)) if np.isfinite(points[k][i, 0])]
        if len(seen) < 2:
            continue
        A = np.array([row for k in seen for row in (points[k][i, 0] * cameras[k][2] - cameras[k][0],
                                                    points[k][i, 1] * cameras[k][2] - cameras[k][1])])
        X = np.linalg.svd(A / np.linalg.norm(A, axis=1, keepdims=True))[2][-1]
        for k in seen:
            h = cameras[k] @ X
            res[k, i] = np.linalg.norm(h[:2] / h[2] - points[k][i])
    return res


def segment_residuals(lines, cameras):
    res = np.full((len(lines), len(lines[0]) if len(lines[0]) else 0), np.nan)
    for i in range(res.shape[1]):
        seen = [k for k in range(len(lines)) if np.isfinite(lines[k][i, 0])]
        if len(seen) < 3:
            continue
        planes = []
        for k in seen:
            s = lines[k][i]
            l = np.cross([s[0], s[1], 1.0], [s[2], s[3], 1.0])
            planes.append(cameras[k].T @ (l / np.hypot(l[0], l[1])))
        planes = np.array(planes)
        A, B = np.linalg.svd(planes / np.linalg.norm(planes[:, :3], axis=1, keepdims=True))[2][-2:]
        for k in seen:
            l = np.cross(cameras[k] @ A, cameras[k] @ B)
            l /= np.hypot(l[0], l[1])
            s = lines[k][i]
            res[k, i] = np.sqrt(np.mean([(l @ [s[0], s[1], 1.0]) ** 2, (l @ [s[2], s[3], 1.0]) ** 2]))
    return res


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
