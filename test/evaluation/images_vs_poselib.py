# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""PoseLib's PnPL beside tripose on the image front end's matches (doc/studies/real_images.md).

    .venv/bin/python test/evaluation/images_vs_poselib.py --data <VGG folder with images> \
        [--tool build/test/evaluation/tripose_images_report] [--threshold 2] [--seed 0]

Runs tripose_images_report --dump-inputs on the sequence: for every run of three consecutive frames,
the point tracks and segment triplets the front end found, and their structure triangulated from
views 1-2 (points by DLT; a segment's end points by their view-1 rays cut by the plane of the view-2
segment, dropped where that ray runs within about a degree of the plane). PoseLib's
estimate_absolute_pose_pnpl (LO-RANSAC with its default settings, then its bundle adjustment) takes
that structure and view 3's observations at the same threshold in pixels; the time excludes the
triangulation. Prints a Markdown table beside the report's tripose (points and lines) and
triangulation + solvePnPRansac (SQPNP) results on the same matches.
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run_evaluation import _poselib_pose, rotation_error_deg  # noqa: E402


def front_end_triplets(tool, data, threshold, seed=0):
    """tripose_images_report --dump-inputs on the sequence: one dict per run of three consecutive
    frames (its matches, their structure from views 1-2, the sequence's camera, the report's results)."""
    with tempfile.TemporaryDirectory() as tmp:
        dump = Path(tmp) / "inputs.jsonl"
        proc = subprocess.run([str(tool), "--data", str(data), "--threshold", str(threshold), "--seed", str(seed),
                               "--dump-inputs", str(dump)], capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"{tool} failed ({proc.returncode}): {proc.stderr}")
        return [json.loads(line) for line in dump.read_text().splitlines() if line.strip()]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, help="VGG sequence folder with its images")
    ap.add_argument("--tool", default="build/test/evaluation/tripose_images_report")
    ap.add_argument("--threshold", type=float, default=2.0)
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args()

    triplets = front_end_triplets(a.tool, a.data, a.threshold, a.seed)

    print(f"{a.data}: {len(triplets)} triplets, threshold {a.threshold} px; rotation error (deg), translation "
          "error (% of |t|); PoseLib: points, segments with structure from views 1-2, ms\n")
    print("| views | tripose P+L rot | tripose P+L t | tri + SQPnP rot | tri + SQPnP t | PoseLib PnPL rot | "
          "PoseLib PnPL t | PoseLib points | PoseLib segments | PoseLib ms |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    columns = {"tripose": [], "tri_sqpnp": [], "poselib": []}
    for k, tr in enumerate(triplets):
        R_gt = np.array(tr["R_gt"], float)
        t_gt = np.array(tr["t_gt"], float).reshape(3)
        X = np.array(tr["points3d_12"], float).reshape(-1, 3)
        L = np.array(tr["lines3d_12"], float).reshape(-1, 6)
        n_points = int(np.all(np.isfinite(X), axis=1).sum())
        n_lines = int(np.all(np.isfinite(L), axis=1).sum())
        cell = "not registered | -"
        rot = np.inf
        try:
            R, t, us = _poselib_pose(tr, a.threshold, a.seed * 100003 + k)
            if np.all(np.isfinite(R)) and np.all(np.isfinite(t)):
                rot = rotation_error_deg(np.asarray(R), R_gt)
                cell = f"{rot:.3f} | {100 * np.linalg.norm(np.asarray(t).ravel() - t_gt) / np.linalg.norm(t_gt):.2f}"
        except Exception as e:  # noqa: BLE001 - a failed PoseLib call is this peer failing on this triplet
            us = float("nan")
            print(f"PoseLib failed on {tr['views']}: {e}", file=sys.stderr)
        columns["poselib"].append(rot)
        row = [f"{tr['views'][0]}-{tr['views'][1]}-{tr['views'][2]}"]
        for name in ("tripose", "tri_sqpnp"):
            o = tr[name]
            columns[name].append(o["rot_deg"] if o["ok"] else np.inf)
            row.append(f"{o['rot_deg']:.3f} | {o['t_percent']:.2f}" if o["ok"] else "not registered | -")
        row += [cell, str(n_points), str(n_lines), f"{us / 1000:.1f}"]
        print("| " + " | ".join(row) + " |")

    print("\n| method | registered | median rot (deg) | max rot (deg) |\n| --- | --- | --- | --- |")
    for name, label in (("tripose", "tripose points+lines"), ("tri_sqpnp", "triangulation + PnP (SQPNP)"),
                        ("poselib", "triangulation + PoseLib PnPL")):
        v = np.array(columns[name])
        ok = np.isfinite(v)
        print(f"| {label} | {ok.sum()}/{len(v)} | {np.median(v[ok]) if ok.any() else np.nan:.3f} | "
              f"{v[ok].max() if ok.any() else np.nan:.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
