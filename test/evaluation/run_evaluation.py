# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Regenerates every figure and table of doc/studies/evaluation.md.

    .venv/bin/python test/evaluation/run_evaluation.py --size smoke   # CI size, a few minutes at most
    .venv/bin/python test/evaluation/run_evaluation.py --size full    # the paper's 500 trials

The C++ executable tripose_evaluate (built with the module; looked up in $TRIPOSE_BUILD_DIR, then
<repo>/build) runs our methods and the OpenCV peers and prints one JSON line per trial, with the
trial's inputs and the structure triangulated from views 1-2. This script runs PoseLib on exactly
those inputs, summarises (quantiles, means, failure counts, median times), writes
<out>/data/summary.json and <out>/tables.md, and plots <out>/*.png. Everything is seeded: the same
command gives the same errors (times vary with the machine).
"""

import argparse
import functools
import json
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
TOOL_NAME = "tripose_evaluate"
VGG_DIR = REPO / "test" / "data" / "vgg"
VGG_SEQUENCES = ["University-Library", "Merton-College-I", "Merton-College-II", "Merton-College-III",
                 "Wadham-College", "Corridor", "Model-House"]
# Regimes beyond the paper's protocol (SyntheticSceneParams): a narrow known pair (view 2 at a
# fraction of the 20 m depth from view 1, view 3 by small motion) and planar structure (one plane
# tilted 30 degrees from view 1), as tripose_evaluate arguments.
REGIMES = {
    "narrow 1 %": ["--motion", "small", "--baseline12-fraction", 0.01],
    "narrow 0.5 %": ["--motion", "small", "--baseline12-fraction", 0.005],
    "planar large": ["--motion", "large", "--planar"],
    "planar small": ["--motion", "small", "--planar"],
}
# The outlier experiment's configurations (1 px noise, wrong matches in the new view(s)): the
# paper's scene with 20 points + 20 lines, a line-heavy one with 3 points + 60 lines (both large
# motion, views 1-2 known), and the stereo rig with 100 points + 40 lines (the rig at time A known,
# wrong matches at time B; SyntheticStereoParams' defaults). Each gives its tripose_evaluate
# arguments, the methods it runs (None: all), its PoseLib peer (PEERS) and its title.
OUTLIER_CONFIGS = {
    "20P+20L": dict(source="synthetic", points=20, lines=20, methods=None, peer="pnpl",
                    title="20 points + 20 lines, large motion, outliers in view 3"),
    "3P+60L": dict(source="synthetic", points=3, lines=60, methods="linear,ransac,ml_from_truth",
                   peer="pnpl-adaptive", title="3 points + 60 lines, large motion, outliers in view 3"),
    "rig 100P+40L": dict(source="stereo", points=100, lines=40, methods="stereo_ransac,stereo_ml_from_truth",
                         peer="generalized", title="stereo rig, 100 points + 40 lines, outliers at time B"),
}
# The paper's Fig. 6 draws, as (lines, points).
VGG_CONFIGS = [(2, 2), (2, 3), (2, 4), (3, 3), (4, 2), (4, 4), (6, 6), (10, 10)]

# Method keys, in plotting order, with the labels of the figures.
METHODS = {
    "linear": "linear (ours, the paper)",
    "linear+refine": "linear + ML refine (ours)",
    "ransac": "RANSAC + refine (ours)",
    "tri+sqpnp": "triangulate + SQPnP",
    "tri+epnp": "triangulate + EPnP",
    "poselib": "triangulate + PoseLib PnPL",
    "poselib-adaptive": "triangulate + PoseLib PnPL, min_iterations 0",
    "ml_from_truth": "ML from ground truth (limit)",
    # The stereo rig (four views; tripose_evaluate stereo): ours on the four views and on views 1-3,
    # the peers on the left image at B with the structure triangulated from the rig at A.
    "stereo_linear": "stereo linear (ours)",
    "stereo_multi_start": "stereo linear, POSE_LINEAR_REFINE (ours)",
    "stereo_linear+refine": "stereo linear + ML refine (ours)",
    "stereo_ransac": "stereo RANSAC + refine (ours)",
    "three_view_linear+refine": "three-view linear + refine, views 1-3 (ours)",
    "three_view_ransac": "three-view RANSAC + refine, views 1-3 (ours)",
    "tri+iterative": "triangulate + solvePnP ITERATIVE",
    "stereo_ml_from_truth": "four-view ML from ground truth (limit)",
    # The rig's PoseLib peer: both time-B cameras, the points triangulated from the rig at A.
    "poselib-generalized": "triangulate + PoseLib generalized absolute pose, min_iterations 0",
}
STYLE = {
    "linear": dict(color="tab:blue", marker="o"),
    "linear+refine": dict(color="tab:cyan", marker="s"),
    "ransac": dict(color="tab:purple", marker="D"),
    "tri+sqpnp": dict(color="tab:orange", marker="^"),
    "tri+epnp": dict(color="tab:red", marker="v"),
    "poselib": dict(color="tab:green", marker="P"),
    "poselib-adaptive": dict(color="tab:olive", marker="*"),
    "ml_from_truth": dict(color="black", marker="x", linestyle="--"),
    "stereo_linear": dict(color="tab:blue", marker="o"),
    "stereo_multi_start": dict(color="tab:gray", marker="h"),
    "stereo_linear+refine": dict(color="tab:cyan", marker="s"),
    "stereo_ransac": dict(color="tab:purple", marker="D"),
    "three_view_linear+refine": dict(color="tab:pink", marker="<"),
    "three_view_ransac": dict(color="tab:brown", marker=">"),
    "tri+iterative": dict(color="tab:red", marker="v"),
    "stereo_ml_from_truth": dict(color="black", marker="x", linestyle="--"),
    "poselib-generalized": dict(color="goldenrod", marker="p"),
}
# Column and legend order of the stereo regime: ours on four views, ours on views 1-3, the peers, the limit.
STEREO_METHODS = ["stereo_ransac", "stereo_multi_start", "stereo_linear+refine", "stereo_linear", "three_view_ransac",
                  "three_view_linear+refine", "poselib", "poselib-adaptive", "tri+sqpnp", "tri+iterative",
                  "stereo_ml_from_truth"]
# Column order of the outlier tables: ours, the peers, the limits.
OUTLIER_METHODS = ["ransac", "stereo_ransac", "linear", "linear+refine", "tri+sqpnp", "tri+epnp", "poselib",
                   "poselib-adaptive", "poselib-generalized", "ml_from_truth", "stereo_ml_from_truth"]
# The stereo regime's decision: the final estimate within this factor of the four-view ML limit in
# median rotation error (issue 14).
STEREO_ML_FACTOR = 1.05

SIZES = {
    # Smoke: every figure and table, few trials; CI runs it in well under 3 minutes on 2 cores.
    "smoke": dict(trials=20, noise=[0.0, 1.0, 3.0], fig4_n=[4, 8], fig5_n=[4, 10, 45], fig5_trials=10,
                  fig5_repeats=3, vgg_trials=10, outliers=[0.0, 0.3], outlier_trials=10, rig_outlier_trials=10,
                  regime_n=[4, 10], regime_noise=[1.0], regime_trials=10,
                  stereo_n=[4, 10], stereo_noise=[1.0], stereo_trials=10),
    # Full: the paper's 500 trials per point (100 runs per VGG configuration).
    "full": dict(trials=500, noise=[0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0], fig4_n=[4, 5, 6, 7, 8],
                 fig5_n=[4, 5, 6, 8, 10, 15, 20, 25, 30, 35, 40, 45], fig5_trials=500, fig5_repeats=5,
                 vgg_trials=100, outliers=[0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6], outlier_trials=500,
                 rig_outlier_trials=500,
                 regime_n=[4, 10], regime_noise=[0.5, 1.0, 2.0], regime_trials=200,
                 stereo_n=[4, 10], stereo_noise=[0.5, 1.0, 1.5, 2.0, 3.0], stereo_trials=500),
}


def find_tool():
    candidates = []
    if os.environ.get("TRIPOSE_BUILD_DIR"):
        build = Path(os.environ["TRIPOSE_BUILD_DIR"])
        candidates += [build / "test" / "evaluation" / TOOL_NAME, build / TOOL_NAME]
    candidates.append(REPO / "build" / "test" / "evaluation" / TOOL_NAME)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return c
    raise SystemExit(f"{TOOL_NAME} not found (looked in {', '.join(map(str, candidates))}); build the project "
                     "or set TRIPOSE_BUILD_DIR")


# ------------------------------------------------------------------------------------------------
# PoseLib peer: triangulated structure from views 1-2 (computed by tripose_evaluate) + view 3.

def _poselib_pose(inputs, threshold_px, seed, min_iterations=None):
    """PoseLib's robust PnPL (LO-RANSAC + bundle) on the triangulated points and lines.

    Observations are normalised by K3 (handles skew, which PoseLib's PINHOLE model lacks), so the
    camera is the identity and the thresholds are divided by the focal length.
    """
    import poselib

    K3 = np.array(inputs["K"][2], dtype=float)
    K3inv = np.linalg.inv(K3)
    focal = 0.5 * (K3[0, 0] + K3[1, 1])

    def normalise(xy):
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        h = np.c_[xy, np.ones(len(xy))] @ K3inv.T
        return h[:, :2] / h[:, 2:3]

    X = np.asarray(inputs["points3d_12"], dtype=float).reshape(-1, 3)
    x3 = normalise(inputs["points3"])
    keep = np.all(np.isfinite(X), axis=1)
    X, x3 = X[keep], x3[keep]
    L = np.asarray(inputs["lines3d_12"], dtype=float).reshape(-1, 6)
    l3 = np.asarray(inputs["lines3"], dtype=float).reshape(-1, 4)
    keep = np.all(np.isfinite(L), axis=1)
    L, l3 = L[keep], l3[keep]
    a, b = normalise(l3[:, :2]), normalise(l3[:, 2:])
    camera = {"model": "PINHOLE", "width": 2, "height": 2, "params": [1.0, 1.0, 0.0, 0.0]}
    ransac = {"max_reproj_error": threshold_px / focal, "max_epipolar_error": threshold_px / focal, "seed": seed}
    if min_iterations is not None:
        ransac["min_iterations"] = min_iterations
    t0 = time.perf_counter()
    pose, _info = poselib.estimate_absolute_pose_pnpl(x3, X, a, b, L[:, :3], L[:, 3:], camera, ransac, {})
    elapsed_us = 1e6 * (time.perf_counter() - t0)
    return np.asarray(pose.R), np.asarray(pose.t), elapsed_us


def rotation_error_deg(A, B):
    return math.degrees(2.0 * math.asin(min(1.0, np.linalg.norm(A - B) / (2.0 * math.sqrt(2.0)))))


# PoseLib's defaults run at least 1000 RANSAC iterations; the adaptive variant lets its stopping rule
# decide alone, which is the fair speed comparison with our adaptive RANSAC.
POSELIB_VARIANTS = (("poselib", None), ("poselib-adaptive", 0))


def add_poselib(trial, variants=POSELIB_VARIANTS):
    """Adds PoseLib's PnPL on the structure triangulated from views 1-2, as the (name, min_iterations)
    @variants."""
    inputs = trial.pop("inputs")
    R_gt = np.array(inputs["R_gt"], dtype=float)
    t_gt = np.array(inputs["t_gt"], dtype=float).reshape(3)
    n_points = len(inputs["points3"])
    n_lines = len(inputs["lines3"])
    # PoseLib's minimal solvers need three features (P3P, P2P1LL, P1P2LL, P3LL).
    if n_points + n_lines < 3:
        return trial
    for name, min_iterations in variants:
        try:
            R, t, us = _poselib_pose(inputs, trial["threshold"], trial["seed"] * 100003 + trial["trial"],
                                     min_iterations)
            ok = bool(np.all(np.isfinite(R)) and np.all(np.isfinite(t)))
            # The triangulation is part of this peer's work, as it is of tri+sqpnp's.
            us += inputs["triangulation_us"]
            trial["methods"][name] = {
                "ok": ok,
                "rot_deg": rotation_error_deg(R, R_gt) if ok else None,
                "t_rel": float(np.linalg.norm(t - t_gt) / np.linalg.norm(t_gt)) if ok else None,
                "time_us": us,
            }
        except Exception:  # noqa: BLE001 - a failed PoseLib call is a failure of that peer on this trial
            trial["methods"][name] = {"ok": False, "rot_deg": None, "t_rel": None, "time_us": None}
    return trial


def add_poselib_rig(trial):
    """Adds PoseLib's generalized absolute pose on the stereo rig (rig_vs_peers.poselib_generalized:
    both time-B cameras, the points triangulated from the rig at A, min_iterations 0)."""
    from rig_vs_peers import poselib_generalized

    trial.pop("inputs")
    inputs = trial.pop("rig_inputs")
    R_gt = np.array(inputs["R_gt"], dtype=float)
    t_gt = np.array(inputs["t_gt"], dtype=float).reshape(3)
    try:
        R, t, us = poselib_generalized(inputs, trial["threshold"], trial["seed"] * 1009 + trial["trial"])
        ok = bool(np.all(np.isfinite(R)) and np.all(np.isfinite(t)))
        trial["methods"]["poselib-generalized"] = {
            "ok": ok,
            "rot_deg": rotation_error_deg(R, R_gt) if ok else None,
            "t_rel": float(np.linalg.norm(t - t_gt) / np.linalg.norm(t_gt)) if ok else None,
            # The triangulation (the rig's points and lines at A) is part of this peer's work, as above.
            "time_us": us + inputs["triangulation_us"],
        }
    except Exception:  # noqa: BLE001 - a failed PoseLib call is a failure of that peer on this trial
        trial["methods"]["poselib-generalized"] = {"ok": False, "rot_deg": None, "t_rel": None, "time_us": None}
    return trial


# The PoseLib peers by name (OUTLIER_CONFIGS); every other experiment gets "pnpl".
PEERS = {
    "pnpl": add_poselib,
    "pnpl-adaptive": functools.partial(add_poselib, variants=(("poselib-adaptive", 0),)),
    "generalized": add_poselib_rig,
}


def peer_for(name, key):
    """The function that adds the PoseLib peer to a trial of experiment @name, group @key."""
    if name == "outliers":
        return PEERS[OUTLIER_CONFIGS[key["config"]]["peer"]]
    return PEERS["pnpl"]


# ------------------------------------------------------------------------------------------------
# Running experiments

def run_tool(tool, args, progress, peer=add_poselib):
    """Runs one tripose_evaluate invocation; returns its trials (with the PoseLib @peer added, if any)."""
    cmd = [str(tool)] + [str(a) for a in args] + (["--dump-inputs"] if peer else [])
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    trials = []
    for line in proc.stdout:
        trial = json.loads(line)
        if peer:
            trial = peer(trial)
        trials.append(trial)
        progress.update(1)
    err = proc.stderr.read()
    if proc.wait() != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {err}")
    return trials


def summarise(trials, key):
    """Statistics of one method over the trials: failures count as +inf in the quantiles."""
    rows = [t["methods"][key] for t in trials if key in t["methods"]]
    if not rows:
        return None
    ok = [r for r in rows if r["ok"]]
    out = {"n": len(rows), "fails": len(rows) - len(ok)}
    for name in ("rot_deg", "t_rel"):
        vals = np.array([r[name] for r in ok] + [math.inf] * (len(rows) - len(ok)), dtype=float)
        finite = vals[np.isfinite(vals)]
        out[name] = {
            "q25": float(np.quantile(vals, 0.25, method="lower")),
            "median": float(np.quantile(vals, 0.5, method="lower")),
            "q75": float(np.quantile(vals, 0.75, method="lower")),
            "mean": float(finite.mean()) if len(finite) else None,
        }
    times = np.array([r["time_us"] for r in rows if r["time_us"] is not None], dtype=float)
    out["time_us"] = {"median": float(np.median(times)), "mean": float(times.mean())} if len(times) else None
    return out


def summarise_group(trials, raw=False):
    methods = {}
    for key in METHODS:
        s = summarise(trials, key)
        if s is not None:
            if raw:  # Fig. 6 draws box plots from the distributions
                rows = [t["methods"][key] for t in trials if key in t["methods"]]
                s["raw_rot_deg"] = [r["rot_deg"] if r["ok"] else None for r in rows]
                s["raw_t_rel"] = [r["t_rel"] if r["ok"] else None for r in rows]
            methods[key] = s
    return methods


def plan(size):
    """Every invocation of the suite: (experiment name, group key dict, tool arguments, trials)."""
    cfg = SIZES[size]
    jobs = []
    for motion in ("large", "small"):
        for n_lines in (3, 4):
            for n_points in (3, 4):
                for noise in cfg["noise"]:
                    key = dict(motion=motion, points=n_points, lines=n_lines, noise=noise)
                    jobs.append(("fig3", key, ["synthetic", "--points", n_points, "--lines", n_lines, "--noise", noise,
                                               "--motion", motion, "--trials", cfg["trials"], "--seed", 1000],
                                 cfg["trials"]))
        for n in cfg["fig4_n"]:
            for noise in cfg["noise"]:
                key = dict(motion=motion, points=n, lines=n, noise=noise)
                jobs.append(("fig4", key, ["synthetic", "--points", n, "--lines", n, "--noise", noise, "--motion", motion,
                                           "--trials", cfg["trials"], "--seed", 2000], cfg["trials"]))
        for n in cfg["fig5_n"]:
            key = dict(motion=motion, points=n, lines=n, noise=1.0)
            jobs.append(("fig5", key, ["synthetic", "--points", n, "--lines", n, "--noise", 1.0, "--motion", motion,
                                       "--trials", cfg["fig5_trials"], "--repeats", cfg["fig5_repeats"], "--seed", 3000],
                         cfg["fig5_trials"]))
    for config, spec in OUTLIER_CONFIGS.items():
        trials = cfg["rig_outlier_trials"] if spec["source"] == "stereo" else cfg["outlier_trials"]
        methods = ["--methods", spec["methods"]] if spec["methods"] else []
        for ratio in cfg["outliers"]:
            key = dict(config=config, points=spec["points"], lines=spec["lines"], noise=1.0, outliers=ratio)
            if spec["source"] == "synthetic":
                key["motion"] = "large"
            jobs.append(("outliers", key, [spec["source"], "--points", spec["points"], "--lines", spec["lines"],
                                           "--noise", 1.0, "--outliers", ratio] + methods +
                         ["--trials", trials, "--seed", 4000], trials))
    for regime, regime_args in REGIMES.items():
        for n in cfg["regime_n"]:
            for noise in cfg["regime_noise"]:
                key = dict(regime=regime, points=n, lines=n, noise=noise)
                jobs.append(("regimes", key, ["synthetic", "--points", n, "--lines", n, "--noise", noise] + regime_args +
                             ["--trials", cfg["regime_trials"], "--seed", 6000], cfg["regime_trials"]))
    # The stereo rig (SyntheticStereoParams' defaults: baseline 0.1-0.5 m, depth 5-30 m, motion 0.3-3 m).
    for n in cfg["stereo_n"]:
        for noise in cfg["stereo_noise"]:
            key = dict(points=n, lines=n, noise=noise)
            jobs.append(("stereo", key, ["stereo", "--points", n, "--lines", n, "--noise", noise,
                                         "--trials", cfg["stereo_trials"], "--seed", 7000], cfg["stereo_trials"]))
    for seq in VGG_SEQUENCES:
        for n_lines, n_points in VGG_CONFIGS:
            key = dict(sequence=seq, points=n_points, lines=n_lines)
            jobs.append(("fig6", key, ["vgg", "--sequence", VGG_DIR / seq, "--points", n_points, "--lines", n_lines,
                                       "--trials", cfg["vgg_trials"], "--seed", 5000], cfg["vgg_trials"]))
    return jobs


def run_all(size, tool, jobs_filter=None):
    from tqdm import tqdm

    jobs = plan(size)
    if jobs_filter:
        jobs = [j for j in jobs if j[0] in jobs_filter]
    results = {}
    with tqdm(total=sum(j[3] for j in jobs), unit="trial", desc=f"evaluation ({size})", file=sys.stderr) as bar:
        for name, key, args, _ in jobs:
            bar.set_postfix_str(f"{name} {' '.join(f'{k}={v}' for k, v in key.items())}", refresh=False)
            trials = run_tool(tool, args, bar, peer_for(name, key))
            results.setdefault(name, []).append({"key": key, "methods": summarise_group(trials, raw=name == "fig6")})
    return results


def machine_description():
    cpu = platform.processor() or "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "system": f"{platform.system()} {platform.release()}",
            "python": platform.python_version()}


# ------------------------------------------------------------------------------------------------
# Plots

def _group(results, name, **match):
    return [g for g in results.get(name, []) if all(g["key"].get(k) == v for k, v in match.items())]


def _curve(groups, xkey, method, stat, quantity):
    xs, ys = [], []
    for g in sorted(groups, key=lambda g: g["key"][xkey]):
        if xkey == "noise" and g["key"]["noise"] == 0:
            continue  # rounding-level errors would squash the noisy range; the tables give them
        s = g["methods"].get(method)
        if s is None or s[quantity][stat] is None or not math.isfinite(s[quantity][stat]):
            continue
        xs.append(g["key"][xkey])
        ys.append(max(s[quantity][stat], 1e-12))  # log axes: an exact 0 is drawn at the floor
    return xs, ys


def plot_noise_curves(results, name, out_dir, configs, stats, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    paths = []
    if not results.get(name):
        return paths
    for motion in ("large", "small"):
        rows = [(s, q) for s in stats for q in ("rot_deg", "t_rel")]
        fig, axes = plt.subplots(len(rows), len(configs), figsize=(3.2 * len(configs), 2.6 * len(rows)),
                                 squeeze=False, sharex=True)
        for c, (n_points, n_lines) in enumerate(configs):
            groups = _group(results, name, motion=motion, points=n_points, lines=n_lines)
            for r, (stat, quantity) in enumerate(rows):
                ax = axes[r][c]
                for method in METHODS:
                    xs, ys = _curve(groups, "noise", method, stat, quantity)
                    if xs:
                        ax.plot(xs, ys, label=METHODS[method], markersize=4, **STYLE[method])
                ax.set_yscale("log")
                ax.grid(True, which="both", alpha=0.3)
                if r == 0:
                    ax.set_title(f"{n_points} points + {n_lines} lines", fontsize=9)
                if c == 0:
                    ax.set_ylabel(f"{stat} {'rotation (deg)' if quantity == 'rot_deg' else 'rel. translation'}",
                                  fontsize=8)
                if r == len(rows) - 1:
                    ax.set_xlabel("noise sigma (px)")
        handles, labels = axes[0][0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
        fig.suptitle(f"{title}, {motion} motion (failures count as infinite error)", fontsize=10)
        fig.tight_layout(rect=(0, 0.06, 1, 0.97))
        path = out_dir / f"{name}_{motion}.png"
        fig.savefig(path, dpi=90)
        plt.close(fig)
        paths.append(path)
    return paths


def plot_regimes(results, out_dir):
    """Median rotation error vs noise per regime (rows) and feature count (columns)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if not results.get("regimes"):
        return []
    counts = sorted({g["key"]["points"] for g in results["regimes"]})
    fig, axes = plt.subplots(len(REGIMES), len(counts), figsize=(3.6 * len(counts), 2.4 * len(REGIMES)),
                             squeeze=False, sharex=True)
    for r, regime in enumerate(REGIMES):
        for c, n in enumerate(counts):
            ax = axes[r][c]
            groups = _group(results, "regimes", regime=regime, points=n)
            for method in METHODS:
                xs, ys = _curve(groups, "noise", method, "median", "rot_deg")
                if xs:
                    ax.plot(xs, ys, label=METHODS[method], markersize=4, **STYLE[method])
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.set_title(f"{regime}, {n} points + {n} lines", fontsize=9)
            if c == 0:
                ax.set_ylabel("median rotation (deg)", fontsize=8)
            if r == len(REGIMES) - 1:
                ax.set_xlabel("noise sigma (px)")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
    fig.suptitle("Narrow known baselines and planar structure (failures count as infinite error)", fontsize=10)
    fig.tight_layout(rect=(0, 0.06, 1, 0.97))
    path = out_dir / "regimes.png"
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return [path]


def plot_stereo(results, out_dir):
    """Stereo rig: median rotation error vs noise (top) and its ratio to the four-view ML limit
    (bottom), one column per feature count."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if not results.get("stereo"):
        return []
    counts = sorted({g["key"]["points"] for g in results["stereo"]})
    fig, axes = plt.subplots(2, len(counts), figsize=(5.2 * len(counts), 6.4), squeeze=False, sharex=True)
    for c, n in enumerate(counts):
        groups = sorted(_group(results, "stereo", points=n), key=lambda g: g["key"]["noise"])
        for method in STEREO_METHODS:
            xs, ys = _curve(groups, "noise", method, "median", "rot_deg")
            if not xs:
                continue
            axes[0][c].plot(xs, ys, label=METHODS[method], markersize=4, **STYLE[method])
            ratios = [(g["key"]["noise"], stereo_ratio(g, method)) for g in groups]
            ratios = [(x, r) for x, r in ratios if r is not None and math.isfinite(r)]
            if ratios:
                axes[1][c].plot([x for x, _ in ratios], [r for _, r in ratios], markersize=4, **STYLE[method])
        axes[0][c].set_yscale("log")
        axes[0][c].set_title(f"{n} points + {n} lines", fontsize=9)
        axes[1][c].set_yscale("log")
        axes[1][c].axhline(STEREO_ML_FACTOR, color="black", linewidth=0.8, linestyle=":")
        axes[1][c].set_xlabel("noise sigma (px)")
        for r in range(2):
            axes[r][c].grid(True, which="both", alpha=0.3)
        if c == 0:
            axes[0][c].set_ylabel("median rotation (deg)", fontsize=8)
            axes[1][c].set_ylabel(f"ratio to the four-view ML limit\n(dotted: {STEREO_ML_FACTOR})", fontsize=8)
    # Every method of any column (solvePnP ITERATIVE needs six points: not in the 4 + 4 column).
    legend = {}
    for ax in axes[0]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    labels = [METHODS[m] for m in STEREO_METHODS if METHODS[m] in legend]
    handles = [legend[label] for label in labels]
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8)
    fig.suptitle("Stereo rig: baseline 0.1-0.5 m, depth 5-30 m, motion 0.3-3 m (failures count as infinite error)",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0.13, 1, 0.97))
    path = out_dir / "stereo.png"
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return [path]


def stereo_ratio(group, method):
    """Median rotation error of @method over the four-view ML limit's, in one stereo group."""
    s, limit = group["methods"].get(method), group["methods"].get("stereo_ml_from_truth")
    if s is None or limit is None or not limit["rot_deg"]["median"]:
        return None
    return s["rot_deg"]["median"] / limit["rot_deg"]["median"]


def plot_time(results, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4), squeeze=False)
    for c, motion in enumerate(("large", "small")):
        ax = axes[0][c]
        groups = _group(results, "fig5", motion=motion)
        for method in METHODS:
            pts = sorted((g["key"]["points"], g["methods"][method]["time_us"]["median"])
                         for g in groups if method in g["methods"] and g["methods"][method]["time_us"])
            if pts:
                ax.plot([2 * p[0] for p in pts], [p[1] for p in pts], label=METHODS[method], markersize=4,
                        **STYLE[method])
        ax.set_yscale("log")
        ax.set_xlabel("features (half points, half lines)")
        ax.set_ylabel("median time per call (us)")
        ax.set_title(f"{motion} motion, noise 1 px, one thread", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    path = out_dir / "fig5_time.png"
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return [path]


def plot_outliers(results, out_dir):
    """Median rotation error, translation error and time vs the outlier ratio, one row per
    configuration of OUTLIER_CONFIGS."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    configs = [c for c in OUTLIER_CONFIGS if _group(results, "outliers", config=c)]
    if not configs:
        return []
    fig, axes = plt.subplots(len(configs), 3, figsize=(13, 3.4 * len(configs)), squeeze=False)
    for r, config in enumerate(configs):
        groups = sorted(_group(results, "outliers", config=config), key=lambda g: g["key"]["outliers"])
        for c, (quantity, label) in enumerate((("rot_deg", "median rotation error (deg)"),
                                               ("t_rel", "median rel. translation error"),
                                               ("time_us", "median time (us)"))):
            ax = axes[r][c]
            for method in OUTLIER_METHODS:
                pts = _outlier_curve(groups, method, quantity)
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], label=METHODS[method], markersize=4,
                            **STYLE[method])
            ax.set_yscale("log")
            ax.set_xlabel("outliers (%)", fontsize=8)
            ax.set_ylabel(label, fontsize=8)
            ax.grid(True, which="both", alpha=0.3)
            if c == 1:
                ax.set_title(OUTLIER_CONFIGS[config]["title"] + ", noise 1 px", fontsize=9)
    legend = {}
    for row in axes:
        for handle, label in zip(*row[0].get_legend_handles_labels()):
            legend.setdefault(label, handle)
    fig.legend(list(legend.values()), list(legend), loc="lower center", ncol=4, fontsize=8)
    fig.tight_layout(rect=(0, 0.04 + 0.025 * (len(legend) // 4), 1, 1))
    path = out_dir / "outliers.png"
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return [path]


def _outlier_curve(groups, method, quantity):
    """(outlier %, median @quantity) of @method over @groups, finite values only (log axes: 0 at a floor)."""
    pts = []
    for g in groups:
        s = g["methods"].get(method)
        if s is None:
            continue
        v = (s["time_us"]["median"] if s["time_us"] else None) if quantity == "time_us" else s[quantity]["median"]
        if v is not None and math.isfinite(v):
            pts.append((100 * g["key"]["outliers"], max(v, 1e-12)))
    return pts


def plot_vgg(results, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    paths = []
    for seq in VGG_SEQUENCES:
        groups = _group(results, "fig6", sequence=seq)
        if not groups:
            continue
        fig, axes = plt.subplots(2, 1, figsize=(16, 7), sharex=True)
        methods = [m for m in METHODS if any(m in g["methods"] for g in groups)]
        width = 0.8 / len(methods)
        for r, (quantity, label) in enumerate((("raw_rot_deg", "rotation error (deg)"),
                                               ("raw_t_rel", "rel. translation error"))):
            ax = axes[r]
            for mi, method in enumerate(methods):
                data, pos = [], []
                for ci, (n_lines, n_points) in enumerate(VGG_CONFIGS):
                    g = next((g for g in groups if g["key"]["lines"] == n_lines and g["key"]["points"] == n_points), None)
                    if g is None or method not in g["methods"]:
                        continue
                    vals = [v for v in g["methods"][method][quantity] if v is not None]
                    if vals:
                        data.append(np.maximum(vals, 1e-9))
                        pos.append(ci + (mi - (len(methods) - 1) / 2) * width)
                if data:
                    bp = ax.boxplot(data, positions=pos, widths=width * 0.9, patch_artist=True, showfliers=True,
                                    flierprops=dict(markersize=2), manage_ticks=False)
                    for box in bp["boxes"]:
                        box.set_facecolor(STYLE[method]["color"])
                        box.set_alpha(0.6)
                    ax.plot([], [], color=STYLE[method]["color"], linewidth=6, alpha=0.6, label=METHODS[method])
            ax.set_yscale("log")
            ax.set_ylabel(label)
            ax.grid(True, axis="y", which="both", alpha=0.3)
        axes[1].set_xticks(range(len(VGG_CONFIGS)))
        axes[1].set_xticklabels([f"{l}L+{p}P" for l, p in VGG_CONFIGS])
        axes[0].legend(loc="upper right", ncol=4, fontsize=8)
        axes[0].set_title(f"VGG {seq}, views 0-1-2, random draws (failures are left out of the boxes; see tables)",
                          fontsize=10)
        fig.tight_layout()
        path = out_dir / f"fig6_{seq}.png"
        fig.savefig(path, dpi=80)
        plt.close(fig)
        paths.append(path)
    return paths


# ------------------------------------------------------------------------------------------------
# Tables

def _fmt(x, digits=3):
    if x is None:
        return "-"
    if not math.isfinite(x):
        return "inf"
    return f"{x:.{digits}g}"


def tables_markdown(results, size, machine, runs):
    commands = "; ".join(f"`{run['command']}` ({', '.join(exps)}, {run['elapsed_s']:.0f} s)"
                         for run, exps in _runs_by_command(runs))
    out = [f"<!-- Generated by test/evaluation/run_evaluation.py --size {size}; do not edit. -->", "",
           f"Size: **{size}**. Machine: {machine['cpu']}, {machine['cores']} cores, {machine['system']}. "
           f"Commands: {commands}.", ""]

    def method_table(title, groups, keycols, stat, quantities=("rot_deg", "t_rel"), with_time=False, order=METHODS):
        out.append(f"### {title}")
        out.append("")
        methods = [m for m in order if any(m in g["methods"] for g in groups)]
        header = keycols + [f"{METHODS[m]}" for m in methods]
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + "---|" * len(header))
        for g in groups:
            cells = [str(g["key"][k]) for k in keycols]
            for m in methods:
                s = g["methods"].get(m)
                if s is None:
                    cells.append("n/a")
                    continue
                parts = [_fmt(s[q][stat]) for q in quantities]
                if with_time and s["time_us"]:
                    parts.append(f"{_fmt(s['time_us']['median'])} us")
                text = " / ".join(parts)
                if s["fails"]:
                    text += f" ({s['fails']}/{s['n']} fail)"
                cells.append(text)
            out.append("| " + " | ".join(cells) + " |")
        out.append("")

    for motion in ("large", "small"):
        groups = [g for g in results.get("fig3", []) if g["key"]["motion"] == motion]
        if groups:
            method_table(f"Fig. 3, {motion} motion: lower quartile of rotation error (deg) / relative translation error",
                         groups, ["points", "lines", "noise"], "q25")
    for motion in ("large", "small"):
        groups = [g for g in results.get("fig4", []) if g["key"]["motion"] == motion]
        if groups:
            method_table(f"Fig. 4, {motion} motion: median rotation error (deg) / relative translation error",
                         groups, ["points", "lines", "noise"], "median")
            method_table(f"Fig. 4, {motion} motion: mean (over successes) rotation error (deg) / relative translation "
                         "error", groups, ["points", "lines", "noise"], "mean")

    # Speed: medians and ratios against the linear solver, in the same process (PoseLib: same inputs,
    # timed around the Python call, plus the C++ triangulation time).
    for motion in ("large", "small"):
        groups = [g for g in results.get("fig5", []) if g["key"]["motion"] == motion]
        if not groups:
            continue
        methods = [m for m in METHODS if any(m in g["methods"] for g in groups)]
        out.append(f"### Fig. 5, {motion} motion: median time per call (us), ratio = peer / linear "
                   "(> 1: ours is faster), and median rotation error (deg)")
        out.append("")
        header = ["features"] + [METHODS[m] for m in methods]
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + "---|" * len(header))
        for g in sorted(groups, key=lambda g: g["key"]["points"]):
            base = g["methods"]["linear"]["time_us"]["median"]
            cells = [f"{g['key']['points']}P+{g['key']['lines']}L"]
            for m in methods:
                s = g["methods"].get(m)
                if s is None or not s["time_us"]:
                    cells.append("n/a")
                    continue
                tm = s["time_us"]["median"]
                cells.append(f"{_fmt(tm)} (x{_fmt(tm / base, 2)}), {_fmt(s['rot_deg']['median'])} deg")
            out.append("| " + " | ".join(cells) + " |")
        out.append("")

    for config, spec in OUTLIER_CONFIGS.items():
        groups = sorted(_group(results, "outliers", config=config), key=lambda g: g["key"]["outliers"])
        if groups:
            trials = max(s["n"] for s in groups[0]["methods"].values())
            method_table(f"Outliers ({spec['title']}, 1 px, {trials} scenes per ratio): median rotation error (deg) / "
                         "relative translation error / median time", groups, ["outliers"], "median", with_time=True,
                         order=OUTLIER_METHODS)

    for regime in REGIMES:
        groups = [g for g in results.get("regimes", []) if g["key"]["regime"] == regime]
        if groups:
            method_table(f"{regime}: median rotation error (deg) / relative translation error", groups,
                         ["points", "lines", "noise"], "median")

    groups = sorted(results.get("stereo", []), key=lambda g: (g["key"]["points"], g["key"]["noise"]))
    if groups:
        method_table("Stereo rig: median rotation error (deg) / relative translation error / median time", groups,
                     ["points", "lines", "noise"], "median", with_time=True, order=STEREO_METHODS)
        methods = [m for m in STEREO_METHODS if m != "stereo_ml_from_truth" and any(m in g["methods"] for g in groups)]
        out.append(f"### Stereo rig: median rotation error over the four-view ML limit's (criterion: <= "
                   f"{STEREO_ML_FACTOR})")
        out.append("")
        header = ["points", "lines", "noise", "trials", "ML limit (deg)"] + [METHODS[m] for m in methods]
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + "---|" * len(header))
        for g in groups:
            limit = g["methods"]["stereo_ml_from_truth"]
            cells = [str(g["key"]["points"]), str(g["key"]["lines"]), str(g["key"]["noise"]), str(limit["n"]),
                     _fmt(limit["rot_deg"]["median"])]
            cells += [_fmt(stereo_ratio(g, m)) if m in g["methods"] else "n/a" for m in methods]
            out.append("| " + " | ".join(cells) + " |")
        out.append("")

    groups = results.get("fig6", [])
    if groups:
        method_table("Fig. 6, VGG: median rotation error (deg) / relative translation error", groups,
                     ["sequence", "lines", "points"], "median")
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------------------------------------
# Partial runs (--only): the experiments not rerun are kept from the summary already in <out>.

def runs_of(summary):
    """Experiment -> the run that produced it ({"command", "elapsed_s"}); a summary written before runs
    were recorded gets its one command for every experiment."""
    if "runs" in summary:
        return summary["runs"]
    return {name: {"command": summary["command"], "elapsed_s": summary["elapsed_s"]} for name in summary["results"]}


def merge_previous(path, size, results, runs):
    """Adds to @results (and @runs) the experiments of the summary at @path that this run did not
    redo, if that summary has the same size; returns both."""
    if not path.is_file():
        return results, runs
    previous = json.loads(path.read_text())
    if previous["size"] != size:
        return results, runs
    previous_runs = runs_of(previous)
    merged = {name: groups for name, groups in previous["results"].items() if name not in results}
    merged.update(results)
    merged_runs = {name: previous_runs[name] for name in merged if name not in runs}
    merged_runs.update(runs)
    return merged, merged_runs


def _runs_by_command(runs):
    """[(run, [experiments])] in the order of first appearance, one entry per distinct command."""
    out = []
    for name, run in runs.items():
        for seen, names in out:
            if seen == run:
                names.append(name)
                break
        else:
            out.append((run, [name]))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", choices=sorted(SIZES), default="smoke")
    parser.add_argument("--out", type=Path, default=REPO / "doc" / "studies" / "evaluation",
                        help="output folder for PNGs, tables.md and data/summary.json (default doc/studies/evaluation)")
    parser.add_argument("--only", nargs="*", choices=["fig3", "fig4", "fig5", "fig6", "outliers", "regimes", "stereo"],
                        help="run only these experiments (the others are kept from <out>/data/summary.json when "
                             "it has the same size)")
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw the figures and tables from <out>/data/summary.json without running anything")
    args = parser.parse_args(argv)

    out = args.out
    if args.plot_only:
        summary = json.loads((out / "data" / "summary.json").read_text())
        args.size = summary["size"]
        results, machine, elapsed = summary["results"], summary["machine"], summary["elapsed_s"]
        runs = runs_of(summary)
    else:
        tool = find_tool()
        started = time.time()
        results = run_all(args.size, tool, args.only)
        elapsed = time.time() - started
        (out / "data").mkdir(parents=True, exist_ok=True)
        machine = machine_description()
        command = "test/evaluation/run_evaluation.py --size " + args.size + (" --only " + " ".join(args.only)
                                                                              if args.only else "")
        runs = {name: {"command": command, "elapsed_s": elapsed} for name in results}
        if args.only:
            results, runs = merge_previous(out / "data" / "summary.json", args.size, results, runs)
        summary = {"size": args.size, "config": SIZES[args.size], "machine": machine, "elapsed_s": elapsed,
                   "command": command, "runs": runs, "results": results}
        (out / "data" / "summary.json").write_text(json.dumps(summary, indent=1))
    (out / "tables.md").write_text(tables_markdown(results, args.size, machine, runs))

    pngs = []
    pngs += plot_noise_curves(results, "fig3", out, [(3, 3), (4, 3), (3, 4), (4, 4)], ["q25"],
                              "Fig. 3: lower quartile of the errors vs noise")
    pngs += plot_noise_curves(results, "fig4", out, [(n, n) for n in SIZES[args.size]["fig4_n"]], ["mean", "median"],
                              "Fig. 4: mean (over successes) and median errors vs noise, n points + n lines")
    if results.get("fig5"):
        pngs += plot_time(results, out)
    pngs += plot_outliers(results, out)
    pngs += plot_regimes(results, out)
    pngs += plot_stereo(results, out)
    pngs += plot_vgg(results, out)
    print(f"{len(pngs)} figures, tables.md and data/summary.json in {out} ({elapsed:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
