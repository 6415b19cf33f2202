# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Side-by-side speed and accuracy of the stereo rig's robust estimate and what a rig user would
otherwise run.

    .venv/bin/python test/evaluation/rig_vs_peers.py --tool build/test/evaluation/tripose_evaluate \\
        [--tool build-before/test/evaluation/tripose_evaluate] [--label after --label before] \\
        [--points 100 --lines 40] [--outliers 0 0.5] [--trials 10 --rounds 3]

The same seeded scenes (tripose_evaluate stereo: a 0.1-0.5 m rig, structure at 5-30 m, motion
0.3-3 m, a fifth of the features seen by one time-B camera only, 1 px noise, wrong matches at time
B) for every method:
- tripose: estimatePoseLinePointStereoRansac, RANSAC + refinement over the four views
  (--threshold px);
- PoseLib: estimate_generalized_absolute_pose (LO-RANSAC and bundle adjustment, min_iterations 0)
  with both time-B cameras, points only, on the points triangulated from the rig at time A;
- OpenCV: solvePnPRansac (AP3P, 10000 iterations at most, confidence 0.999) in the left time-B
  camera on the same points, then solvePnPRefineLM on its inliers;
- the four-view maximum-likelihood refinement from the true pose on the true matches
  (refinePoseLinePointStereo): the accuracy the observations allow, for the count of scenes where
  the estimate stops short of it.
The peers are timed without the triangulation. Every time is the median of --repeats calls on one
scene; a row gives the median over the scenes, the ratio peer time / tripose time (above 1: tripose
is faster), the median rotation error, tripose's slowest scene over its median, and the scenes in
which tripose is more than 0.5 degrees off while the refinement from the truth is within 0.1.
"""

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ransac_vs_poselib import comparison_arguments, run_tools, tool_labels  # noqa: E402
from run_evaluation import rotation_error_deg  # noqa: E402

OFF_DEG = 0.5
LIMIT_DEG = 0.1


def rig_views(inputs):
    """The time-B observations of each camera with the rig-A structure: (x normalised, X) per camera."""
    K = [np.array(k, dtype=float) for k in inputs["K"]]
    X = np.asarray(inputs["points3d_12"], dtype=float).reshape(-1, 3)
    views = []
    for key, Kv in (("points3", K[2]), ("points4", K[3])):
        x = np.asarray(inputs[key], dtype=float).reshape(-1, 2)
        keep = np.all(np.isfinite(x), axis=1) & np.all(np.isfinite(X), axis=1)
        h = np.c_[x[keep], np.ones(int(keep.sum()))] @ np.linalg.inv(Kv).T
        views.append((h[:, :2] / h[:, 2:3], X[keep], x[keep]))
    return views, K


def poselib_generalized(inputs, threshold_px, seed):
    """PoseLib's generalized absolute pose RANSAC on @inputs (a "rig_inputs" dump): R, t of the left
    time-B camera and the call's time (us), the triangulation not included."""
    import poselib

    views, K = rig_views(inputs)
    focal = 0.5 * (K[2][0, 0] + K[2][1, 1])
    left = poselib.CameraPose()
    right = poselib.CameraPose()
    right.R = np.array(inputs["R12"], dtype=float)
    right.t = np.array(inputs["t12"], dtype=float).reshape(3)
    camera = {"model": "PINHOLE", "width": 2, "height": 2, "params": [1.0, 1.0, 0.0, 0.0]}
    ransac = {"max_reproj_error": threshold_px / focal, "seed": seed, "min_iterations": 0}
    t0 = time.perf_counter()
    pose, _info = poselib.estimate_generalized_absolute_pose([v[0] for v in views], [v[1] for v in views],
                                                             [left, right], [camera, camera], ransac, {})
    elapsed = 1e6 * (time.perf_counter() - t0)
    return np.asarray(pose.R), np.asarray(pose.t), elapsed


