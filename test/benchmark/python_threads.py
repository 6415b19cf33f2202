"""How the package's estimates scale with Python threads (a benchmark, not a test).

The extension releases the GIL while it estimates, so that threads run estimates in parallel. This
times a batch of independent RANSAC estimates (100P+40L, 30 % outliers, one scene per task) run one
after another, and the same batch spread over 2, ... threads (concurrent.futures), median of
several rounds, and prints the speed-up over one thread; on a machine with C free cores the ideal
is min(threads, C). The results must equal the sequential ones, or the comparison means nothing.

Run with the installed package: python test/benchmark/python_threads.py [--tasks 64] [--rounds 5]
[--threads 1 2 4]
"""
import argparse
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

import tripose

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python" / "tests"))
from scenes import add_outliers, three_view_scene  # noqa: E402


def problems(count):
    """(the estimate's arguments, the true rotation of view 3) per task."""
    out = []
    for seed in range(count):
        rng = np.random.default_rng(seed)
        s = three_view_scene(seed, 100, 40, min_line_plane_angle=np.deg2rad(10.0))
        points = [p + rng.normal(scale=0.5, size=p.shape) for p in s.points]
        lines = [l + rng.normal(scale=0.5, size=l.shape) for l in s.lines]
        points[2], lines[2], _, _ = add_outliers(rng, points[2], lines[2], 0.3)
        out.append(((*points, *lines, s.K, s.R12, s.t12), s.R))
    return out


# The scenes are solved to a small fraction of a degree; a pose further off than this (or none) is a
# failure, and a batch of failures says nothing about the speed of estimates.
MAX_ROTATION_ERROR_DEG = 2.0


def rotation_error_deg(R, R_true):
    return float(np.degrees(np.arccos(np.clip((np.trace(R @ R_true.T) - 1) / 2, -1, 1))))


def estimate(problem):
    return tripose.estimate_pose_line_point_ransac(*problem, seed=1)


def batch_seconds(tasks, threads):
    start = time.perf_counter()
    if threads == 1:
        results = [estimate(p) for p in tasks]
    else:
        with ThreadPoolExecutor(max_workers=threads) as pool:
            results = list(pool.map(estimate, tasks))
    return time.perf_counter() - start, results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", type=int, default=64)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2, 4])
    args = parser.parse_args()

    tasks, truths = zip(*problems(args.tasks))
    _, reference = batch_seconds(tasks, 1)  # warm-up, and the results every variant must give
    failed = [i for i, (r, R_true) in enumerate(zip(reference, truths))
              if r["R"] is None or not rotation_error_deg(r["R"], R_true) < MAX_ROTATION_ERROR_DEG]
    if failed:
        sys.exit(f"{len(failed)} of {len(tasks)} estimates found no pose or a wrong one (tasks {failed[:10]}): "
                 "not timing them")
    times = {n: [] for n in args.threads}
    for _ in range(args.rounds):
        for n in args.threads:  # interleaved, so that load changes hit every thread count alike
            seconds, results = batch_seconds(tasks, n)
            for a, b in zip(reference, results):
                assert np.array_equal(a["R"], b["R"]) and np.array_equal(a["t"], b["t"]), "results differ"
            times[n].append(seconds)
    base = float(np.median(times[args.threads[0]]))
    print(f"{len(tasks)} RANSAC estimates (100P+40L, 30 % outliers), {os.cpu_count()} cores, "
          f"median of {args.rounds} rounds")
    print(f"{'threads':>8s} {'batch':>10s} {'per estimate':>14s} {'speed-up':>9s}")
    for n in args.threads:
        seconds = float(np.median(times[n]))
        print(f"{n:8d} {1e3 * seconds:7.1f} ms {1e3 * seconds / len(tasks):11.2f} ms {base / seconds:9.2f}")


if __name__ == "__main__":
    main()
