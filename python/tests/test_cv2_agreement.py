"""The package and cv2.tripose (the OpenCV module's Python bindings) give the same results: one problem
of each family (three views, a stereo rig, several known views), solved by the linear estimators and
by RANSAC, against the solutions recorded in test/data/agreement/cv2_agreement.npz.

The recorded file holds the problems and the package's solutions of them. This test solves them with
the package, and with cv2.tripose where the cv2 on the path has it (an OpenCV built with the module;
the opencv-contrib-python wheels have not); modules/tripose/misc/python/test/test_tripose.py solves
them with cv2.tripose inside the OpenCV build (scripts/test_intree.sh), where the package is not
installed. Both compare with the same recorded solutions, so each side is checked where it runs.

After a change of the estimators that moves their results, record the file again (with the package
installed) and say why in the commit:

    python python/tests/test_cv2_agreement.py --record
"""
from __future__ import annotations

import os
import sys
from typing import Dict

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

RECORDED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test", "data", "agreement",
                        "cv2_agreement.npz")
SEED = 3  # the RANSAC's sampler seed

# Both sides run the same core on the same doubles; builds with other compilers or flags differ in
# rounding only. Poses: entries of R and of t / |t|; the covariance (an inverse) relative to its norm.
POSE_TOLERANCE = 1e-8
RMS_TOLERANCE = 1e-8
COVARIANCE_TOLERANCE = 1e-6
FAMILIES = ("three", "rig", "multi")


def make_problems() -> Dict[str, np.ndarray]:
    """One problem per family, 0.5 px noise; the RANSAC's copies have 25 % of the estimated views'
    observations moved 30-100 px (the linear estimators get the inliers alone)."""
    rng = np.random.default_rng(20261128)
    out: Dict[str, np.ndarray] = {"seed": np.array(SEED)}

    def noisy(a):
        a = np.array(a, dtype=np.float64)
        return a + rng.normal(scale=0.5, size=a.shape)

    s = scenes.three_view_scene(101, 40, 20)
    for v in range(3):
        out[f"three_points{v + 1}"] = noisy(s.points[v])
        out[f"three_lines{v + 1}"] = noisy(s.lines[v])
    out["three_ransac_points3"], out["three_ransac_lines3"], _, _ = scenes.add_outliers(
        rng, out["three_points3"], out["three_lines3"], 0.25)
    out["three_K"], out["three_R12"], out["three_t12"] = s.K, s.R12, s.t12

    r = scenes.stereo_scene(102, 40, 20, missing=0.2)
    for v in range(4):
        out[f"rig_points{v + 1}"] = noisy(r.points[v])
        out[f"rig_lines{v + 1}"] = noisy(r.lines[v])
    for v in (3, 4):
        # NaN rows (unseen) stay NaN when moved.
        out[f"rig_ransac_points{v}"], out[f"rig_ransac_lines{v}"], _, _ = scenes.add_outliers(
            rng, out[f"rig_points{v}"], out[f"rig_lines{v}"], 0.25)
    out["rig_K"], out["rig_R12"], out["rig_t12"] = r.K, r.R12, r.t12

    m = scenes.multiview_scene(103, 40, 20, num_known=3)
    views = len(m.points)
    for v in range(views):
        out[f"multi_points{v}"] = noisy(m.points[v])
        out[f"multi_lines{v}"] = noisy(m.lines[v])
    new = views - 1
    out["multi_ransac_points"], out["multi_ransac_lines"], _, _ = scenes.add_outliers(
        rng, out[f"multi_points{new}"], out[f"multi_lines{new}"], 0.25)
    out["multi_K"], out["multi_Rs"], out["multi_ts"] = m.K, np.array(m.Rs), np.array(m.ts)
    return out


def three_view_args(p: Dict[str, np.ndarray], ransac: bool) -> list:
    view3 = ("three_ransac_points3", "three_ransac_lines3") if ransac else ("three_points3", "three_lines3")
    return [p["three_points1"], p["three_points2"], p[view3[0]], p["three_lines1"], p["three_lines2"], p[view3[1]]]


def rig_args(p: Dict[str, np.ndarray], ransac: bool) -> list:
    late = "rig_ransac_" if ransac else "rig_"
    return [p["rig_points1"], p["rig_points2"], p[late + "points3"], p[late + "points4"],
            p["rig_lines1"], p["rig_lines2"], p[late + "lines3"], p[late + "lines4"]]


def multi_args(p: Dict[str, np.ndarray], ransac: bool) -> tuple:
    views = len(p["multi_Rs"]) + 1
    points = [p[f"multi_points{v}"] for v in range(views)]
    lines = [p[f"multi_lines{v}"] for v in range(views)]
    if ransac:
        points[-1], lines[-1] = p["multi_ransac_points"], p["multi_ransac_lines"]
    return points, lines, list(p["multi_Rs"]), list(p["multi_ts"])


