"""The robust function's report of several minima within the noise (doc/conventions.md, "Several
minima"): the dict's candidates, candidate_rms and ambiguous. The C++ test test_narrow_minima.cpp
checks the minima themselves against a reference search; here, what the package returns."""
import numpy as np

import tripose
from scenes import observe, three_view_scene


def narrow_problem(seed, baseline=0.05, sigma=1.0):
    """A scene of 4 points and 4 lines whose view 2 sits `baseline` from view 1 (about 1 % of the
    7 m depth), with Gaussian noise of `sigma` px on every view."""
    scene = three_view_scene(seed, 4, 4)
    rng = np.random.default_rng(1000 + seed)
    R12, t12 = np.eye(3), -np.array([baseline, 0.0, 0.0])
    points2, lines2, _ = observe(scene.K, R12, t12, scene.structure, rng)
    points = [scene.points[0], points2, scene.points[2]]
    lines = [scene.lines[0], lines2, scene.lines[2]]
    points = [p + rng.normal(scale=sigma, size=p.shape) for p in points]
    lines = [l + rng.normal(scale=sigma, size=l.shape) for l in lines]
    return (*points, *lines, scene.K, R12, t12)


def check_report(result):
    candidates, rms = result["candidates"], result["candidate_rms"]
    assert len(candidates) == len(rms) >= 1
    assert result["ambiguous"] == (len(candidates) > 1)
    np.testing.assert_array_equal(candidates[0][0], result["R"])
    np.testing.assert_array_equal(candidates[0][1], result["t"])
    for R, t in candidates:
        assert R.shape == (3, 3) and t.shape == (3,)
        assert np.all(np.isfinite(R)) and np.all(np.isfinite(t))
    # The returned pose is the lowest minimum over the same residuals: its RMS is the smallest.
    assert all(r >= rms[0] for r in rms[1:])


def test_narrow_baselines_report_the_minima_within_the_noise():
    ambiguous = 0
    for seed in range(12):
        result = tripose.estimate_pose_line_point_ransac(*narrow_problem(seed), threshold=4.0, min_inliers=0)
        assert result["R"] is not None, seed
        check_report(result)
        ambiguous += result["ambiguous"]
    # About half of such scenes (4P+4L, 1 px) have a second minimum within the noise (doc/studies/accuracy.md).
    assert ambiguous >= 1


def test_a_wide_baseline_reports_its_pose_alone():
    scene = three_view_scene(3, 10, 10)
    result = tripose.estimate_pose_line_point_ransac(*scene.args(), threshold=2.0)
    check_report(result)
    assert not result["ambiguous"]


def test_without_refinement_there_is_no_report():
    scene = three_view_scene(3, 10, 10)
    result = tripose.estimate_pose_line_point_ransac(*scene.args(), refine=False)
    assert result["candidates"] == [] and result["candidate_rms"] == [] and not result["ambiguous"]
