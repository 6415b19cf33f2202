"""End-to-end tests of the command-line estimator `tripose_estimate` on problem files.

Scenes come from the project's own generator through `tripose_make_scene`; files are read and
written with OpenCV's FileStorage, the format the tools speak.
"""
import gzip
import os
import subprocess
from pathlib import Path

import cv2
import numpy as np
import pytest

from tripose_tools import (all_of, build_tool, edited, estimate, expect_rejected, files_in, make_scene,
                           read_matrices, rotation_error, setter, write_problem)

ESTIMATE = build_tool("tripose_estimate")

PROBLEM_KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]


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
    result = read_matrices(out, ["R", "point_inliers", "line_inliers"])
    assert rotation_error(result["R"], truth["R_gt"]) < np.deg2rad(1.0)
    assert result["point_inliers"].size == 60 and result["line_inliers"].size == 30
    agree = np.mean(np.concatenate([result["point_inliers"].ravel() == truth["point_inliers"].ravel(),
                                    result["line_inliers"].ravel() == truth["line_inliers"].ravel()]))
    assert agree >= 0.95


def test_linear_refine_option_refines_the_linear_estimate(tmp_path):
    # 1 px noise, few features: refinement over the three views lowers the error of the linear
    # estimate in most scenes, and "--refine 0" is the plain linear estimate.
    linear, refined = [], []
    for seed in range(8):
        scene = make_scene(tmp_path, points=5, lines=5, seed=seed, noise=1.0)
        truth = read_matrices(scene, ["R_gt"])["R_gt"]
        for flag, errors in (("0", linear), ("1", refined)):
            proc, out = estimate(tmp_path, scene, "--method", "linear", "--refine", flag, name=f"r{seed}_{flag}.yml")
            assert proc.returncode == 0, proc.stderr
            errors.append(rotation_error(read_matrices(out, ["R"])["R"], truth))
    assert linear != refined
    assert np.median(refined) < np.median(linear)


def break_problem(tmp_path, scene, change):
    values = read_matrices(scene, PROBLEM_KEYS)
    change(values)
    problem = tmp_path / "broken.yml"
    write_problem(problem, values)
    return problem


def shared_K(v):
    """One K for the three views instead of K1..K3."""
    v["K"] = v.pop("K1")
    v.pop("K2")
    v.pop("K3")


def keep_features(points, lines):
    def change(v):
        for i in (1, 2, 3):
            v[f"points{i}"] = v[f"points{i}"][:points]
            v[f"lines{i}"] = v[f"lines{i}"][:lines]
    return change


def drop_features(v):
    for i in (1, 2, 3):
        v.pop(f"points{i}")
        v.pop(f"lines{i}")


def zero_length_segment(v):
    m = v["lines2"].copy()
    m[1, 2:] = m[1, :2]
    v["lines2"] = m


