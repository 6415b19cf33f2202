# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""The work of the stereo rig's robust estimate per seeded scene, counted in instructions, and its
slowest scene over the median: the ratio of the goal "worst-case time within 3 times the median
over 100 seeded scenes" (doc/studies/speed.md, Stereo rig), without the timing noise of a shared 2-core
machine.

    .venv/bin/python test/evaluation/rig_scene_cost.py --tool build/test/evaluation/tripose_evaluate \\
        [--points 10 --lines 10] [--outliers 0] [--seeds 7000 8000 9000 10000 11000] [--trials 20]

Each scene is a tripose_evaluate stereo trial (1 px noise, threshold 4 px: the scenes of
rig_vs_peers.py). valgrind's callgrind counts the instructions executed inside
estimatePoseLinePointStereoRansac only; a batch of seed S run to trial k and to trial k + 1 differ
by trial k's count. (Trial k's scene is drawn from seed S + k, but its RANSAC seed is the batch's S:
run alone as --seed S + k, the sampler would draw other samples.) A batch of T scenes therefore
costs T (T + 1) / 2 scene runs. The first call of a process costs 0.6 % more than a second call on
the same scene (seed 8000, trial 0), so trial 0 is counted as the others.
The count of a scene is the same on every run of the same binary, whatever else the machine does;
the time ratios of repeated timed passes scatter around it (doc/studies/speed.md).
Needs valgrind (Debian package valgrind). Runs two valgrind processes at a time.
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import statistics
import subprocess
import sys


def instructions(tool, a, seed, trials):
    """Instructions inside the rig's robust estimator over the first `trials` scenes of batch `seed`."""
    cmd = ["valgrind", "--tool=callgrind", "--collect-atstart=no",
           "--toggle-collect=*estimatePoseLinePointStereoRansac*", "--callgrind-out-file=/dev/null",
           tool, "stereo", "--points", str(a.points), "--lines", str(a.lines), "--noise", "1",
           "--outliers", str(a.outliers), "--trials", str(trials), "--seed", str(seed), "--repeats", "1",
           "--threshold", "4", "--methods", "stereo_ransac"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    found = re.search(r"Collected : (\d+)", run.stderr)
    if run.returncode != 0 or not found:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{run.stderr[-2000:]}")
    return int(found.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tool", required=True, help="tripose_evaluate binary")
    ap.add_argument("--points", type=int, default=10)
    ap.add_argument("--lines", type=int, default=10)
    ap.add_argument("--outliers", type=float, default=0.0)
    ap.add_argument("--seeds", type=int, nargs="+", default=[7000, 8000, 9000, 10000, 11000])
    ap.add_argument("--trials", type=int, default=20, help="scenes per seed")
    ap.add_argument("--show", type=int, default=5, help="how many of the costliest scenes to list")
    a = ap.parse_args()
    if shutil.which("valgrind") is None:
        sys.exit("rig_scene_cost.py: valgrind not found (apt-get install valgrind)")
    if not (os.path.isfile(a.tool) and os.access(a.tool, os.X_OK)):
        sys.exit(f"rig_scene_cost.py: argument --tool: {a.tool} is not an executable file")
    if a.trials < 1 or a.show < 1:
        sys.exit("rig_scene_cost.py: arguments --trials and --show must be >= 1")
    if not 0.0 <= a.outliers < 1.0:
        sys.exit("rig_scene_cost.py: argument --outliers must be in [0, 1)")
    seeds = list(dict.fromkeys(a.seeds))

    pool = concurrent.futures.ThreadPoolExecutor(2)
    try:
        runs = {(s, n): pool.submit(instructions, a.tool, a, s, n) for s in seeds for n in range(1, a.trials + 1)}
        cumulative = {key: job.result() for key, job in runs.items()}
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    cost = {}
    for s in seeds:
        for n in range(1, a.trials + 1):
            cost[(s, n - 1)] = cumulative[(s, n)] - (cumulative[(s, n - 1)] if n > 1 else 0)
    if min(cost.values()) <= 0:
        sys.exit("rig_scene_cost.py: a scene counted no instructions inside estimatePoseLinePointStereoRansac "
                 "(a binary without symbols, or one that does not call it)")

    median = statistics.median(cost.values())
    ranked = sorted(cost.items(), key=lambda kv: -kv[1])
    print(f"{a.points}P+{a.lines}L, {a.outliers:.0%} wrong matches, seeds {' '.join(map(str, seeds))}, "
          f"{a.trials} scenes each: {len(cost)} scenes")
    print(f"median {median / 1e6:.3f} M instructions, slowest / median {ranked[0][1] / median:.2f}")
    print("costliest (seed, trial): " + ", ".join(f"({s}, {t}) {c / median:.2f}" for (s, t), c in ranked[:a.show]))


if __name__ == "__main__":
    main()
