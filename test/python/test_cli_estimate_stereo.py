"""End-to-end tests of `tripose_estimate` on stereo-rig problem files (points4 and/or lines4).

Scenes come from the support library's rig generator through `tripose_make_scene --stereo`; a row of
.nan in points3/points4/lines3/lines4 marks a feature that view does not see.
"""
import subprocess

import cv2
import numpy as np
import pytest

from tripose_tools import (all_of, build_tool, edited, estimate, expect_rejected, make_stereo_scene, read_matrices,
                           rotation_error, run, setter, write_problem)

STEREO_KEYS = ["K1", "K2", "K3", "K4", "R12", "t12", "points1", "points2", "points3", "points4",
               "lines1", "lines2", "lines3", "lines4"]


def exact(result, truth):
    return (rotation_error(result["R"], truth["R_gt"]) < 1e-6 and
            np.linalg.norm(result["t"].ravel() - truth["t_gt"].ravel()) < 1e-6 * np.linalg.norm(truth["t_gt"]))


@pytest.mark.parametrize("points,lines,missing", [(3, 0, 0.0), (0, 3, 0.0), (2, 1, 0.0), (10, 10, 0.5), (6, 6, 1.0)])
def test_linear_recovers_exact_rig_motion(tmp_path, points, lines, missing):
    scene = make_stereo_scene(tmp_path, points, lines, seed=5, missing=missing)
    values = read_matrices(scene, STEREO_KEYS + ["R_gt", "t_gt"])
    # The file carries NaN rows (written by FileStorage as .Nan) exactly when features are missing.
    time_b = [values.get(k) for k in ("points3", "points4", "lines3", "lines4")]
    assert any(m is not None and np.isnan(m).any() for m in time_b) == (missing > 0)
    proc, out = estimate(tmp_path, scene)
    assert proc.returncode == 0, proc.stderr
    result = read_matrices(out, ["R", "t"])
    assert exact(result, values)


@pytest.mark.parametrize("spelling", [".nan", "nan", ".NaN", "NaN", ".NAN"])
def test_nan_spellings_mark_missing_rows(tmp_path, spelling):
    # YAML's .nan in its spellings, and the plain nan other writers produce: each reads as NaN.
    scene = make_stereo_scene(tmp_path, 8, 8, seed=6, missing=0.5)
    text = scene.read_text()
    assert ".Nan" in text
    problem = tmp_path / "spelled.yml"
    problem.write_text(text.replace(".Nan", spelling))
    proc, out = estimate(tmp_path, problem)
    assert proc.returncode == 0, proc.stderr
    assert exact(read_matrices(out, ["R", "t"]), read_matrices(scene, ["R_gt", "t_gt"]))


def test_json_rig_problem_with_shared_K_and_absent_view(tmp_path):
    # JSON, one K for the four views, and lines4 absent: view 4 sees no lines, so every line must be
    # seen in view 3 (no NaN in lines3).
    scene = make_stereo_scene(tmp_path, 6, 4, seed=7)
    values = read_matrices(scene, STEREO_KEYS)
    values["K"] = values.pop("K1")
    for k in ("K2", "K3", "K4", "lines4"):
        values.pop(k)
    problem = tmp_path / "rig.json"
    write_problem(problem, values)
    proc, out = estimate(tmp_path, problem, name="result.json")
    assert proc.returncode == 0, proc.stderr
    assert exact(read_matrices(out, ["R", "t"]), read_matrices(scene, ["R_gt", "t_gt"]))


def test_ransac_on_a_rig_writes_inlier_masks(tmp_path):
    scene = make_stereo_scene(tmp_path, 60, 30, seed=2, noise=1.0, outliers=0.3, missing=0.2)
    proc, out = estimate(tmp_path, scene, "--method", "ransac")
    assert proc.returncode == 0, proc.stderr
    truth = read_matrices(scene, ["R_gt", "point_inliers", "line_inliers"])
    result = read_matrices(out, ["R", "point_inliers", "line_inliers"])
    assert rotation_error(result["R"], truth["R_gt"]) < np.deg2rad(0.5)
    assert result["point_inliers"].size == 60 and result["line_inliers"].size == 30
    agree = np.mean(np.concatenate([result["point_inliers"].ravel() == truth["point_inliers"].ravel(),
                                    result["line_inliers"].ravel() == truth["line_inliers"].ravel()]))
    assert agree >= 0.95


def test_linear_refine_on_a_rig(tmp_path):
    linear, refined = [], []
    for seed in range(8):
        scene = make_stereo_scene(tmp_path, 8, 8, seed=seed, noise=1.0, missing=0.2)
        truth = read_matrices(scene, ["R_gt"])["R_gt"]
        for flag, errors in (("0", linear), ("1", refined)):
            proc, out = estimate(tmp_path, scene, "--refine", flag, name=f"r{seed}_{flag}.yml")
            assert proc.returncode == 0, proc.stderr
            errors.append(rotation_error(read_matrices(out, ["R"])["R"], truth))
    assert np.median(refined) < np.median(linear)