# The bad-input catalogue of modules/tripose/test/test_estimate_pose_bad_input.cpp, through the
# problem file: each kind maps to the change of a valid 3-point, 3-line problem (with K1..K3) and to
# what stderr must name (key 'X' for a problem key). The file reader rejects what the file can say
# wrongly (shape, channels, NaN/Inf, missing keys); the solver rejects the rest, and the tool turns
# the solver's argument (cameraMatrix[1], distCoeffs, ...) into the key (K2, dist, ...).
# Kinds the tool cannot express:
#   - wrong element types (integer points, R12, K): the reader converts every matrix to CV_64F;
#   - homogeneous lines (Mx3), hence a line with a = b = 0 and homogeneous lines with distortion:
#     the file carries Mx4 segments only (an Mx3 lines key is rejected as the wrong width);
#   - a non-vector Rs output, refinement parameters and the initial pose of refinePoseLinePoint:
#     the tool has no such outputs or entry point (--refine only switches RANSAC's final refinement).
CATALOGUE = {
    # shapes and channels
    "points_with_wrong_width": (setter("points2", np.zeros((3, 3))), "key 'points2'"),
    "points_with_three_channels": (setter("points3", np.zeros((3, 1, 3))), "key 'points3'"),
    "lines_with_wrong_width": (setter("lines1", np.ones((3, 5))), "key 'lines1'"),
    "lines_with_two_channels": (setter("lines2", np.ones((3, 2, 2))), "key 'lines2'"),
    "segments_mixed_with_homogeneous_lines": (setter("lines3", lambda v: v["lines3"][:, :3].copy()), "key 'lines3'"),
    # counts
    "point_counts_differ": (setter("points3", lambda v: v["points3"][:2]), "key 'points3'"),
    "points_missing_in_one_view": (lambda v: v.pop("points2"), "key 'points2'"),
    "line_counts_differ": (setter("lines2", lambda v: v["lines2"][:1]), "key 'lines2'"),
    "fewer_than_four_features": (keep_features(1, 2), "at least 4 features"),
    "nothing_at_all": (drop_features, "at least 4 features"),
    # values of the observations
    "nan_in_points": (edited("points2", 1, 0, np.nan), "key 'points2'"),
    "inf_in_lines": (edited("lines3", 0, 3, np.inf), "key 'lines3'"),
    "zero_length_segment": (zero_length_segment, "key 'lines2'"),
    # pose of view 2
    "R12_not_a_rotation": (setter("R12", lambda v: 1.1 * v["R12"]), "key 'R12'"),
    "R12_reflection": (setter("R12", lambda v: -v["R12"]), "key 'R12'"),
    "R12_wrong_shape": (setter("R12", np.eye(2)), "key 'R12'"),
    "nan_in_R12": (edited("R12", 0, 1, np.nan), "key 'R12'"),
    "R12_missing": (lambda v: v.pop("R12"), "key 'R12'"),
    "t12_zero": (setter("t12", np.zeros((3, 1))), "key 't12'"),
    "t12_wrong_size": (setter("t12", np.ones((4, 1))), "key 't12'"),
    "inf_in_t12": (edited("t12", 2, 0, -np.inf), "key 't12'"),
    "t12_missing": (lambda v: v.pop("t12"), "key 't12'"),
    # intrinsics
    "camera_matrix_negative_focal": (all_of(shared_K, edited("K", 0, 0, -800.0)), "key 'K'"),
    "camera_matrix_zero_focal": (edited("K1", 1, 1, 0.0), "key 'K1'"),
    "camera_matrix_singular": (edited("K3", 2, 2, 0.0), "key 'K3'"),
    "camera_matrix_not_upper_triangular": (edited("K2", 1, 0, 5.0), "key 'K2'"),
    "camera_matrix_wrong_shape": (setter("K1", np.eye(3, 4)), "key 'K1'"),
    "nan_in_camera_matrix": (edited("K2", 0, 2, np.nan), "key 'K2'"),
    "camera_matrix_missing": (lambda v: [v.pop(k) for k in ("K1", "K2", "K3")], "key 'K'"),
    "two_camera_matrices": (lambda v: v.pop("K3"), "key 'K3'"),
    "one_of_three_camera_matrices_bad": (edited("K2", 0, 0, -1.0), "key 'K2'"),
    "K_together_with_K1_K3": (setter("K", lambda v: v["K1"]), "key 'K'"),
    # distortion
    "distortion_with_wrong_count": (setter("dist", np.array([[0.1, 0, 0, 0, 0, 0]])), "key 'dist'"),
    "distortion_as_matrix": (setter("dist", np.zeros((2, 4))), "key 'dist'"),
    "nan_in_distortion": (setter("dist", np.array([[0.1, np.nan, 0, 0, 0]])), "key 'dist'"),
    "two_distortion_vectors": (all_of(setter("dist1", np.full((1, 5), 0.01)), setter("dist2", np.full((1, 5), 0.01))),
                               "key 'dist3'"),
    "one_of_three_distortion_vectors_bad": (all_of(*[setter(f"dist{i}", np.full((1, 5), 0.01)) for i in (1, 3)],
                                                   setter("dist2", np.full((1, 6), 0.01))), "key 'dist2'"),
}


@pytest.fixture(scope="module")
def valid_scene(tmp_path_factory):
    return make_scene(tmp_path_factory.mktemp("scene"), points=3, lines=3, seed=1)


