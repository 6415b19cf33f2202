"""The package and the C++ command-line tool tripose_estimate (built in build/samples, or in
$TRIPOSE_BUILD_DIR/samples) give the same poses and inlier masks on the same problem files.

The problem files are written here (OpenCV FileStorage YAML or JSON, through cv2) from noisy
synthetic scenes; the test reads each file back through cv2.FileStorage, so that both sides see the
values the file holds, and compares the tool's R, t (and masks) with the package's to 1e-12. A
missing tool is a failure, not a skip: the comparison is the point of this file.
"""
import os
import subprocess
from pathlib import Path

import cv2
import numpy as np
import pytest

import tripose
from cli_tool import estimate_tool
from scenes import add_outliers, stereo_scene, three_view_scene

REPO = Path(__file__).resolve().parents[2]
TOL = 1e-12


def write_problem(path, values):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    for key, value in values.items():
        fs.write(key, np.asarray(value, dtype=np.float64))
    fs.release()


def read_problem(path):
    """Every matrix of a problem file (None for an absent or empty key)."""
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    keys = ["K", "dist", "R12", "t12"] + [f"{kind}{v}" for kind in ("points", "lines") for v in (1, 2, 3, 4)]
    out = {}
    for key in keys:
        node = fs.getNode(key)
        out[key] = None if node.empty() else node.mat()
    fs.release()
    return out


