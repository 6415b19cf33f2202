# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Side-by-side speed of estimatePoseLinePointRansac and PoseLib's adaptive PnPL RANSAC.

    .venv/bin/python test/evaluation/ransac_vs_poselib.py --tool build/test/evaluation/tripose_evaluate \
        [--tool build-base/test/evaluation/tripose_evaluate] [--label after --label before] \
        [--points 100 --lines 40] [--outliers 0 0.5] [--rounds 3]

The same seeded synthetic scenes (tripose_evaluate synthetic, 1 px noise, --threshold px for both
methods) for every tool and outlier ratio; PoseLib (estimate_absolute_pose_pnpl, min_iterations 0)
runs on the structure tripose_evaluate triangulates from views 1-2 and is timed without that
triangulation. Every time is the median of --repeats calls on one scene; a table row gives the
median over the scenes. The tools and PoseLib alternate scene batch by scene batch (--rounds
passes over the ratios), so that machine load falls on all of them alike. Prints a Markdown table
with the ratio PoseLib time / tool time (above 1: tripose is faster).
"""

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run_evaluation import _poselib_pose, rotation_error_deg  # noqa: E402


def run_tool(tool, args):
    out = subprocess.run([str(tool)] + [str(a) for a in args], check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def run_tools(tools, args):
    """Each tool's trials on the same scenes, and the first tool's with their inputs dumped (what the
    peers run on): ({tool: trials}, dumped trials)."""
    trials, dumped = {}, None
    for tool in tools:
        trials[tool] = run_tool(tool, args + (["--dump-inputs"] if dumped is None else []))
        if dumped is None:
            dumped = trials[tool]
    return trials, dumped


def comparison_arguments(description, outliers):
    """The command line the side-by-side scripts share: the tools and their labels, the scenes and
    how often each is timed."""
    ap = argparse.ArgumentParser(description=description, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tool", action="append", required=True, help="tripose_evaluate binary (repeatable)")
    ap.add_argument("--label", action="append", default=[],
                    help="column title of each --tool, in their order (default: the build folder's name)")
    ap.add_argument("--points", type=int, default=100)
    ap.add_argument("--lines", type=int, default=40)
    ap.add_argument("--noise", type=float, default=1.0)
    ap.add_argument("--threshold", type=float, default=4.0)
    ap.add_argument("--outliers", type=float, nargs="*", default=outliers)
    ap.add_argument("--trials", type=int, default=10, help="scenes per batch")
    ap.add_argument("--rounds", type=int, default=3, help="batches per ratio (seeds differ per batch)")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--seed", type=int, default=7000)
    return ap


def tool_labels(a):
    """Each --tool's column title: its --label, else the name of the build folder it sits in."""
    names = [str(t) for t in a.tool]
    return names, a.label + [Path(n).parent.parent.parent.name or n for n in names[len(a.label):]]


def collect_method(results, per_tool, method):
    """Appends each tool's time (us; NaN where the method failed) and rotation error (deg; inf where it
    failed) of `method` to results[tool] = (times, errors)."""
    for name, trials in per_tool.items():
        for t in trials:
            m = t["methods"][method]
            results[name][0].append(m["time_us"] if m["ok"] else np.nan)
            results[name][1].append(m["rot_deg"] if m["ok"] else np.inf)


def poselib_trial(trial, repeats):
    inputs = trial["inputs"]
    R_gt = np.array(inputs["R_gt"], dtype=float)
    times, R = [], None
    for _ in range(repeats):
        R, _t, us = _poselib_pose(inputs, trial["threshold"], trial["seed"] * 100003 + trial["trial"], 0)
        times.append(us)
    return float(np.median(times)), rotation_error_deg(np.asarray(R), R_gt)


def main():
    ap = comparison_arguments(__doc__, [0.0, 0.3, 0.5, 0.6])
    ap.add_argument("--motion", default="large")
    a = ap.parse_args()

    names, labels = tool_labels(a)
    results = {r: {n: ([], []) for n in names + ["poselib-adaptive"]} for r in a.outliers}
    for rnd in range(a.rounds):
        for ratio in a.outliers:
            seed = a.seed + 1000 * rnd
            args = ["synthetic", "--points", a.points, "--lines", a.lines, "--noise", a.noise, "--outliers", ratio,
                    "--threshold", a.threshold, "--trials", a.trials, "--seed", seed, "--repeats", a.repeats,
                    "--motion", a.motion, "--methods", "ransac"]
            per_tool, dumped = run_tools(names, args)
            collect_method(results[ratio], per_tool, "ransac")
            for t in dumped:
                us, rot = poselib_trial(t, a.repeats)
                results[ratio]["poselib-adaptive"][0].append(us)
                results[ratio]["poselib-adaptive"][1].append(rot)

    print(f"{a.points}P+{a.lines}L, {a.noise} px noise, threshold {a.threshold} px, "
          f"{a.rounds * a.trials} scenes per ratio, median of {a.repeats} calls per scene")
    header = "| outliers |" + "".join(f" {label} ms (x PoseLib) | rot deg |"
                                      for label in labels) + " PoseLib adaptive ms | rot deg |"
    print(header)
    print("|" + " --- |" * (1 + 2 * len(names) + 2))
    for ratio in a.outliers:
        pl_t = np.nanmedian(results[ratio]["poselib-adaptive"][0]) / 1000
        pl_r = np.median(results[ratio]["poselib-adaptive"][1])
        row = f"| {100 * ratio:.0f} % |"
        for n in names:
            t = np.nanmedian(results[ratio][n][0]) / 1000
            fails = int(np.sum(~np.isfinite(results[ratio][n][1])))
            row += f" {t:.2f} (x{pl_t / t:.2f}) | {np.median(results[ratio][n][1]):.3f}{f' ({fails} failed)' if fails else ''} |"
        fails = int(np.sum(~np.isfinite(results[ratio]["poselib-adaptive"][1])))
        row += f" {pl_t:.2f} | {pl_r:.3f}{f' ({fails} failed)' if fails else ''} |"
        print(row, flush=True)


if __name__ == "__main__":
    main()
