# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Whether tracks chained from image matches should be checked against the frames' poses before a
new frame is registered from them (doc/real_images.md, "Tracking Model House from images"): a study,
not what tripose_track does.

    build/samples/tripose_track --data <VGG folder with images> --from-images --output track.yml \
        --observations tracks.yml
    python test/evaluation/track_verification_study.py --data <VGG folder> --observations tracks.yml \
        [--window 5] [--threshold 2]

Needs the tripose package (pip install .). Tracks the sequence as tripose_track does (frames 0 and
1 given, every later frame registered by estimate_pose_multiview_ransac against the last --window
frames with a pose, on the features it shares with at least two of them), twice: as it is, and with
each feature's observations in the window checked first: triangulated from them at the window's
poses (points by DLT; segments seen three times or more by the line that best fits their planes),
the observation furthest from its reprojection dropped while it is more than --threshold px off, and
the feature left out when fewer than two observations remain. The first run reproduces
tripose_track's figures. Prints per frame the rotation error (deg) and the position error (% of the
path) of both.
"""

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np
import tripose

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "samples" / "python"))
import vgg  # noqa: E402
from track_observation_residuals import (line_from_views, point_from_views, point_offset,  # noqa: E402
                                         read_observations, segment_offsets)


def outliers_dropped(rows, cameras, threshold, min_views, fit, offset):
    """rows (one array per camera, NaN where unseen) with, per feature seen min_views times or more,
    the observation furthest from the fitted structure dropped while it is more than threshold px
    off; a point left in two views that disagree loses both."""
    out = [r.copy() for r in rows]
    for i in range(len(out[0])):
        while True:
            views = [j for j in range(len(out)) if np.isfinite(out[j][i, 0])]
            if len(views) < min_views:
                break
            structure = fit([out[j][i] for j in views], [cameras[j] for j in views])
            off = [offset(cameras[j], structure, out[j][i]) for j in views]
            worst = int(np.argmax(off))
            if off[worst] <= threshold:
                break
            for j in (views if len(views) == 2 else [views[worst]]):
                out[j][i] = np.nan
    return out


def point_outliers_dropped(rows, cameras, threshold):
    return outliers_dropped(rows, cameras, threshold, 2, point_from_views, point_offset)


def segment_outliers_dropped(rows, cameras, threshold):
    return outliers_dropped(rows, cameras, threshold, 3, line_from_views,
                            lambda P, AB, s: max(segment_offsets(P, AB[0], AB[1], s)))


def track(points, lines, K, truth, window, threshold, verify):
    poses = {0: truth[0], 1: truth[1]}
    for k in range(2, len(points)):
        frames = [f for f in range(k) if f in poses][-window:]
        rows = []
        for kind in (points, lines):
            seen = [np.isfinite(kind[f][:, 0]) for f in frames]
            shared = np.flatnonzero(np.isfinite(kind[k][:, 0]) & (np.sum(seen, axis=0) >= 2))
            rows.append([kind[f][shared] for f in frames] + [kind[k][shared]])
        if verify:
            cameras = [K[f] @ np.c_[poses[f][0], poses[f][1]] for f in frames]
            for r, drop in ((0, point_outliers_dropped), (1, segment_outliers_dropped)):
                known = drop(rows[r][:-1], cameras, threshold)
                keep = np.sum([np.isfinite(v[:, 0]) for v in known], axis=0) >= 2
                rows[r] = [v[keep] for v in known] + [rows[r][-1][keep]]
        result = tripose.estimate_pose_multiview_ransac(rows[0], rows[1], [K[f] for f in frames] + [K[k]],
                                                        [poses[f][0] for f in frames], [poses[f][1] for f in frames],
                                                        threshold=threshold, seed=0)
        if result["num_inliers"] > 0:
            poses[k] = (np.asarray(result["R"]), np.asarray(result["t"]).ravel())
    return poses


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True)
    ap.add_argument("--observations", required=True, help="tripose_track --observations output")
    ap.add_argument("--window", type=int, default=5)
    ap.add_argument("--threshold", type=float, default=2.0)
    a = ap.parse_args()
    points, lines = read_observations(a.observations)
    fs = cv2.FileStorage(a.observations, cv2.FILE_STORAGE_READ)
    K = [fs.getNode(f"K{k}").mat() for k in range(len(points))]
    fs.release()
    # The sequence's poses in frame 0's camera frame, as tripose_track reads them.
    truth = {0: (np.eye(3), np.zeros(3))}
    for k in range(1, len(points)):
        t = vgg.load_triplet(a.data, (0, 1, max(k, 2)))
        truth[k] = (t.R12, t.t12) if k == 1 else (t.R, t.t)
    centre = {k: -R.T @ t for k, (R, t) in truth.items()}
    path = sum(np.linalg.norm(centre[k] - centre[k - 1]) for k in range(1, len(points)))
    runs = [track(points, lines, K, truth, a.window, a.threshold, verify) for verify in (False, True)]
    print("| frame | rotation (deg), as tracked | checked | position (% of path), as tracked | checked |")
    print("| --- | --- | --- | --- | --- |")
    for k in range(2, len(points)):
        cells = []
        for measure in ("rotation", "position"):
            for poses in runs:
                if k not in poses:
                    cells.append("lost")
                    continue
                R, t = poses[k]
                if measure == "rotation":
                    cells.append(f"{np.degrees(np.linalg.norm(cv2.Rodrigues(R @ truth[k][0].T)[0])):.3f}")
                else:
                    cells.append(f"{100 * np.linalg.norm(-R.T @ t - centre[k]) / path:.3f}")
        print(f"| {k} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
