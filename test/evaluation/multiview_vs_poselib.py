# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Side-by-side speed and accuracy of estimatePoseMultiViewRansac and PoseLib's adaptive PnPL RANSAC.

    .venv/bin/python test/evaluation/multiview_vs_poselib.py --tool build/test/evaluation/tripose_evaluate \\
        [--tool build-before/test/evaluation/tripose_evaluate] [--label after --label before] \\
        [--known 4] [--points 100 --lines 40] [--outliers 0 0.5] [--trials 10 --rounds 3]

The same seeded scenes (tripose_evaluate multiview: --known views and a new one about 20 m around a
10 m cube, every feature seen by the new view and at least two known views, --noise px, wrong
matches in the new view) for every method:
- tripose: estimatePoseMultiViewRansac, RANSAC + refinement over every view (--threshold px);
- PoseLib: estimate_absolute_pose_pnpl (LO-RANSAC and bundle adjustment, min_iterations 0, the
  threshold divided by the focal length) in the new view on the structure triangulated from the known
  views (points: linear least squares over every known view that sees them; lines: the first known
  view's observed end points lifted onto the planes of the others), timed without that
  triangulation, as test/evaluation/ransac_vs_poselib.py times it.
Every time is the median of --repeats calls on one scene; a row gives the median over the scenes,
the ratio PoseLib time / tool time (above 1: tripose is faster), the median rotation error and the
slowest scene over the median one. The tools and PoseLib alternate batch by batch (--rounds passes
over the ratios), so that machine load falls on all of them alike.
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ransac_vs_poselib import collect_method, comparison_arguments, run_tools, tool_labels  # noqa: E402
from run_evaluation import _poselib_pose, rotation_error_deg  # noqa: E402


def _known_projections(inputs):
    """K^-1 and the 3x4 [R | t] of every known view."""
    K = np.array(inputs["K"], dtype=float)
    Rs = [np.array(R, dtype=float) for R in inputs["Rs"]]
    ts = [np.array(t, dtype=float).reshape(3) for t in inputs["ts"]]
    return np.linalg.inv(K), [np.c_[R, t] for R, t in zip(Rs, ts)]


def _homogeneous(Kinv, xy):
    return np.c_[np.asarray(xy, dtype=float).reshape(-1, 2), np.ones(len(np.asarray(xy).reshape(-1, 2)))] @ Kinv.T


def triangulate_known(inputs):
    """Structure of the known views: (N x 3 points, M x 6 segments), NaN rows where it is undetermined
    or lands behind a known view that sees it."""
    Kinv, P = _known_projections(inputs)
    known = len(P)
    points = [np.array(v, dtype=float).reshape(-1, 2) for v in inputs["points"][:known]] if inputs["points"] else []
    lines = [np.array(v, dtype=float).reshape(-1, 4) for v in inputs["lines"][:known]] if inputs["lines"] else []

    n = len(points[0]) if points else 0
    X = np.full((n, 3), np.nan)
    for i in range(n):
        seen = [v for v in range(known) if np.all(np.isfinite(points[v][i]))]
        rows = []
        for v in seen:
            x = _homogeneous(Kinv, points[v][i])[0]
            rows += [x[0] * P[v][2] - P[v][0], x[1] * P[v][2] - P[v][1]]
        if len(seen) < 2:
            continue
        h = np.linalg.svd(np.array(rows))[2][-1]
        if abs(h[3]) < 1e-12:
            continue
        Xi = h[:3] / h[3]
        if all((P[v][:, :3] @ Xi + P[v][:, 3])[2] > 0 for v in seen):
            X[i] = Xi

    m = len(lines[0]) if lines else 0
    L = np.full((m, 6), np.nan)
    for i in range(m):
        seen = [v for v in range(known) if np.all(np.isfinite(lines[v][i]))]
        if len(seen) < 2:
            continue
        planes = []
        for v in seen:
            a, b = _homogeneous(Kinv, lines[v][i][:2])[0], _homogeneous(Kinv, lines[v][i][2:])[0]
            plane = np.cross(a, b) @ P[v]  # l^T [R | t]: the plane through the camera centre and the line
            planes.append(plane / np.linalg.norm(plane[:3]))
        first = seen[0]
        R, t = P[first][:, :3], P[first][:, 3]
        centre = -R.T @ t
        ends = []
        for end in (lines[first][i][:2], lines[first][i][2:]):
            # The ray of the first known view through the end point, to where it best meets the other planes.
            d = R.T @ _homogeneous(Kinv, end)[0]
            num = sum((p[:3] @ centre + p[3]) * (p[:3] @ d) for p in planes[1:])
            den = sum((p[:3] @ d) ** 2 for p in planes[1:])
            s = -num / den if den > 0 else np.nan
            ends.append(centre + s * d if s > 0 else np.full(3, np.nan))
        Li = np.r_[ends[0], ends[1]]
        if np.all(np.isfinite(Li)) and all((P[v][:, :3] @ e + P[v][:, 3])[2] > 0 for v in seen for e in ends):
            L[i] = Li
    return X, L


def poselib_inputs(inputs):
    """The new view's observations and the known views' structure, as _poselib_pose reads a three-view dump."""
    X, L = triangulate_known(inputs)
    K = np.array(inputs["K"], dtype=float)
    empty_points, empty_lines = np.zeros((0, 2)), np.zeros((0, 4))
    return {"K": [K, K, K],
            "points3d_12": X if len(X) else np.zeros((0, 3)),
            "points3": np.array(inputs["points"][-1], dtype=float).reshape(-1, 2) if inputs["points"] else empty_points,
            "lines3d_12": L if len(L) else np.zeros((0, 6)),
            "lines3": np.array(inputs["lines"][-1], dtype=float).reshape(-1, 4) if inputs["lines"] else empty_lines}


def poselib_trial(trial, repeats):
    inputs = trial["inputs"]
    R_gt = np.array(inputs["R_gt"], dtype=float)
    structure = poselib_inputs(inputs)
    times, R = [], None
    for _ in range(repeats):
        R, _t, us = _poselib_pose(structure, trial["threshold"], trial["seed"] * 100003 + trial["trial"], 0)
        times.append(us)
    return float(np.median(times)), rotation_error_deg(np.asarray(R), R_gt)


def main():
    ap = comparison_arguments(__doc__, [0.0, 0.5])
    ap.add_argument("--known", type=int, default=4)
    a = ap.parse_args()

    names, labels = tool_labels(a)
    results = {r: {n: ([], []) for n in names + ["poselib"]} for r in a.outliers}
    for rnd in range(a.rounds):
        for ratio in a.outliers:
            seed = a.seed + 1000 * rnd
            args = ["multiview", "--known", a.known, "--points", a.points, "--lines", a.lines, "--noise", a.noise,
                    "--outliers", ratio, "--threshold", a.threshold, "--trials", a.trials, "--seed", seed,
                    "--repeats", a.repeats, "--methods", "multiview_ransac"]
            per_tool, dumped = run_tools(names, args)
            collect_method(results[ratio], per_tool, "multiview_ransac")
            for t in dumped:
                us, rot = poselib_trial(t, a.repeats)
                results[ratio]["poselib"][0].append(us)
                results[ratio]["poselib"][1].append(rot)

    print(f"{a.known} known views, {a.points}P+{a.lines}L, {a.noise} px noise, threshold {a.threshold} px, "
          f"{a.rounds * a.trials} scenes per ratio, median of {a.repeats} calls per scene")
    print("| outliers |" + "".join(f" {label} ms | rot deg | slowest / median |" for label in labels) +
          " PoseLib adaptive ms (x first) | rot deg | slowest / median |")
    print("|" + " --- |" * (1 + 3 * len(names) + 3))

    def cell(times_us, rots):
        times = np.asarray(times_us) / 1000
        rots = np.asarray(rots)
        fails = int(np.sum(~np.isfinite(rots)))
        return (np.nanmedian(times), np.median(rots), np.nanmax(times) / np.nanmedian(times),
                f" ({fails} failed)" if fails else "")

    for ratio in a.outliers:
        row = f"| {100 * ratio:.0f} % |"
        first = None
        for n in names:
            t, rot, tail, failed = cell(*results[ratio][n])
            first = t if first is None else first
            row += f" {t:.2f} | {rot:.3f}{failed} | {tail:.1f} |"
        t, rot, tail, failed = cell(*results[ratio]["poselib"])
        row += f" {t:.2f} (x{t / first:.2f}) | {rot:.3f}{failed} | {tail:.1f} |"
        print(row, flush=True)


if __name__ == "__main__":
    main()
