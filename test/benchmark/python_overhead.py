"""What the Python package adds to the time of an estimate (a benchmark, not a test).

Median of many runs, in one session:
  * the C++ API (cv::tripose, through build/test/benchmark/tripose_problem_benchmark) on the same
    arrays, written to a problem file: its runs alternate, in rounds, with the package's, and the
    two sides must return the same pose;
  * estimate_pose_line_point on a 4P+4L scene through the public wrapper (tripose) and through
    the extension function directly (tripose._tripose_ext): the wrapper's cost;
  * the same problem with float32 and with Fortran-order arrays: the conversion's cost;
  * the linear estimate followed by refine_pose_line_point of the best candidate (what the C++
    benchmark tripose_benchmark times as "lin+refine"), and refine=True, which refines every
    candidate and further starts (POSE_LINEAR_REFINE; much slower on few features);
  * estimate_pose_line_point_ransac on 100P+40L with 30 % outliers and 0.5 px noise.
Run with the installed package (and cv2 from opencv-contrib-python-headless, to write the problem
files): python test/benchmark/python_overhead.py [--runs N] [--rounds K] [--build build]
"""
import argparse
import subprocess
import sys
import tempfile
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


REPO = Path(__file__).resolve().parents[2]


def write_problem(path, points, lines, K, R12, t12):
    """A three-view problem file as tripose_estimate reads it."""
    import cv2  # only to write the file; the package never imports it

    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    fs.write("K", np.asarray(K, np.float64))
    fs.write("R12", np.asarray(R12, np.float64))
    fs.write("t12", np.asarray(t12, np.float64).reshape(3, 1))
    for v in range(3):
        fs.write(f"points{v + 1}", np.ascontiguousarray(points[v], np.float64))
        fs.write(f"lines{v + 1}", np.ascontiguousarray(lines[v], np.float64))
    fs.release()


def cpp_median(tool, problem, method, runs):
    """Median seconds per call of the C++ API on @p problem, and the (R, t) it returned."""
    run = subprocess.run([str(tool), "--input", str(problem), "--method", method, "--runs", str(runs)],
                         capture_output=True, text=True)
    out = run.stdout.split("\n")
    if "no pose" in out:
        sys.exit(f"the C++ API found no pose on {problem.name} ({method}): its time would be a failure's")
    run.check_returncode()
    values = {line.split()[0]: [float(x) for x in line.split()[1:]] for line in out if line.strip()}
    return values["median_us"][0] * 1e-6, np.array(values["R"]).reshape(3, 3), np.array(values["t"])


def rotation_error_deg(R, R_true):
    return float(np.degrees(np.arccos(np.clip((np.trace(R @ R_true.T) - 1) / 2, -1, 1))))


# Both problems are solved to about 0.1 degree (0.5 px noise); anything beyond this is a broken solver,
# whose time means nothing.
MAX_ROTATION_ERROR_DEG = 2.0
# The package and the C++ API run the same code on the same doubles (the problem file stores them
# exactly): their poses agree to the last bit, up to this round-off allowance.
MAX_POSE_DIFFERENCE = 1e-12


