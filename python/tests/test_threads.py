"""Estimation releases the GIL: calls from several threads give the sequential results, and Python
code runs while an estimate is being computed. No timing is asserted."""
import sys
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import tripose
from scenes import add_outliers, three_view_scene


@pytest.fixture(scope="module")
def problem():
    """500 features (300 points, 200 lines), 0.7 px noise, 30 % outliers in view 3."""
    s = three_view_scene(0, 300, 200, min_line_plane_angle=np.deg2rad(10.0))
    rng = np.random.default_rng(0)
    points = [p + rng.normal(scale=0.7, size=p.shape) for p in s.points]
    lines = [l + rng.normal(scale=0.7, size=l.shape) for l in s.lines]
    points[2], lines[2], _, _ = add_outliers(rng, points[2], lines[2], 0.3)
    return (*points, *lines, s.K, s.R12, s.t12)


def run_ransac(args, seed):
    return tripose.estimate_pose_line_point_ransac(*args, seed=seed, threshold=2.5)


def test_threads_give_the_sequential_results(problem):
    seeds = list(range(8))
    sequential = [run_ransac(problem, seed) for seed in seeds]
    with ThreadPoolExecutor(2) as pool:
        threaded = list(pool.map(lambda seed: run_ransac(problem, seed), seeds))
    for a, b in zip(sequential, threaded):
        assert a["R"] is not None
        np.testing.assert_array_equal(a["R"], b["R"])
        np.testing.assert_array_equal(a["t"], b["t"])
        np.testing.assert_array_equal(a["point_inliers"], b["point_inliers"])
        np.testing.assert_array_equal(a["line_inliers"], b["line_inliers"])
        assert a["num_inliers"] == b["num_inliers"] and a["rms"] == b["rms"]


def test_threads_share_one_input_without_copies(problem):
    # Eight threads on the very same arrays: the extension only reads them.
    with ThreadPoolExecutor(8) as pool:
        results = list(pool.map(lambda _: tripose.estimate_pose_line_point(*problem), range(8)))
    for r in results[1:]:
        assert len(r.candidates) == len(results[0].candidates) > 0
        for (Ra, ta), (Rb, tb) in zip(results[0].candidates, r.candidates):
            np.testing.assert_array_equal(Ra, Rb)
            np.testing.assert_array_equal(ta, tb)


def test_python_runs_during_an_estimate(problem):
    # The main thread counts while a worker thread runs one estimate (the linear solver with
    # refinement on 500 features, tens of milliseconds). Holding the GIL, the estimate would stop
    # the counting for all of its duration: with a switch interval of 0.1 ms, only the few bytecodes
    # of the Python wrapper around the call could let the counter on, a few hundred increments per
    # switch. Released, the counter runs throughout, ~1e5 increments or more.
    state = {"count": 0, "done": False}

    def work():
        state["start"] = state["count"]
        tripose.estimate_pose_line_point(*problem, refine=True)
        state["end"] = state["count"]
        state["done"] = True

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-4)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        while not state["done"]:
            state["count"] += 1
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert state["end"] - state["start"] > 20000, state
