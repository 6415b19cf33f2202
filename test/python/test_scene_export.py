# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Synthetic scenes exported by samples/tripose_make_scene read back in Python (numpy + cv2).

The tool is looked up in $TRIPOSE_BUILD_DIR/samples, else in build/samples under the repository
root; a tool that has not been built is an error.
"""

import subprocess

import cv2
import numpy as np
import pytest

from tripose_tools import build_tool

TOOL_NAME = "tripose_make_scene"
TOOL = build_tool(TOOL_NAME)

PROBLEM_KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]
TRUTH_KEYS = ["R_gt", "t_gt", "points3d", "lines3d", "point_inliers", "line_inliers"]


def make_scene(path, *args):
    return subprocess.run([str(TOOL), "--output", str(path), *map(str, args)],
                          capture_output=True, text=True, timeout=60)


def read_scene(path):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    assert fs.isOpened(), f"cannot open {path}"
    scene = {}
    for key in PROBLEM_KEYS + TRUTH_KEYS:
        node = fs.getNode(key)
        assert not node.empty(), f"key {key} missing from {path}"
        # A 0-row matrix reads as None; rows() restores its documented column count.
        scene[key] = node.mat()
    fs.release()
    return scene


def rows(m, cols):
    return np.zeros((0, cols)) if m is None else np.asarray(m, dtype=np.float64).reshape(-1, cols)


def poses(scene):
    return [(np.eye(3), np.zeros(3)),
            (scene["R12"], scene["t12"].ravel()),
            (scene["R_gt"], scene["t_gt"].ravel())]


def project(K, R, t, X):
    """Pixels of the rows of X under x ~ K (R X + t), and their depths."""
    c = X @ R.T + t
    p = c @ K.T
    return p[:, :2] / p[:, 2:3], c[:, 2]


@pytest.mark.parametrize("motion", ["large", "small"])
@pytest.mark.parametrize("extension", [".yml", ".json"])
def test_noise_free_scene_reprojects_exactly(tmp_path, motion, extension):
    path = tmp_path / f"scene{extension}"
    result = make_scene(path, "--points", 12, "--lines", 9, "--motion", motion, "--seed", 5)
    assert result.returncode == 0, result.stderr
    s = read_scene(path)

    X = rows(s["points3d"], 3)
    L = rows(s["lines3d"], 6)
    assert X.shape == (12, 3) and L.shape == (9, 6)
    for R in (s["R12"], s["R_gt"]):
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-12)
        assert abs(np.linalg.det(R) - 1) < 1e-12

    for v, (R, t) in enumerate(poses(s)):
        K = s[f"K{v + 1}"]
        np.testing.assert_array_equal(K, [[800, 0, 319.5], [0, 800, 239.5], [0, 0, 1]])
        x, depth = project(K, R, t, X)
        a, depth_a = project(K, R, t, L[:, :3])
        b, depth_b = project(K, R, t, L[:, 3:])
        assert (depth > 0).all() and (depth_a > 0).all() and (depth_b > 0).all()
        points = rows(s[f"points{v + 1}"], 2)
        segments = rows(s[f"lines{v + 1}"], 4)
        assert np.abs(x - points).max() < 1e-9
        assert np.abs(a - segments[:, :2]).max() < 1e-9
        assert np.abs(b - segments[:, 2:]).max() < 1e-9
        inside = np.vstack([points, segments[:, :2], segments[:, 2:]])
        assert (inside >= 0).all() and (inside[:, 0] <= 639).all() and (inside[:, 1] <= 479).all()


def test_same_seed_writes_the_same_file(tmp_path):
    args = ["--points", 6, "--lines", 6, "--noise", 1.0, "--outliers", 0.25]
    first, second, other = tmp_path / "a.yml", tmp_path / "b.yml", tmp_path / "c.yml"
    for path, seed in ((first, 42), (second, 42), (other, 43)):
        result = make_scene(path, *args, "--seed", seed)
        assert result.returncode == 0, result.stderr
    assert first.read_bytes() == second.read_bytes()
    assert first.read_bytes() != other.read_bytes()
    a, c = read_scene(first), read_scene(other)
    assert np.abs(a["R_gt"] - c["R_gt"]).max() > 1e-3


def test_noise_and_outliers(tmp_path):
    sigma, n = 2.0, 200
    path = tmp_path / "noisy.json"
    result = make_scene(path, "--points", n, "--lines", n, "--noise", sigma, "--outliers", 0.3, "--seed", 8)
    assert result.returncode == 0, result.stderr
    s = read_scene(path)
    point_inliers = s["point_inliers"].ravel().astype(bool)
    line_inliers = s["line_inliers"].ravel().astype(bool)
    assert (~point_inliers).sum() == round(0.3 * n)
    assert (~line_inliers).sum() == round(0.3 * n)

    # Residuals of the inliers in view 3 are N(0, sigma^2) per coordinate: 140 points and 280 end
    # points give 840 coordinates, so the sample std has a relative standard error of
    # 1/sqrt(2 * 840) = 2.4%; +-10% is 4 standard errors.
    K, (R, t) = s["K3"], poses(s)[2]
    x, _ = project(K, R, t, rows(s["points3d"], 3)[point_inliers])
    L = rows(s["lines3d"], 6)[line_inliers]
    a, _ = project(K, R, t, L[:, :3])
    b, _ = project(K, R, t, L[:, 3:])
    segments = rows(s["lines3"], 4)[line_inliers]
    residuals = np.concatenate([(rows(s["points3"], 2)[point_inliers] - x).ravel(),
                                (segments[:, :2] - a).ravel(), (segments[:, 2:] - b).ravel()])
    assert abs(residuals.std(ddof=1) / sigma - 1) < 0.1

    # Outliers are far from the truth.
    x_out, _ = project(K, R, t, rows(s["points3d"], 3)[~point_inliers])
    assert (np.linalg.norm(rows(s["points3"], 2)[~point_inliers] - x_out, axis=1) > 20 - 6 * sigma).all()


def test_narrow_baseline_and_planar_regimes(tmp_path):
    # View 2 at the requested distance from view 1 (centre -R12^T t12), in metres or as a fraction of
    # the 20 m depth.
    for args, baseline in ((["--baseline12", "0.3"], 0.3), (["--baseline12-fraction", "0.01"], 0.2)):
        path = tmp_path / "narrow.yml"
        assert make_scene(path, "--points", 6, "--lines", 6, "--motion", "small", *args).returncode == 0
        s = read_scene(path)
        assert np.linalg.norm(s["R12"].T @ s["t12"].ravel()) == pytest.approx(baseline, rel=1e-9)
    # Every point and segment end point on one plane through the cube centre, whose normal is
    # --plane-tilt from the direction to view 1 (view 1 at the origin of the frame, looking at the
    # cube centre 20 m along its optical axis).
    path = tmp_path / "planar.yml"
    assert make_scene(path, "--points", 8, "--lines", 8, "--planar", "--plane-tilt", 20).returncode == 0
    s = read_scene(path)
    X = np.vstack([rows(s["points3d"], 3), rows(s["lines3d"], 6).reshape(-1, 3)])
    centre = X.mean(axis=0)
    _, sv, vt = np.linalg.svd(X - centre)
    assert sv[2] < 1e-9 * sv[0]
    normal, cube_centre = vt[2], np.array([0.0, 0.0, 20.0])
    assert abs(normal @ (cube_centre - centre)) < 1e-9 * sv[0]
    to_view1 = -cube_centre / np.linalg.norm(cube_centre)
    assert np.degrees(np.arccos(abs(normal @ to_view1))) == pytest.approx(20, abs=1e-6)


@pytest.mark.parametrize("args, named", [
    (["--points", "-1"], "--points"),
    (["--points", "2.5"], "--points"),
    (["--lines", "many"], "--lines"),
    (["--motion", "medium"], "--motion"),
    (["--noise", "-0.5"], "--noise"),
    (["--outliers", "1"], "--outliers"),
    (["--seed", "1e20"], "--seed"),
    (["--frobnicate", "1"], "--frobnicate"),
    (["--points"], "--points"),
    (["--baseline12", "0"], "--baseline12"),
    (["--baseline12-fraction", "-0.01"], "--baseline12-fraction"),
    (["--baseline12", "0.2", "--baseline12-fraction", "0.01"], "--baseline12"),
    (["--plane-tilt", "20"], "--plane-tilt"),
    (["--planar", "--plane-tilt", "90"], "--plane-tilt"),
])
def test_bad_arguments_fail_naming_the_argument(tmp_path, args, named):
    path = tmp_path / "scene.yml"
    result = make_scene(path, *args)
    assert result.returncode != 0
    assert named in result.stderr
    assert not path.exists()


def test_output_is_required_and_must_be_yaml_or_json(tmp_path):
    result = subprocess.run([str(TOOL), "--points", "3"], capture_output=True, text=True, timeout=60)
    assert result.returncode != 0 and "--output" in result.stderr
    result = make_scene(tmp_path / "scene.txt")
    assert result.returncode != 0 and "--output" in result.stderr