def test_catalogue_problem_is_valid(tmp_path, valid_scene):
    # Every kind below breaks exactly one thing in this problem, which both methods accept.
    problem = break_problem(tmp_path, valid_scene, lambda v: None)
    for method in ("linear", "ransac"):
        proc, out = estimate(tmp_path, problem, "--method", method, name=f"{method}.yml")
        assert proc.returncode == 0, proc.stderr
        assert out.exists()


@pytest.mark.parametrize("kind", sorted(CATALOGUE))
@pytest.mark.parametrize("method", ["linear", "ransac"])
def test_bad_input_is_named_and_nothing_is_written(tmp_path, valid_scene, kind, method):
    change, names = CATALOGUE[kind]
    problem = break_problem(tmp_path, valid_scene, change)
    expect_rejected(tmp_path, problem, names, "--method", method)


@pytest.mark.parametrize("args,name", [
    (["--method", "magic"], "argument --method"),
    (["--threshold", "-1", "--method", "ransac"], "argument --threshold"),
    (["--threshold", "0", "--method", "ransac"], "argument --threshold"),
    (["--threshold", "nan", "--method", "ransac"], "argument --threshold"),
    (["--threshold", "abc", "--method", "ransac"], "argument --threshold"),
    (["--confidence", "0", "--method", "ransac"], "argument --confidence"),
    (["--confidence", "1", "--method", "ransac"], "argument --confidence"),
    (["--max-iterations", "0", "--method", "ransac"], "argument --max-iterations"),
    (["--max-iterations", "2.5", "--method", "ransac"], "argument --max-iterations"),
    (["--refine", "2", "--method", "ransac"], "argument --refine"),
    (["--loss", "tukey", "--method", "ransac"], "argument --loss"),
    (["--loss-scale", "0", "--method", "ransac"], "argument --loss-scale"),
    (["--loss-scale", "-2", "--method", "ransac"], "argument --loss-scale"),
    (["--min-inliers", "-1", "--method", "ransac"], "argument --min-inliers"),
    (["--min-inliers", "1.5", "--method", "ransac"], "argument --min-inliers"),
])
def test_bad_arguments_are_named(tmp_path, valid_scene, args, name):
    expect_rejected(tmp_path, valid_scene, name, *args)


def test_output_that_cannot_be_written(tmp_path, valid_scene):
    proc, _ = estimate(tmp_path, valid_scene, name="no_folder/result.yml")
    assert proc.returncode == 1 and "--output" in proc.stderr and "cannot be written" in proc.stderr


def test_loss_reaches_the_refinement(tmp_path):
    # Noisy features: a Cauchy loss weighs the residuals otherwise than least squares, so the refined
    # poses differ; the same loss named twice gives the same pose.
    scene = make_scene(tmp_path, points=30, lines=10, seed=3, noise=1.0)
    poses = {}
    for name, extra in (("squared", []), ("cauchy", ["--loss", "cauchy", "--loss-scale", "0.5"]),
                        ("cauchy_again", ["--loss", "cauchy", "--loss-scale", "0.5"])):
        proc, out = estimate(tmp_path, scene, "--method", "ransac", *extra, name=f"{name}.yml")
        assert proc.returncode == 0, proc.stderr
        poses[name] = read_matrices(out, ["R"])["R"]
    assert np.abs(poses["squared"] - poses["cauchy"]).max() > 1e-6
    assert np.abs(poses["cauchy"] - poses["cauchy_again"]).max() == 0


def test_unparsable_file_is_rejected(tmp_path):
    problem = tmp_path / "garbage.yml"
    problem.write_text("%YAML:1.0\nK1: [this is not\n")
    expect_rejected(tmp_path, problem, "cannot parse")
    proc, _ = estimate(tmp_path, problem)
    assert "line 3, column 1" in proc.stderr, proc.stderr  # where the parser stopped