def run_tool(tmp_path, problem, *options, name="result.yml"):
    out = tmp_path / name
    proc = subprocess.run([str(estimate_tool()), "--input", str(problem), "--output", str(out), *map(str, options)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    result = {"num_solutions": int(fs.getNode("num_solutions").real())}
    for key in ("R", "t", "point_inliers", "line_inliers"):
        node = fs.getNode(key)
        result[key] = None if node.empty() else node.mat()
    if not fs.getNode("num_inliers").empty():
        result["num_inliers"] = int(fs.getNode("num_inliers").real())
    fs.release()
    return result


def noisy_three_view_problem(tmp_path, seed, num_points, num_lines, outliers=0.0, dist=None, suffix=".yml"):
    s = three_view_scene(seed, num_points, num_lines)
    rng = np.random.default_rng(seed + 1000)
    points = [p + rng.normal(scale=0.5, size=p.shape) for p in s.points]
    lines = [l + rng.normal(scale=0.5, size=l.shape) for l in s.lines]
    if outliers:
        points[2], lines[2], _, _ = add_outliers(rng, points[2], lines[2], outliers)
    values = {"K": s.K, "R12": s.R12, "t12": s.t12.reshape(3, 1)}
    if dist is not None:
        # Observations as a camera with this distortion would see them.
        values["dist"] = dist
        for v in range(3):
            points[v] = distort(points[v], s.K, dist)
            lines[v] = distort(lines[v].reshape(-1, 2), s.K, dist).reshape(-1, 4)
    for v in range(3):
        values[f"points{v + 1}"] = points[v]
        values[f"lines{v + 1}"] = lines[v]
    path = tmp_path / f"problem_{seed}{suffix}"
    write_problem(path, values)
    return path


def distort(pixels, K, dist):
    """Pixels of an ideal camera K moved to where the camera K with distortion dist sees them."""
    normalised = np.c_[(pixels - K[:2, 2]) / np.diag(K)[:2], np.ones(len(pixels))]
    out, _ = cv2.projectPoints(normalised, np.zeros(3), np.zeros(3), K, np.asarray(dist, dtype=np.float64))
    return out.reshape(-1, 2)


def three_view_args(p):
    return (p["points1"], p["points2"], p["points3"], p["lines1"], p["lines2"], p["lines3"], p["K"], p["R12"],
            p["t12"])


def assert_same_pose(tool, R, t):
    assert tool["R"] is not None and R is not None
    np.testing.assert_allclose(R, tool["R"], rtol=0, atol=TOL)
    np.testing.assert_allclose(t, tool["t"].ravel(), rtol=0, atol=TOL * max(1.0, np.linalg.norm(t)))


def assert_same_masks(tool, result):
    np.testing.assert_array_equal(result["point_inliers"], tool["point_inliers"].ravel() != 0)
    np.testing.assert_array_equal(result["line_inliers"], tool["line_inliers"].ravel() != 0)
    assert result["num_inliers"] == tool["num_inliers"]


DIST5 = np.array([-0.12, 0.05, 0.001, -0.0015, -0.01])


@pytest.mark.parametrize("refine", [0, 1])
@pytest.mark.parametrize("seed,num_points,num_lines,dist,suffix", [
    (1, 6, 4, None, ".yml"), (2, 3, 1, None, ".yml"), (3, 0, 5, None, ".json"), (4, 8, 8, DIST5, ".yml")])
def test_linear_matches_tool(tmp_path, seed, num_points, num_lines, dist, suffix, refine):
    problem = noisy_three_view_problem(tmp_path, seed, num_points, num_lines, dist=dist, suffix=suffix)
    tool = run_tool(tmp_path, problem, "--method", "linear", "--refine", refine)
    p = read_problem(problem)
    result = tripose.estimate_pose_line_point(*three_view_args(p), dist=p["dist"], refine=bool(refine))
    assert tool["num_solutions"] == len(result.candidates) > 0
    assert_same_pose(tool, result.R, result.t)


@pytest.mark.parametrize("refine", [0, 1])
@pytest.mark.parametrize("seed,dist", [(5, None), (6, DIST5)])
def test_ransac_matches_tool(tmp_path, seed, dist, refine):
    problem = noisy_three_view_problem(tmp_path, seed, 60, 30, outliers=0.3, dist=dist)
    tool = run_tool(tmp_path, problem, "--method", "ransac", "--threshold", 3, "--refine", refine, "--seed", 7)
    p = read_problem(problem)
    result = tripose.estimate_pose_line_point_ransac(*three_view_args(p), dist=p["dist"], threshold=3.0,
                                                     refine=bool(refine), seed=7)
    assert_same_pose(tool, result["R"], result["t"])
    assert_same_masks(tool, result)


def stereo_problem(tmp_path, seed, num_points, num_lines, outliers=0.0):
    s = stereo_scene(seed, num_points, num_lines, missing=0.3)
    rng = np.random.default_rng(seed + 2000)
    points = [p + rng.normal(scale=0.5, size=p.shape) for p in s.points]
    lines = [l + rng.normal(scale=0.5, size=l.shape) for l in s.lines]
    if outliers:
        points[2], lines[2], _, _ = add_outliers(rng, points[2], lines[2], outliers)
    values = {"K": s.K, "R12": s.R12, "t12": s.t12.reshape(3, 1)}
    for v in range(4):
        values[f"points{v + 1}"] = points[v]
        values[f"lines{v + 1}"] = lines[v]
    path = tmp_path / f"stereo_{seed}.yml"
    write_problem(path, values)
    return path


def stereo_args(p):
    return (p["points1"], p["points2"], p["points3"], p["points4"], p["lines1"], p["lines2"], p["lines3"],
            p["lines4"], p["K"], p["R12"], p["t12"])


@pytest.mark.parametrize("refine", [0, 1])
def test_stereo_linear_matches_tool(tmp_path, refine):
    problem = stereo_problem(tmp_path, 8, 10, 6)
    p = read_problem(problem)
    # NaN rows (features unseen by view 3 or 4) survive the file.
    assert sum(int(np.isnan(p[key]).all(axis=1).sum()) for key in ("points3", "points4", "lines3", "lines4")) > 0
    tool = run_tool(tmp_path, problem, "--method", "linear", "--refine", refine)
    result = tripose.estimate_pose_line_point_stereo(*stereo_args(p), refine=bool(refine))
    assert tool["num_solutions"] == len(result.candidates) > 0
    assert_same_pose(tool, result.R, result.t)


def test_stereo_ransac_matches_tool(tmp_path):
    problem = stereo_problem(tmp_path, 9, 60, 30, outliers=0.3)
    tool = run_tool(tmp_path, problem, "--method", "ransac", "--threshold", 3, "--seed", 3)
    p = read_problem(problem)
    result = tripose.estimate_pose_line_point_stereo_ransac(*stereo_args(p), threshold=3.0, seed=3)
    assert_same_pose(tool, result["R"], result["t"])
    assert_same_masks(tool, result)
