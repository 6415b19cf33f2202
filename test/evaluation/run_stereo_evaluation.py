# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Regenerates the tables and the figure of doc/studies/stereo.md: every frame pair of OpenCV's stereo
calibration sample (test/data/stereo), our stereo-rig estimators beside the peers.

    .venv/bin/python test/evaluation/run_stereo_evaluation.py [--out doc/studies/stereo]

The sample tripose_stereo_chessboard (looked up in $TRIPOSE_BUILD_DIR, then <repo>/build) calibrates
the rig, builds each pair's four-view problem from image features, runs our estimators and writes
everything to a FileStorage file: once with corners and lines, once with the lines alone. This script
adds the peers on exactly those features, all on the left image at B against structure triangulated
from the rig at A: cv::solvePnP (SQPnP, and ITERATIVE) on the corners, and PoseLib's PnPL (LO-RANSAC
on points and lines, with its bundle adjustment). It writes <out>/tables.md (every pair, then the
medians), <out>/errors.png and <out>/data/summary.json. Deterministic: the same command gives the
same numbers.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import cv2
import numpy as np

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "test" / "data" / "stereo"
sys.path.insert(0, str(Path(__file__).resolve().parent))
from run_evaluation import _poselib_pose, rotation_error_deg  # noqa: E402  (the same PoseLib call and metric)

THRESHOLD_PX = 2.0
# A rotation error beyond this is a wrong solution, not an inaccurate one: every method's typical
# error on these pairs is a few tenths of a degree.
GROSS_DEG = 5.0

# Method keys, in table and plot order, with their labels.
METHODS = {
    "stereo_ransac": "stereo RANSAC + refine (ours)",
    "stereo_linear": "stereo linear (ours)",
    "three_view_ransac": "three-view RANSAC + refine, views 1-3 (ours)",
    "three_view_linear": "three-view linear, views 1-3 (ours)",
    "stereo_ransac_lines": "stereo RANSAC + refine, lines only (ours)",
    "stereo_linear_lines": "stereo linear, lines only (ours)",
    "three_view_ransac_lines": "three-view RANSAC + refine, lines only (ours)",
    "tri+sqpnp": "triangulate + SQPnP",
    "tri+iterative": "triangulate + solvePnP ITERATIVE",
    "tri+poselib": "triangulate + PoseLib PnPL",
}


def find_tool():
    name = "tripose_stereo_chessboard"
    candidates = []
    if os.environ.get("TRIPOSE_BUILD_DIR"):
        candidates.append(Path(os.environ["TRIPOSE_BUILD_DIR"]) / "samples" / name)
    candidates.append(REPO / "build" / "samples" / name)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return c
    raise SystemExit(f"{name} not found (looked in {', '.join(map(str, candidates))}); build it "
                     f"(cmake --build build --target {name}) or set TRIPOSE_BUILD_DIR")


def run_sample(tool, features, path):
    subprocess.run([str(tool), "--data", str(DATA), "--pairs", "all", "--features", features,
                    "--threshold", str(THRESHOLD_PX), "--output", str(path)], check=True, capture_output=True, text=True)
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    rig = {k: fs.getNode(k).mat() for k in ("K1", "K2", "dist1", "dist2", "R12", "t12")}
    rig["rms"] = fs.getNode("calibration_rms").real()
    node = fs.getNode("pairs")
    pairs = []
    for i in range(node.size()):
        p = node.at(i)
        pair = {"frame_a": int(p.getNode("frame_a").real()), "frame_b": int(p.getNode("frame_b").real()),
                "left_a": p.getNode("left_a").string(), "left_b": p.getNode("left_b").string(),
                "R_gt": p.getNode("R_gt").mat(), "t_gt": p.getNode("t_gt").mat().reshape(3)}
        for kind in ("points", "lines"):
            for v in range(1, 5):
                m = p.getNode(f"{kind}{v}").mat()
                pair[f"{kind}{v}"] = np.zeros((0, 2 if kind == "points" else 4)) if m is None else m
        for key in ("stereo_ransac", "stereo_linear", "three_view_ransac", "three_view_linear"):
            e = p.getNode(key)
            pair[key] = ({"ok": True, "rot_deg": e.getNode("rot_deg").real(), "t_rel": e.getNode("t_rel").real()}
                         if int(e.getNode("ok").real()) else {"ok": False})
        pairs.append(pair)
    fs.release()
    return rig, pairs


def undistort(xy, K, dist, pixels):
    """Undistorted image coordinates: pixels (P = K) or normalised (P = identity)."""
    xy = np.asarray(xy, dtype=np.float64).reshape(-1, 1, 2)
    return cv2.undistortPoints(xy, K, dist, P=K if pixels else None).reshape(-1, 2)


def triangulate_points(rig, x1, x2):
    P1 = np.hstack([np.eye(3), np.zeros((3, 1))])
    P2 = np.hstack([rig["R12"], rig["t12"].reshape(3, 1)])
    X = cv2.triangulatePoints(P1, P2, undistort(x1, rig["K1"], rig["dist1"], False).T,
                              undistort(x2, rig["K2"], rig["dist2"], False).T)
    return (X[:3] / X[3]).T