def with_robust(out: Dict[str, np.ndarray], family: str, num_inliers, R, t, point_inliers, line_inliers,
                candidate_Rs, candidate_ts, candidate_rms, covariance, noise_variance) -> None:
    """The robust estimate's outputs under their keys, in one layout whichever side produced them."""
    key = family + "_ransac_"
    out[key + "num_inliers"] = np.array(int(num_inliers))
    out[key + "R"] = np.asarray(R, np.float64).reshape(3, 3)
    out[key + "t"] = np.asarray(t, np.float64).reshape(3)
    out[key + "point_inliers"] = np.asarray(point_inliers).ravel() != 0
    out[key + "line_inliers"] = np.asarray(line_inliers).ravel() != 0
    out[key + "candidate_Rs"] = np.array([np.asarray(c, np.float64).reshape(3, 3) for c in candidate_Rs]).reshape(-1, 3, 3)
    out[key + "candidate_ts"] = np.array([np.asarray(c, np.float64).reshape(3) for c in candidate_ts]).reshape(-1, 3)
    out[key + "candidate_rms"] = np.asarray(candidate_rms, np.float64).ravel()
    out[key + "covariance"] = np.asarray(covariance, np.float64).reshape(6, 6)
    out[key + "noise_variance"] = np.array(float(np.asarray(noise_variance).ravel()[0]))


def with_linear(out: Dict[str, np.ndarray], family: str, Rs, ts) -> None:
    out[family + "_linear_Rs"] = np.array([np.asarray(R, np.float64).reshape(3, 3) for R in Rs]).reshape(-1, 3, 3)
    out[family + "_linear_ts"] = np.array([np.asarray(t, np.float64).reshape(3) for t in ts]).reshape(-1, 3)


def solve_with_package(p: Dict[str, np.ndarray]) -> Dict[str, np.ndarray]:
    import tripose

    options = tripose.RansacOptions(seed=int(p["seed"]))
    out: Dict[str, np.ndarray] = {}

    def robust(family: str, result) -> None:
        with_robust(out, family, result.num_inliers, result.R, result.t, result.point_inliers, result.line_inliers,
                    [R for R, _ in result.candidates], [t for _, t in result.candidates], result.candidate_rms,
                    result.covariance, result.noise_variance)

    def linear(family: str, result) -> None:
        with_linear(out, family, [R for R, _ in result.candidates], [t for _, t in result.candidates])

    known = (p["three_K"], p["three_R12"], p["three_t12"])
    linear("three", tripose.estimate_pose_line_point(*three_view_args(p, False), *known))
    robust("three", tripose.estimate_pose_line_point_ransac(*three_view_args(p, True), *known, options=options,
                                                            covariance=True))
    rig = (p["rig_K"], p["rig_R12"], p["rig_t12"])
    linear("rig", tripose.estimate_pose_line_point_stereo(*rig_args(p, False), *rig))
    robust("rig", tripose.estimate_pose_line_point_stereo_ransac(*rig_args(p, True), *rig, options=options,
                                                                 covariance=True))
    points, lines, Rs, ts = multi_args(p, False)
    linear("multi", tripose.estimate_pose_multiview(points, lines, p["multi_K"], Rs, ts))
    points, lines, Rs, ts = multi_args(p, True)
    robust("multi", tripose.estimate_pose_multiview_ransac(points, lines, p["multi_K"], Rs, ts, options=options,
                                                           covariance=True))
    return out


def solve_with_cv2(cv, p: Dict[str, np.ndarray]) -> Dict[str, np.ndarray]:
    """The same calls through cv2.tripose: every optional output in the order the C++ functions
    declare it (candidates, their errors, covariance, noise variance after the inlier masks)."""
    params = cv.tripose.RansacParams()
    params.seed = int(p["seed"])
    out: Dict[str, np.ndarray] = {}

    def robust(family: str, result) -> None:
        n, R, t, point_inliers, line_inliers, Rs, ts, errors, covariance, noise_variance = result
        with_robust(out, family, n, R, t, point_inliers, line_inliers, Rs, ts, errors, covariance, noise_variance)

    def linear(family: str, result) -> None:
        _, _, _, Rs, ts = result[:5]
        with_linear(out, family, Rs, ts)

    known = (p["three_K"], None, p["three_R12"], p["three_t12"])
    linear("three", cv.tripose.estimatePoseLinePoint(*three_view_args(p, False), *known))
    robust("three", cv.tripose.estimatePoseLinePointRansac(*three_view_args(p, True), *known, params=params))
    rig = (p["rig_K"], None, p["rig_R12"], p["rig_t12"])
    linear("rig", cv.tripose.estimatePoseLinePointStereo(*rig_args(p, False), *rig))
    robust("rig", cv.tripose.estimatePoseLinePointStereoRansac(*rig_args(p, True), *rig, params=params))
    points, lines, Rs, ts = multi_args(p, False)
    linear("multi", cv.tripose.estimatePoseMultiView(points, lines, p["multi_K"], None, Rs, ts))
    points, lines, Rs, ts = multi_args(p, True)
    robust("multi", cv.tripose.estimatePoseMultiViewRansac(points, lines, p["multi_K"], None, Rs, ts, params=params))
    return out


