# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""What the observations of a tracked sequence allow (doc/studies/real_images.md, "Tracking Model House from
images"): the last frame's drift when the tracks are registered frame by frame, and at the
maximum-likelihood fit of all frames at once, on the tracks as written and with every observation
more than 2 px or 1 px off at the sequence's cameras removed (which no tracker can do: it measures
how much of the drift the wrong links and the imprecise observations make).

    build/test/evaluation/tripose_track_vgg --data <VGG folder> [--from-images] --check-tracks 0 --output track.yml \
        --observations tracks.yml
    python test/evaluation/track_drift_limit.py --data <VGG folder> --observations tracks.yml [--window 5]

Needs the tripose package (pip install .). Frame by frame: as tripose_track --check-tracks 0 (frames
0 and 1 at the sequence's cameras, each later frame by estimate_pose_multiview_ransac against the
last --window frames with a pose, on the features it shares with two of them; 2 px, seed 0). The
fit of all frames: adjust_poses_multiview over every frame, frames 0 and 1 fixed, started from the
frame-by-frame poses, Huber loss at 2 px. An observation is off when it lies that far from the
structure fitted to its track at the sequence's cameras, the furthest of a track dropped first
(points by DLT; segments seen three times or more by the line that best fits their planes, the
larger of the end points' distances).
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

THRESHOLD = 2.0


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


def without_observations_off(points, lines, cameras, pixels):
    return (outliers_dropped(points, cameras, pixels, 2, point_from_views, point_offset),
            outliers_dropped(lines, cameras, pixels, 3, line_from_views,
                             lambda P, AB, s: max(segment_offsets(P, AB[0], AB[1], s))))


def seen_by(rows, frames, at_least):
    return np.sum([np.isfinite(rows[f][:, 0]) for f in frames], axis=0) >= at_least


def frame_by_frame(points, lines, K, given, window):
    poses = dict(given)
    for k in range(2, len(points)):
        frames = [f for f in range(k) if f in poses][-window:]
        rows = []
        for kind in (points, lines):
            shared = np.flatnonzero(np.isfinite(kind[k][:, 0]) & seen_by(kind, frames, 2))
            rows.append([kind[f][shared] for f in frames + [k]] if len(shared) else None)
        r = tripose.estimate_pose_multiview_ransac(rows[0], rows[1], [K[f] for f in frames + [k]],
                                                   [poses[f][0] for f in frames], [poses[f][1] for f in frames],
                                                   threshold=THRESHOLD, seed=0)
        if r["num_inliers"] > 0:
            poses[k] = (np.asarray(r["R"]), np.asarray(r["t"]).ravel())
    return poses


def fit_of_all_frames(points, lines, K, start):
    frames = sorted(start)
    rows = []
    for kind in (points, lines):
        keep = seen_by(kind, frames, 2)
        rows.append([kind[f][keep] for f in frames] if keep.any() else None)
    r = tripose.adjust_poses_multiview(rows[0], rows[1], [K[f] for f in frames], [f < 2 for f in frames],
                                       [start[f][0] for f in frames], [start[f][1] for f in frames],
                                       loss="huber", loss_scale=THRESHOLD)
    return {f: (np.asarray(R), np.asarray(t).ravel()) for f, R, t in zip(frames, r["Rs"], r["ts"])}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True)
    ap.add_argument("--observations", required=True, help="tripose_track --observations output")
    ap.add_argument("--window", type=int, default=5)
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
    cameras = [K[k] @ np.c_[truth[k][0], truth[k][1]] for k in range(len(points))]
    centre = {k: -R.T @ t for k, (R, t) in truth.items()}
    path = sum(np.linalg.norm(centre[k] - centre[k - 1]) for k in range(1, len(points)))
    last = len(points) - 1

    def drift(poses):
        if last not in poses:
            return "lost"
        R, t = poses[last]
        return f"{100 * np.linalg.norm(-R.T @ t - centre[last]) / path:.3f} %"

    print("| tracks | registered frame by frame | maximum-likelihood fit of all frames (Huber, 2 px) |")
    print("| --- | --- | --- |")
    for name, (p, l) in (("as written", (points, lines)),
                         ("observations more than 2 px off removed", without_observations_off(points, lines, cameras, 2)),
                         ("observations more than 1 px off removed", without_observations_off(points, lines, cameras, 1))):
        poses = frame_by_frame(p, l, K, {0: truth[0], 1: truth[1]}, a.window)
        fitted = fit_of_all_frames(p, l, K, poses) if len(poses) == len(points) else {}
        print(f"| {name} | {drift(poses)} | {drift(fitted)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