def triangulate_lines(rig, l1, l2):
    """Mx6 3D segments: view 1's end-point rays cut by view 2's back-projected plane."""
    a1 = np.c_[undistort(l1[:, :2], rig["K1"], rig["dist1"], False), np.ones(len(l1))]
    b1 = np.c_[undistort(l1[:, 2:], rig["K1"], rig["dist1"], False), np.ones(len(l1))]
    a2 = np.c_[undistort(l2[:, :2], rig["K2"], rig["dist2"], False), np.ones(len(l2))]
    b2 = np.c_[undistort(l2[:, 2:], rig["K2"], rig["dist2"], False), np.ones(len(l2))]
    n2 = np.cross(a2, b2)                       # plane of view 2's line, in view 2's frame
    normal = n2 @ rig["R12"]                     # the same plane in view 1's frame: normal . X + offset = 0
    offset = n2 @ rig["t12"].reshape(3)
    ends = [(-offset / np.sum(normal * ray, axis=1))[:, None] * ray for ray in (a1, b1)]
    return np.hstack(ends)


def pose_errors(R, t, pair):
    ok = R is not None and np.all(np.isfinite(R)) and np.all(np.isfinite(t))
    if not ok:
        return {"ok": False}
    t = np.asarray(t, dtype=float).reshape(3)
    return {"ok": True, "rot_deg": rotation_error_deg(np.asarray(R, dtype=float), pair["R_gt"]),
            "t_rel": float(np.linalg.norm(t - pair["t_gt"]) / np.linalg.norm(pair["t_gt"]))}


def peers(rig, pair, seed):
    """The peers on the left image at B, from the structure the rig triangulates at A."""
    out = {}
    X = triangulate_points(rig, pair["points1"], pair["points2"])
    x3 = np.asarray(pair["points3"], dtype=np.float64)
    for name, flags in (("tri+sqpnp", cv2.SOLVEPNP_SQPNP), ("tri+iterative", cv2.SOLVEPNP_ITERATIVE)):
        ok, rvec, tvec = cv2.solvePnP(X, x3, rig["K1"], rig["dist1"], flags=flags)
        out[name] = pose_errors(cv2.Rodrigues(rvec)[0], tvec, pair) if ok else {"ok": False}
    seen3 = np.all(np.isfinite(pair["lines3"]), axis=1)
    L = triangulate_lines(rig, pair["lines1"][seen3], pair["lines2"][seen3])
    l3 = pair["lines3"][seen3]
    inputs = {"K": [None, None, rig["K1"]], "points3d_12": X,
              "points3": undistort(x3, rig["K1"], rig["dist1"], True),
              "lines3d_12": L,
              "lines3": np.hstack([undistort(l3[:, :2], rig["K1"], rig["dist1"], True),
                                   undistort(l3[:, 2:], rig["K1"], rig["dist1"], True)])}
    try:
        R, t, _ = _poselib_pose(inputs, THRESHOLD_PX, seed)
        out["tri+poselib"] = pose_errors(R, t, pair)
    except Exception:  # noqa: BLE001 - a failed PoseLib call is that peer's failure on this pair
        out["tri+poselib"] = {"ok": False}
    return out


def evaluate(tool):
    with tempfile.TemporaryDirectory() as tmp:
        rig, pairs = run_sample(tool, "all", Path(tmp) / "all.yml")
        _, lines_only = run_sample(tool, "lines", Path(tmp) / "lines.yml")
    rows = []
    for i, (pair, lp) in enumerate(zip(pairs, lines_only)):
        methods = {k: pair[k] for k in ("stereo_ransac", "stereo_linear", "three_view_ransac", "three_view_linear")}
        methods["stereo_ransac_lines"] = lp["stereo_ransac"]
        methods["stereo_linear_lines"] = lp["stereo_linear"]
        methods["three_view_ransac_lines"] = lp["three_view_ransac"]
        methods.update(peers(rig, pair, seed=i))
        rows.append({"frames": [pair["frame_a"], pair["frame_b"]], "images": [pair["left_a"], pair["left_b"]],
                     "points": int(len(pair["points1"])),
                     "lines_b": [int(np.all(np.isfinite(pair[f"lines{v}"]), axis=1).sum()) for v in (3, 4)],
                     "motion_deg": rotation_error_deg(pair["R_gt"], np.eye(3)),
                     "motion_t": float(np.linalg.norm(pair["t_gt"])),
                     "methods": methods})
    calibration = {"rms_px": rig["rms"], "baseline": float(np.linalg.norm(rig["t12"])),
                   "K1": rig["K1"].tolist(), "K2": rig["K2"].tolist(),
                   "dist1": rig["dist1"].ravel().tolist(), "dist2": rig["dist2"].ravel().tolist()}
    return calibration, rows