def opencv_pnp(inputs, threshold_px):
    import cv2

    cv2.setNumThreads(1)  # one thread, as tripose and PoseLib run
    views, K = rig_views(inputs)
    _x, X, pixels = views[0]
    t0 = time.perf_counter()
    ok, rvec, tvec, inliers = cv2.solvePnPRansac(X, pixels, K[2], None, iterationsCount=10000,
                                                 reprojectionError=threshold_px, confidence=0.999,
                                                 flags=cv2.SOLVEPNP_AP3P)
    if ok and inliers is not None and len(inliers) >= 4:
        inliers = inliers.ravel()
        rvec, tvec = cv2.solvePnPRefineLM(X[inliers], pixels[inliers], K[2], None, rvec, tvec)
    elapsed = 1e6 * (time.perf_counter() - t0)
    if not ok:
        return None, None, elapsed
    return cv2.Rodrigues(rvec)[0], tvec.ravel(), elapsed


def peer_trial(trial, repeats, threshold):
    inputs = trial["rig_inputs"]
    R_gt = np.array(inputs["R_gt"], dtype=float)
    out = {}
    for name, call in (("poselib", lambda: poselib_generalized(inputs, threshold, trial["seed"] * 1009 + trial["trial"])),
                       ("opencv", lambda: opencv_pnp(inputs, threshold))):
        times, R = [], None
        for _ in range(repeats):
            R, _t, us = call()
            times.append(us)
        out[name] = (float(np.median(times)), rotation_error_deg(np.asarray(R), R_gt) if R is not None else np.inf)
    return out


def main():
    ap = comparison_arguments(__doc__, [0.0, 0.5])
    a = ap.parse_args()

    names, labels = tool_labels(a)
    peers = ["poselib", "opencv"]
    results = {r: {n: {"time": [], "rot": [], "limit": []} for n in names + peers} for r in a.outliers}
    for rnd in range(a.rounds):
        for ratio in a.outliers:
            seed = a.seed + 1000 * rnd
            args = ["stereo", "--points", a.points, "--lines", a.lines, "--noise", a.noise, "--outliers", ratio,
                    "--threshold", a.threshold, "--trials", a.trials, "--seed", seed, "--repeats", a.repeats,
                    "--methods", "stereo_ransac,stereo_ml_from_truth"]
            per_tool, dumped = run_tools(names, args)
            for name in names:
                for t in per_tool[name]:
                    m, limit = t["methods"]["stereo_ransac"], t["methods"]["stereo_ml_from_truth"]
                    cell = results[ratio][name]
                    cell["time"].append(m["time_us"] if m["ok"] else np.nan)
                    cell["rot"].append(m["rot_deg"] if m["ok"] else np.inf)
                    cell["limit"].append(limit["rot_deg"] if limit["ok"] else np.inf)
            for t in dumped:
                for name, (us, rot) in peer_trial(t, a.repeats, a.threshold).items():
                    results[ratio][name]["time"].append(us)
                    results[ratio][name]["rot"].append(rot)

    print(f"stereo rig {a.points}P+{a.lines}L, {a.noise} px noise, threshold {a.threshold} px, "
          f"{a.rounds * a.trials} scenes per ratio, median of {a.repeats} calls per scene")
    print("| outliers |" + "".join(f" {label} ms | rot deg | slowest / median | off (> {OFF_DEG} deg, limit "
                                   f"< {LIMIT_DEG}) |" for label in labels) +
          " PoseLib generalized ms | rot deg | solvePnPRansac + RefineLM ms | rot deg |")
    print("|" + " --- |" * (1 + 4 * len(names) + 4))
    for ratio in a.outliers:
        row = f"| {100 * ratio:.0f} % |"
        first = np.nanmedian(results[ratio][names[0]]["time"]) / 1000
        for n in names:
            cell = results[ratio][n]
            times = np.asarray(cell["time"]) / 1000
            rot, limit = np.asarray(cell["rot"]), np.asarray(cell["limit"])
            off = int(np.sum((rot > OFF_DEG) & (limit < LIMIT_DEG)))
            fails = int(np.sum(~np.isfinite(rot)))
            row += (f" {np.nanmedian(times):.2f} | {np.median(rot):.3f}{f' ({fails} failed)' if fails else ''} |"
                    f" {np.nanmax(times) / np.nanmedian(times):.1f} | {off} |")
        for p in peers:
            cell = results[ratio][p]
            t = np.median(cell["time"]) / 1000
            fails = int(np.sum(~np.isfinite(cell["rot"])))
            row += f" {t:.2f} (x{t / first:.2f}) | {np.median(cell['rot']):.3f}{f' ({fails} failed)' if fails else ''} |"
        print(row, flush=True)


if __name__ == "__main__":
    main()
