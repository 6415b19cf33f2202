"""End-to-end tests of the command-line estimator `tripose_estimate` on problem files.

Scenes come from the project's own generator through `tripose_make_scene`; files are read and
written with OpenCV's FileStorage, the format the tools speak.
"""
import os
import subprocess
from pathlib import Path

import cv2
import numpy as np
import pytest

from tripose_tools import build_tool, rotation_error, make_scene

ESTIMATE = build_tool("tripose_estimate")

PROBLEM_KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]


def read_matrices(path, keys):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    out = {k: fs.getNode(k).mat() for k in keys if not fs.getNode(k).empty()}
    fs.release()
    return out


def write_problem(path, values):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    for key, value in values.items():
        if isinstance(value, str):
            fs.write(key, value)
        else:
            fs.write(key, np.asarray(value, dtype=np.float64))
    fs.release()


def run(*args):
    return subprocess.run([str(ESTIMATE), *map(str, args)], capture_output=True, text=True, timeout=60)


def estimate(tmp_path, problem, *extra, name="result.yml"):
    out = tmp_path / name
    proc = run("--input", problem, "--output", out, *extra)
    return proc, out


def test_linear_recovers_exact_pose(tmp_path):
    scene = make_scene(tmp_path, points=3, lines=3, seed=4)
    proc, out = estimate(tmp_path, scene)
    assert proc.returncode == 0, proc.stderr
    truth = read_matrices(scene, ["R_gt", "t_gt"])
    result = read_matrices(out, ["R", "t"])
    assert rotation_error(result["R"], truth["R_gt"]) < 1e-6
    assert np.linalg.norm(result["t"].ravel() - truth["t_gt"].ravel()) < 1e-6 * np.linalg.norm(truth["t_gt"])


@pytest.mark.parametrize("points,lines", [(6, 0), (0, 6), (2, 2)])
def test_either_kind_of_feature_may_be_absent(tmp_path, points, lines):
    scene = make_scene(tmp_path, points=points, lines=lines, seed=9)
    values = read_matrices(scene, PROBLEM_KEYS)
    problem = tmp_path / "problem.json"  # JSON as well as YAML
    write_problem(problem, {k: v for k, v in values.items() if v is not None and v.size > 0})
    proc, out = estimate(tmp_path, problem, name="result.json")
    assert proc.returncode == 0, proc.stderr
    truth = read_matrices(scene, ["R_gt"])
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    assert fs.getNode("num_solutions").real() >= 1
    assert rotation_error(fs.getNode("R").mat(), truth["R_gt"]) < 1e-6


def test_ransac_writes_inlier_masks(tmp_path):
    scene = make_scene(tmp_path, points=60, lines=30, seed=2, noise=1.0, outliers=0.3)
    proc, out = estimate(tmp_path, scene, "--method", "ransac", "--threshold", "3", "--refine", "1")
    assert proc.returncode == 0, proc.stderr
    truth = read_matrices(scene, ["R_gt", "point_inliers", "line_inliers"])
    result = read_matrices(out, ["R", "inliers_points", "inliers_lines"])
    assert rotation_error(result["R"], truth["R_gt"]) < np.deg2rad(1.0)
    assert result["inliers_points"].size == 60 and result["inliers_lines"].size == 30
    agree = np.mean(np.concatenate([result["inliers_points"].ravel() == truth["point_inliers"].ravel(),
                                    result["inliers_lines"].ravel() == truth["line_inliers"].ravel()]))
    assert agree >= 0.95


def break_problem(tmp_path, scene, change):
    values = read_matrices(scene, PROBLEM_KEYS)
    change(values)
    problem = tmp_path / "broken.yml"
    write_problem(problem, values)
    return problem


BROKEN = {
    "K1": lambda v: v.pop("K1"),
    "points2": lambda v: v.__setitem__("points2", v["points2"][:2]),
    "lines3": lambda v: v.__setitem__("lines3", v["lines3"][:, :3]),
    "t12": lambda v: v.pop("t12"),
    "R12": lambda v: v.__setitem__("R12", 2.0 * v["R12"]),
    "K": lambda v: v.__setitem__("K", v["K1"]),  # K together with K1..K3
}


@pytest.mark.parametrize("key", sorted(BROKEN))
def test_malformed_key_is_named_and_nothing_is_written(tmp_path, key):
    scene = make_scene(tmp_path, points=3, lines=3, seed=1)
    problem = break_problem(tmp_path, scene, BROKEN[key])
    proc, out = estimate(tmp_path, problem)
    assert proc.returncode != 0
    assert key in proc.stderr, proc.stderr
    assert not out.exists()
    assert not list(tmp_path.glob("result.partial*"))


@pytest.mark.parametrize("args,name", [
    (["--method", "magic"], "--method"),
    (["--threshold", "-1", "--method", "ransac"], "--threshold"),
    (["--threshold", "abc", "--method", "ransac"], "--threshold"),
    (["--refine", "2", "--method", "ransac"], "--refine"),
])
def test_bad_arguments_are_named(tmp_path, args, name):
    scene = make_scene(tmp_path, points=3, lines=3, seed=1)
    proc, out = estimate(tmp_path, scene, *args)
    assert proc.returncode != 0
    assert name in proc.stderr
    assert not out.exists()


def test_unparsable_file_is_rejected(tmp_path):
    problem = tmp_path / "garbage.yml"
    problem.write_text("%YAML:1.0\nK1: [this is not\n")
    proc, out = estimate(tmp_path, problem)
    assert proc.returncode != 0
    assert not out.exists()
