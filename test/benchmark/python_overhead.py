"""What the Python package adds to the time of an estimate (a benchmark, not a test).

In one process, interleaved (one run of each variant in turn, repeated), median of many runs:
  * estimate_pose_line_point on a 4P+4L scene through the public wrapper (tripose) and through
    the extension function directly (tripose._tripose_ext): the wrapper's cost;
  * the same problem with float32 and with Fortran-order arrays: the conversion's cost;
  * the linear estimate followed by refine_pose_line_point of the best candidate (what the C++
    benchmark tripose_benchmark times as "lin+refine"), and refine=True, which refines every
    candidate and further starts (POSE_LINEAR_REFINE; much slower on few features);
  * estimate_pose_line_point_ransac on 100P+40L with 30 % outliers and 0.5 px noise.
Run with the installed package: python test/benchmark/python_overhead.py [--runs N]
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

import tripose
from tripose import _tripose_ext as ext

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python" / "tests"))
from scenes import add_outliers, three_view_scene  # noqa: E402


def interleaved(variants, runs):
    """Median time (s) of each variant, its runs interleaved with the others'."""
    times = {name: [] for name in variants}
    for _ in range(runs):
        for name, call in variants.items():
            start = time.perf_counter()
            call()
            times[name].append(time.perf_counter() - start)
    return {name: float(np.median(t)) for name, t in times.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2000)
    args = parser.parse_args()

    s = three_view_scene(1, 4, 4)
    rng = np.random.default_rng(0)
    points = [p + rng.normal(scale=0.5, size=p.shape) for p in s.points]
    lines = [l + rng.normal(scale=0.5, size=l.shape) for l in s.lines]
    small = (*points, *lines, s.K, s.R12, s.t12)
    small32 = tuple(a.astype(np.float32) for a in small[:6]) + small[6:]
    small_f = tuple(np.asfortranarray(a) for a in small)

    b = three_view_scene(2, 100, 40, min_line_plane_angle=np.deg2rad(10.0))
    big_points = [p + rng.normal(scale=0.5, size=p.shape) for p in b.points]
    big_lines = [l + rng.normal(scale=0.5, size=l.shape) for l in b.lines]
    big_points[2], big_lines[2], _, _ = add_outliers(rng, big_points[2], big_lines[2], 0.3)
    big = (*big_points, *big_lines, b.K, b.R12, b.t12)

    variants = {
        "4P+4L linear, extension directly": lambda: ext.estimate_pose_line_point(*small, None, False),
        "4P+4L linear, tripose": lambda: tripose.estimate_pose_line_point(*small),
        "4P+4L linear, tripose, float32": lambda: tripose.estimate_pose_line_point(*small32),
        "4P+4L linear, tripose, Fortran order": lambda: tripose.estimate_pose_line_point(*small_f),
    }
    def linear_then_refine():
        R, t = tripose.estimate_pose_line_point(*small)[0]
        return tripose.refine_pose_line_point(*small, R, t)

    variants["4P+4L linear, then refine the best, tripose"] = linear_then_refine
    refine_variants = {
        "4P+4L linear + refine, tripose": lambda: tripose.estimate_pose_line_point(*small, refine=True),
    }
    ransac_variants = {
        "100P+40L RANSAC + refine, extension": lambda: ext.estimate_pose_line_point_ransac(
            *big, None, 2.0, 0.999, 10000, True, 0),
        "100P+40L RANSAC + refine, tripose": lambda: tripose.estimate_pose_line_point_ransac(*big, seed=0),
        "100P+40L RANSAC, no refine, tripose": lambda: tripose.estimate_pose_line_point_ransac(*big, refine=False),
    }
    # Same results both ways, or the comparison means nothing.
    a, c = ext.estimate_pose_line_point(*small, None, False), tripose.estimate_pose_line_point(*small)
    assert all(np.array_equal(x[0], y[0]) for x, y in zip(a, c))

    # Groups of similar duration, so that a long run does not precede (and evict the caches of) a short one.
    for call in list(variants.values()) + list(refine_variants.values()) + list(ransac_variants.values()):
        call()  # warm-up
    results = interleaved(variants, args.runs)
    results.update(interleaved(refine_variants, max(50, args.runs // 20)))
    results.update(interleaved(ransac_variants, max(50, args.runs // 20)))

    reference = results["4P+4L linear, extension directly"]
    ransac_reference = results["100P+40L RANSAC + refine, extension"]
    print(f"{'variant':42s} {'median':>12s} {'ratio':>8s}")
    for name, seconds in results.items():
        base = ransac_reference if name.startswith("100P") else reference
        print(f"{name:42s} {1e6 * seconds:9.1f} us {seconds / base:8.3f}")
    print(f"wrapper overhead on 4P+4L: {1e6 * (results['4P+4L linear, tripose'] - reference):.1f} us per call")


if __name__ == "__main__":
    main()