def medians(rows):
    out = {}
    for m in METHODS:
        ok = [r["methods"][m] for r in rows if r["methods"][m]["ok"]]
        out[m] = {"pairs": len(rows), "failed": len(rows) - len(ok),
                  "rot_deg": float(np.median([e["rot_deg"] for e in ok])) if ok else None,
                  "rot_deg_max": float(np.max([e["rot_deg"] for e in ok])) if ok else None,
                  "t_rel": float(np.median([e["t_rel"] for e in ok])) if ok else None,
                  "t_rel_max": float(np.max([e["t_rel"] for e in ok])) if ok else None,
                  "gross": sum(e["rot_deg"] > GROSS_DEG for e in ok)}
    return out


def _cell(e):
    return f"{e['rot_deg']:.3f} / {100 * e['t_rel']:.2f}" if e["ok"] else "failed"


def tables_markdown(calibration, rows, summary):
    keys = list(METHODS)
    lines = ["# Stereo chessboard pairs: every frame pair",
             "",
             "Generated by `test/evaluation/run_stereo_evaluation.py`; read with [../stereo.md](../stereo.md).",
             f"Rig calibration RMS {calibration['rms_px']:.3f} px, baseline {calibration['baseline']:.3f} squares.",
             "",
             "Each cell: rotation error (degrees) / translation error (% of the true translation).",
             "",
             "## Medians over the pairs",
             "",
             f"| method | rotation, median (max) deg | translation, median (max) % | rotation error > {GROSS_DEG:g} deg | failed |",
             "| --- | --- | --- | --- | --- |"]
    for k in keys:
        s = summary[k]
        if s["rot_deg"] is None:
            lines.append(f"| {METHODS[k]} | - | - | - | {s['failed']} / {s['pairs']} |")
        else:
            lines.append(f"| {METHODS[k]} | {s['rot_deg']:.3f} ({s['rot_deg_max']:.2f}) | "
                         f"{100 * s['t_rel']:.2f} ({100 * s['t_rel_max']:.1f}) | {s['gross']} | {s['failed']} / {s['pairs']} |")
    lines += ["",
              "## Per pair",
              "",
              "Frames are numbered from 0 in the list's order (frame 9 is left11.jpg: there is no pair 10). "
              "Motion: the true rotation angle (deg) / translation length (squares). Lines: board lines seen "
              "in the left / right image at B (and in both images at A).",
              "",
              "| A, B | images | motion | lines | " + " | ".join(METHODS[k] for k in keys) + " |",
              "| --- | --- | --- | --- | " + " | ".join("---" for _ in keys) + " |"]
    for r in rows:
        lines.append(f"| {r['frames'][0]}, {r['frames'][1]} | {r['images'][0]}, {r['images'][1]} | "
                     f"{r['motion_deg']:.1f} / {r['motion_t']:.2f} | {r['lines_b'][0]} / {r['lines_b'][1]} | "
                     + " | ".join(_cell(r["methods"][k]) for k in keys) + " |")
    return "\n".join(lines) + "\n"


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    keys = list(METHODS)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    for ax, quantity, scale, label in ((axes[0], "rot_deg", 1.0, "rotation error (deg)"),
                                       (axes[1], "t_rel", 100.0, "translation error (% of |t|)")):
        data = [[scale * r["methods"][k][quantity] for r in rows if r["methods"][k]["ok"]] for k in keys]
        ax.boxplot(data, orientation="horizontal", whis=(0, 100), widths=0.6)
        for i, d in enumerate(data):
            ax.plot(d, np.full(len(d), i + 1) + np.linspace(-0.2, 0.2, len(d)), ".", ms=3, alpha=0.5)
        ax.set_yticks(range(1, len(keys) + 1))
        ax.set_yticklabels([METHODS[k] for k in keys] if ax is axes[0] else [])
        ax.set_xscale("log")
        ax.set_xlabel(label)
        ax.invert_yaxis()
        ax.grid(True, which="both", axis="x", alpha=0.3)
    fig.suptitle(f"OpenCV stereo chessboard pairs: {len(rows)} frame pairs (box: quartiles, whiskers: min-max)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=REPO / "doc" / "studies" / "stereo",
                        help="output folder for tables.md, errors.png and data/summary.json (default doc/studies/stereo)")
    args = parser.parse_args(argv)
    calibration, rows = evaluate(find_tool())
    summary = medians(rows)
    (args.out / "data").mkdir(parents=True, exist_ok=True)
    (args.out / "data" / "summary.json").write_text(json.dumps(
        {"command": "test/evaluation/run_stereo_evaluation.py", "threshold_px": THRESHOLD_PX,
         "calibration": calibration, "medians": summary, "pairs": rows}, indent=1))
    (args.out / "tables.md").write_text(tables_markdown(calibration, rows, summary))
    plot(rows, args.out / "errors.png")
    for k in METHODS:
        s = summary[k]
        print(f"{METHODS[k]:48s} " + (f"rot {s['rot_deg']:.3f} deg  t {100 * s['t_rel']:.2f} %" if s["rot_deg"] is not None
                                      else "no result") + f"  failed {s['failed']}/{s['pairs']}")
    print(f"tables.md, errors.png and data/summary.json in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