def test_matrix_header_larger_than_its_data_is_rejected(tmp_path):
    # Regression (fuzz_problem_reader): a corrupt header could ask for gigabytes; the header is
    # compared with the data before anything is allocated.
    problem = tmp_path / "huge.yml"
    problem.write_text("%YAML:1.0\n---\nK1: !!opencv-matrix\n   rows: 100000\n   cols: 100000\n"
                       "   dt: d\n   data: [ 1. ]\n")
    expect_rejected(tmp_path, problem, "key 'K1'")
    proc, _ = estimate(tmp_path, problem)
    assert "header declares 10000000000 elements" in proc.stderr, proc.stderr


@pytest.mark.parametrize("text", ["%YAML:1.0\n---\n- 1\n- 2\n", "%YAML:1.0\n---\n", "",
                                  "%YAML:1.0\n---\nK: 1\n---\n- 2\n"])
def test_problem_that_is_not_a_map_is_rejected(tmp_path, text):
    # Also every later document: FileStorage's append mode writes several, read as one map.
    problem = tmp_path / "not_a_map.yml"
    problem.write_text(text)
    expect_rejected(tmp_path, problem, "map of keys")


def reader_regression(name):
    """The problem text of a fuzz_problem_reader regression input."""
    regression = Path(__file__).resolve().parents[1] / "fuzz" / "regressions" / "fuzz_problem_reader"
    return (regression / name).read_bytes()


def test_key_repeated_inside_a_matrix_is_a_parse_error(tmp_path):
    # Regression (fuzz_problem_reader): the corrupt file once made OpenCV's parser throw
    # std::length_error; a key given twice is named with its lines.
    problem = tmp_path / "corrupt.yml"
    problem.write_bytes(reader_regression("opencv_parser_length_error_on_repeated_key"))
    expect_rejected(tmp_path, problem, "cannot parse")
    problem.write_text("%YAML:1.0\nK: !!opencv-matrix\n  rows: 3\n  cols: 3\n  dt: d\n  dt: d\n")
    expect_rejected(tmp_path, problem, "key 'dt' of 'K' is given twice (lines 5 and 6)")


# Texts on which OpenCV's own YAML parser (FileStorage, 4.6 and 5.0) never returns, as fuzzing found
# them; the tool reads problems with libyaml, which stops on every text.
HANGING_OPENCV = {
    "dashes_after_marker": ("%YAML:1.0\n---K1: 0\n----\n", "line 4, column 1"),
    "dashes_after_marker_in_a_key": ("%YAML:1.0\n---,K1: 0\n----matrix\n", "line 4, column 1"),
    "regression_dashes_after_marker": (reader_regression("opencv_parser_hang_on_dashes_after_marker"),
                                       "cannot parse"),
    "regression_indented_scalar": (reader_regression("opencv_parser_hang_on_indented_scalar"), "map of keys"),
}


@pytest.mark.parametrize("kind", sorted(HANGING_OPENCV))
def test_text_that_hangs_the_opencv_parser_is_rejected(tmp_path, kind):
    text, names = HANGING_OPENCV[kind]
    problem = tmp_path / "hang.yml"
    problem.write_bytes(text.encode() if isinstance(text, str) else text)
    before = files_in(tmp_path)
    out = tmp_path / "result.yml"
    proc = subprocess.run([str(ESTIMATE), "--input", str(problem), "--output", str(out)],
                          capture_output=True, text=True, timeout=10)
    assert proc.returncode != 0, proc.stdout
    assert names in proc.stderr, proc.stderr
    assert not out.exists() and files_in(tmp_path) == before


# Texts on which libyaml's own work would grow with the square of their size (deep nesting, %TAG
# directives): refused before parsing or at the first level too deep, so each takes a moment.
SLOW_FOR_LIBYAML = {
    "deep_flow_nesting": ("[" * 2_000_000, "nested deeper than 32 levels"),
    "deep_block_nesting": ("- " * 1_000_000, "nested deeper than 32 levels"),
    "tag_directives": ("%YAML:1.0\n" + "".join(f"%TAG !t{i}! tag:x{i}:\n" for i in range(100_000)) + "---\nK: 1\n",
                       "line 2: directives"),
}