def compare_with_cpp(tool, problem, method, python_call, runs, rounds):
    """Rounds of (the C++ API's runs, then the package's runs): the median over rounds of each side's
    median, and the largest pose difference between the two sides."""
    cpp, py, difference = [], [], 0.0
    for _ in range(rounds):
        seconds, R, t = cpp_median(tool, problem, method, runs)
        cpp.append(seconds)
        result = python_call()
        R_py, t_py = result.R, result.t
        difference = max(difference, float(np.abs(R - R_py).max()), float(np.abs(t - t_py).max()))
        py.append(interleaved({"py": python_call}, runs)["py"])
    if not difference <= MAX_POSE_DIFFERENCE:
        sys.exit(f"{problem.name} ({method}): the package and the C++ API return poses {difference:.1e} apart, "
                 "so they did not solve the same problem the same way")
    return float(np.median(cpp)), float(np.median(py)), difference


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2000)
    parser.add_argument("--rounds", type=int, default=5, help="alternations of the C++ and the Python runs")
    parser.add_argument("--build", type=Path, default=REPO / "build", help="the CMake build folder")
    args = parser.parse_args()
    tool = args.build / "test" / "benchmark" / "tripose_problem_benchmark"
    if not tool.is_file():
        sys.exit(f"{tool} is not built: cmake --build {args.build} --target tripose_problem_benchmark")

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
        linear = tripose.estimate_pose_line_point(*small)
        return tripose.refine_pose_line_point(*small, linear.R, linear.t)

    variants["4P+4L linear, then refine the best, tripose"] = linear_then_refine
    refine_variants = {
        "4P+4L linear + refine, tripose": lambda: tripose.estimate_pose_line_point(*small, refine=True),
    }
    no_refine = tripose.RansacOptions()
    no_refine.refine = False
    ransac_variants = {
        "100P+40L RANSAC + refine, extension": lambda: ext.estimate_pose_line_point_ransac(
            *big, None, None, "options", False),
        "100P+40L RANSAC + refine, tripose": lambda: tripose.estimate_pose_line_point_ransac(*big),
        "100P+40L RANSAC, no refine, tripose": lambda: tripose.estimate_pose_line_point_ransac(*big,
                                                                                              options=no_refine),
    }
    # Same results both ways, and a correct pose, or the comparison means nothing.
    a, c = ext.estimate_pose_line_point(*small, None, False), tripose.estimate_pose_line_point(*small)
    if not a.candidates or len(a.candidates) != len(c.candidates):
        sys.exit(f"4P+4L: {len(a.candidates)} candidates from the extension, {len(c.candidates)} from the wrapper")
    for x, y in zip(a.candidates, c.candidates):
        if not (np.array_equal(x[0], y[0]) and np.array_equal(x[1], y[1])):
            sys.exit("4P+4L: the extension and the wrapper return different poses")
    ransac = tripose.estimate_pose_line_point_ransac(*big)
    for name, R, R_true in (("4P+4L linear", c.R, s.R), ("100P+40L RANSAC", ransac["R"], b.R)):
        if R is None or not rotation_error_deg(R, R_true) < MAX_ROTATION_ERROR_DEG:
            error = "no pose" if R is None else f"{rotation_error_deg(R, R_true):.2f} deg off the truth"
            sys.exit(f"{name}: {error}; not timing a solver that fails")

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

    # The package beside the C++ API on the same arrays.
    ransac_runs = max(50, args.runs // 20)
    with tempfile.TemporaryDirectory() as folder:
        small_file, big_file = Path(folder) / "small.yml", Path(folder) / "big.yml"
        write_problem(small_file, points, lines, s.K, s.R12, s.t12)
        write_problem(big_file, big_points, big_lines, b.K, b.R12, b.t12)
        rows = [("4P+4L linear", *compare_with_cpp(tool, small_file, "linear",
                                                   lambda: tripose.estimate_pose_line_point(*small),
                                                   args.runs, args.rounds)),
                ("100P+40L RANSAC + refine", *compare_with_cpp(tool, big_file, "ransac",
                                                               lambda: tripose.estimate_pose_line_point_ransac(*big),
                                                               ransac_runs, args.rounds))]
    print(f"\n{'problem':26s} {'C++ API':>10s} {'tripose':>10s} {'added':>10s} {'ratio':>7s} {'pose diff':>10s}")
    for name, cpp, py, difference in rows:
        print(f"{name:26s} {1e6 * cpp:7.1f} us {1e6 * py:7.1f} us {1e6 * (py - cpp):7.1f} us {py / cpp:7.3f} "
              f"{difference:10.1e}")


if __name__ == "__main__":
    main()