def test_help_documents_the_rig():
    proc = run("--help")
    assert proc.returncode == 0
    for words in ("points4", "K1..K4", ".nan"):
        assert words in proc.stdout + proc.stderr, words


def partly_nan(key, row, col):
    return edited(key, row, col, np.nan)


def nan_row(key, row):
    def change(v):
        m = v[key].copy()
        m[row, :] = np.nan
        v[key] = m
    return change


@pytest.fixture(scope="module")
def rig_scene(tmp_path_factory):
    # Every feature seen by both time-B views (no --missing): each kind below breaks one thing.
    return make_stereo_scene(tmp_path_factory.mktemp("rig"), 4, 3, seed=1)


# Bad rig problems: the change of a valid 4-point, 3-line rig problem (K1..K4) and what stderr names.
STEREO_CATALOGUE = {
    "points4_row_count": (setter("points4", lambda v: v["points4"][:3]), "key 'points4'"),
    "lines4_row_count": (setter("lines4", lambda v: np.vstack([v["lines4"], v["lines4"][:1]])), "key 'lines4'"),
    "points3_row_count": (setter("points3", lambda v: v["points3"][:1]), "key 'points3'"),
    "points4_wrong_width": (setter("points4", np.ones((4, 3))), "key 'points4'"),
    "lines3_homogeneous": (setter("lines3", lambda v: v["lines3"][:, :3].copy()), "key 'lines3'"),
    "partly_nan_row_points4": (partly_nan("points4", 0, 1), "key 'points4'"),
    "partly_nan_row_lines3": (partly_nan("lines3", 1, 2), "key 'lines3'"),
    "inf_in_points4": (edited("points4", 0, 0, np.inf), "key 'points4'"),
    "nan_in_points1": (nan_row("points1", 0), "key 'points1'"),
    "nan_in_lines2": (nan_row("lines2", 1), "key 'lines2'"),
    "point_missing_in_views_3_and_4": (all_of(nan_row("points3", 0), nan_row("points4", 0)), "key 'points3'"),
    "line_missing_in_views_3_and_4": (all_of(nan_row("lines3", 2), nan_row("lines4", 2)), "key 'lines3'"),
    "K4_missing": (lambda v: v.pop("K4"), "key 'K4'"),
    "K4_bad": (edited("K4", 0, 0, -1.0), "key 'K4'"),
    "dist_for_three_views_only": (all_of(*[setter(f"dist{i}", np.zeros((1, 5))) for i in (1, 2, 3)]), "key 'dist4'"),
    "dist4_bad": (all_of(*[setter(f"dist{i}", np.zeros((1, 5))) for i in (1, 2, 3)],
                         setter("dist4", np.zeros((1, 6)) + 0.01)), "key 'dist4'"),
    "t12_zero": (setter("t12", np.zeros((3, 1))), "key 't12'"),
}


def test_stereo_catalogue_problem_is_valid(tmp_path, rig_scene):
    values = read_matrices(rig_scene, STEREO_KEYS)
    for key in ("points3", "points4", "lines3", "lines4"):
        assert not np.isnan(values[key]).any(), key
    problem = tmp_path / "rig.yml"
    write_problem(problem, values)
    for method in ("linear", "ransac"):
        proc, out = estimate(tmp_path, problem, "--method", method, name=f"{method}.yml")
        assert proc.returncode == 0, proc.stderr


@pytest.mark.parametrize("kind", sorted(STEREO_CATALOGUE))
@pytest.mark.parametrize("method", ["linear", "ransac"])
def test_bad_rig_input_is_named_and_nothing_is_written(tmp_path, rig_scene, kind, method):
    change, names = STEREO_CATALOGUE[kind]
    values = read_matrices(rig_scene, STEREO_KEYS)
    change(values)
    problem = tmp_path / "broken.yml"
    write_problem(problem, values)
    expect_rejected(tmp_path, problem, names, "--method", method)


def test_nan_outside_the_time_B_views_of_a_rig_is_rejected_by_the_reader(tmp_path, rig_scene):
    # A three-view problem has no missing rows: .nan in points3 is an error of the file.
    values = read_matrices(rig_scene, STEREO_KEYS)
    for key in ("points4", "lines4", "K4"):
        values.pop(key)
    values["points3"] = values["points3"].copy()
    values["points3"][0, :] = np.nan
    problem = tmp_path / "three_view.yml"
    write_problem(problem, values)
    expect_rejected(tmp_path, problem, "key 'points3': contains NaN or Inf")


def test_make_scene_stereo_rejects_three_view_options(tmp_path):
    tool = str(build_tool("tripose_make_scene"))
    proc = subprocess.run([tool, "--stereo", "--motion", "small", "--output", str(tmp_path / "s.yml")],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1 and "argument --motion" in proc.stderr
    proc = subprocess.run([tool, "--missing", "0.5", "--output", str(tmp_path / "s.yml")],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1 and "argument --missing" in proc.stderr