@pytest.mark.parametrize("kind", sorted(SLOW_FOR_LIBYAML))
def test_text_that_slows_the_parser_is_refused_at_once(tmp_path, kind):
    text, names = SLOW_FOR_LIBYAML[kind]
    problem = tmp_path / "slow.yml"
    problem.write_text(text)
    out = tmp_path / "result.yml"
    proc = subprocess.run([str(ESTIMATE), "--input", str(problem), "--output", str(out)],
                          capture_output=True, text=True, timeout=10)
    assert proc.returncode != 0, proc.stdout
    assert names in proc.stderr, proc.stderr
    assert not out.exists()


def test_later_document_that_is_not_a_map_is_a_parse_error(tmp_path):
    # Regression (fuzz_problem_reader): a corrupt text of several documents, the second not a map.
    problem = tmp_path / "documents.yml"
    problem.write_bytes(reader_regression("second_document_not_a_map"))
    expect_rejected(tmp_path, problem, "cannot parse")


MATRIX = "K1: !!opencv-matrix\n  rows: 1\n  cols: 1\n  dt: {dt}\n  data: {data}\n"


@pytest.mark.parametrize("text,names", [
    ("%YAML:1.0\nK1: &k !!opencv-matrix\n  rows: 1\n  cols: 1\n  dt: d\n  data: [ 1 ]\nK2: *k\n",
     "line 7: aliases"),
    ('<?xml version="1.0"?>\n<opencv_storage>\n</opencv_storage>\n', "XML"),
    ("%YAML:2.0\n", "unsupported YAML version"),
    ("%YAML:1.0\nK1: 1\nK1: 2\n", "key 'K1' is given twice (lines 2 and 3)"),
    ("%YAML:1.0\n" + MATRIX.format(dt="d", data='[ "1" ]'), "key 'K1': malformed matrix: data value 1 is not a number"),
    ("%YAML:1.0\n" + MATRIX.format(dt="d", data="[ [ 1 ] ]"), "key 'K1': malformed matrix: data value 1 is not a number"),
    ("%YAML:1.0\n" + MATRIX.format(dt="x", data="[ 1 ]"), "key 'K1': malformed matrix header: dt"),
    ("%YAML:1.0\n" + MATRIX.format(dt="d", data="[ 1, 2 ]"), "key 'K1': malformed matrix: the header declares 1"),
    ("%YAML:1.0\n" + MATRIX.format(dt="f", data="[ 1e300 ]"), "key 'K1': contains NaN or Inf"),
    ("%YAML:1.0\nK1: [ 1, 2 ]\n", "key 'K1': expected an OpenCV matrix"),
])
def test_reader_names_what_is_wrong(tmp_path, text, names):
    problem = tmp_path / "problem.yml"
    problem.write_text(text)
    expect_rejected(tmp_path, problem, names)


def test_gzip_compressed_file_is_rejected(tmp_path, valid_scene):
    problem = tmp_path / "problem.yml.gz"
    problem.write_bytes(gzip.compress(valid_scene.read_bytes()))
    expect_rejected(tmp_path, problem, "gzip-compressed")


def test_format_is_read_from_the_text(tmp_path, valid_scene):
    # YAML with or without OpenCV's %YAML:1.0 line, and JSON, whatever the file is called: each
    # gives the result of the original file.
    proc, reference = estimate(tmp_path, valid_scene, name="reference.yml")
    assert proc.returncode == 0, proc.stderr
    expected = read_matrices(reference, ["R", "t"])
    as_json = tmp_path / "problem.json"
    write_problem(as_json, read_matrices(valid_scene, PROBLEM_KEYS))
    yaml_text = valid_scene.read_text()
    assert yaml_text.startswith("%YAML:1.0\n")
    for name, text in [("plain.yml", yaml_text[len("%YAML:1.0\n"):]), ("json.yml", as_json.read_text()),
                       ("yaml.json", yaml_text)]:
        problem = tmp_path / name
        problem.write_text(text)
        proc, out = estimate(tmp_path, problem, name=f"result_{name}.yml")
        assert proc.returncode == 0, (name, proc.stderr)
        result = read_matrices(out, ["R", "t"])
        for key in ("R", "t"):
            assert np.array_equal(result[key], expected[key]), (name, key)