def differences(found: Dict[str, np.ndarray], expected: Dict[str, np.ndarray]) -> list:
    """What differs between two solutions, one line per output (empty: they agree)."""
    problems = []

    def poses(key_R, key_t):
        R, R0, t, t0 = found[key_R], expected[key_R], found[key_t], expected[key_t]
        if R.shape != R0.shape:
            problems.append(f"{key_R}: {len(R)} poses, expected {len(R0)}")
            return
        scale = max(1.0, float(np.abs(t0).max(initial=0.0)))
        if R.size and np.abs(R - R0).max() > POSE_TOLERANCE:
            problems.append(f"{key_R}: off by {np.abs(R - R0).max():.3g}")
        if t.size and np.abs(t - t0).max() > POSE_TOLERANCE * scale:
            problems.append(f"{key_t}: off by {np.abs(t - t0).max():.3g} (|t| {scale:.3g})")

    for family in FAMILIES:
        poses(f"{family}_linear_Rs", f"{family}_linear_ts")
        key = family + "_ransac_"
        for exact in ("num_inliers", "point_inliers", "line_inliers"):
            if not np.array_equal(found[key + exact], expected[key + exact]):
                problems.append(f"{key + exact}: {found[key + exact]} instead of {expected[key + exact]}")
        poses(key + "R", key + "t")
        poses(key + "candidate_Rs", key + "candidate_ts")
        rms, rms0 = found[key + "candidate_rms"], expected[key + "candidate_rms"]
        if rms.shape != rms0.shape or (rms.size and np.abs(rms - rms0).max() > RMS_TOLERANCE * rms0.max()):
            problems.append(f"{key}candidate_rms: {rms} instead of {rms0}")
        C, C0 = found[key + "covariance"], expected[key + "covariance"]
        if np.linalg.norm(C - C0) > COVARIANCE_TOLERANCE * np.linalg.norm(C0):
            problems.append(f"{key}covariance: off by {np.linalg.norm(C - C0) / np.linalg.norm(C0):.3g} relative")
        s2, s20 = float(found[key + "noise_variance"]), float(expected[key + "noise_variance"])
        if abs(s2 - s20) > RMS_TOLERANCE * s20:
            problems.append(f"{key}noise_variance: {s2} instead of {s20}")
    return problems


def load_recorded() -> Dict[str, np.ndarray]:
    with np.load(RECORDED, allow_pickle=False) as data:
        return {key: data[key] for key in data.files}


def test_the_recorded_problems_are_meaningful():
    # Each robust problem has wrong matches to reject and enough right ones; each linear one a pose.
    recorded = load_recorded()
    for family in FAMILIES:
        key = family + "_ransac_"
        assert recorded[key + "num_inliers"] >= 30, family
        assert not recorded[key + "point_inliers"].all() and not recorded[key + "line_inliers"].all(), family
        assert len(recorded[key + "candidate_Rs"]) >= 1, family
        assert len(recorded[family + "_linear_Rs"]) >= 1, family


def test_the_package_gives_the_recorded_solutions():
    pytest.importorskip("tripose")
    recorded = load_recorded()
    assert differences(solve_with_package(recorded), recorded) == []


def test_cv2_tripose_agrees_with_the_package():
    cv = pytest.importorskip("cv2")
    if not hasattr(cv, "tripose"):
        pytest.skip("this cv2 has no tripose module (an OpenCV built with it has: scripts/test_intree.sh)")
    pytest.importorskip("tripose")
    recorded = load_recorded()
    package = solve_with_package(recorded)
    assert differences(solve_with_cv2(cv, recorded), package) == []


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit(f"usage: {sys.argv[0]} --record")
    problems = make_problems()
    problems.update(solve_with_package(problems))
    os.makedirs(os.path.dirname(RECORDED), exist_ok=True)
    np.savez_compressed(RECORDED, **problems)
    print(f"recorded {RECORDED}: " + ", ".join(
        f"{family} {int(problems[family + '_ransac_num_inliers'])} inliers, "
        f"{len(problems[family + '_ransac_candidate_Rs'])} candidate(s), "
        f"{len(problems[family + '_linear_Rs'])} linear candidate(s)" for family in FAMILIES))
