"""Keys the tools do not know are errors: a misspelt key (point1 for points1) would otherwise read as
an absent one and give a wrong answer or a message about something else. Each tool that reads a
key/value file (tripose_estimate: the problem file; tripose_stereo_chessboard: the image list;
tripose_tracking_study: the track file of --start) names the unknown key and the nearest known one,
exits with status 1 and writes nothing; --allow-unknown-keys reads a file that carries other data.
tripose_track_vgg reads the VGG sequences' own text files, which have no keys.
"""
import subprocess

import numpy as np
import pytest

from tripose_tools import (REPO, build_tool, estimate, files_in, make_scene, make_stereo_scene, read_matrices,
                           write_problem)

PROBLEM_KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]
TRUTH_KEYS = ["R_gt", "t_gt", "points3d", "lines3d", "point_inliers", "line_inliers"]
STEREO_KEYS = PROBLEM_KEYS + ["K4", "points4", "lines4"]
STEREO_TRUTH_KEYS = TRUTH_KEYS + ["point_visibility", "line_visibility"]


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    return make_scene(tmp_path_factory.mktemp("scene"), points=4, lines=4, seed=3)


def expect_bad_input(tmp_path, problem, message, *extra):
    before = files_in(tmp_path)
    proc, out = estimate(tmp_path, problem, *extra)
    assert proc.returncode == 1, (proc.returncode, proc.stdout, proc.stderr)
    assert message in proc.stderr, proc.stderr
    assert not out.exists()
    assert files_in(tmp_path) == before


def renamed(values, old, new):
    return {new if k == old else k: v for k, v in values.items()}


@pytest.mark.parametrize("extension", [".yml", ".json"])
@pytest.mark.parametrize("key,typo", [("points1", "point1"), ("lines3", "line3"), ("K2", "k2"), ("R12", "R21"),
                                      ("t12", "t_12")])
def test_misspelt_key_is_named_with_the_nearest_known_key(tmp_path, scene, extension, key, typo):
    problem = tmp_path / f"problem{extension}"
    write_problem(problem, renamed(read_matrices(scene, PROBLEM_KEYS), key, typo))
    expect_bad_input(tmp_path, problem, f"unknown key '{typo}' in {problem} (did you mean '{key}'?)")


@pytest.mark.parametrize("extension", [".yml", ".json"])
def test_misspelt_matrix_field_is_named(tmp_path, scene, extension):
    # FileStorage writes rows, cols, dt and data; a misspelt one would read as missing.
    problem = tmp_path / f"problem{extension}"
    write_problem(problem, read_matrices(scene, PROBLEM_KEYS))
    text = problem.read_text()
    field = '"rows"' if extension == ".json" else "rows:"
    assert field in text
    problem.write_text(text.replace(field, field.replace("rows", "row"), 1))
    expect_bad_input(tmp_path, problem, f"unknown key 'row' of 'K1' in {problem} (did you mean 'rows'?)")


@pytest.mark.parametrize("extension", [".yml", ".json"])
def test_key_far_from_every_known_key_lists_them(tmp_path, scene, extension):
    problem = tmp_path / f"problem{extension}"
    write_problem(problem, {**read_matrices(scene, PROBLEM_KEYS), "camera_name": "left"})
    expect_bad_input(tmp_path, problem, f"unknown key 'camera_name' in {problem} (known keys: K, K1,")
    proc, _ = estimate(tmp_path, problem)
    assert "--allow-unknown-keys" in proc.stderr.splitlines()[0], proc.stderr


@pytest.mark.parametrize("extension", [".yml", ".json"])
def test_allow_unknown_keys_reads_a_file_with_other_data(tmp_path, scene, extension):
    values = read_matrices(scene, PROBLEM_KEYS)
    plain = tmp_path / f"plain{extension}"
    write_problem(plain, values)
    extended = tmp_path / f"extended{extension}"
    write_problem(extended, {**values, "camera_name": "left", "R": np.eye(3), "point1": np.zeros((2, 2))})
    proc, reference = estimate(tmp_path, plain, name="reference.yml")
    assert proc.returncode == 0, proc.stderr
    proc, out = estimate(tmp_path, extended, "--allow-unknown-keys")
    assert proc.returncode == 0, proc.stderr
    # The other keys are skipped, not read: the same pose as from the plain file.
    expected, result = read_matrices(reference, ["R", "t"]), read_matrices(out, ["R", "t"])
    for key in ("R", "t"):
        assert np.array_equal(result[key], expected[key]), key


def dist(count):
    return np.array([[0.01, -0.002, 0.0005, -0.0003, 0.0001]] * count)


@pytest.mark.parametrize("extension", [".yml", ".json"])
def test_every_key_of_a_problem_and_a_scene_is_known(tmp_path, extension):
    # The allow-list is complete: every key the reader reads (per-view and shared K and dist, the
    # rig's fourth view) and the ground truth tripose_make_scene writes beside them pass without
    # --allow-unknown-keys.
    three = make_scene(tmp_path, points=4, lines=4, seed=5)
    rig = make_stereo_scene(tmp_path, 4, 4, seed=5, missing=0.3)
    for source in (three, rig):
        proc, _ = estimate(tmp_path, source, name="as_written.yml")
        assert proc.returncode == 0, (source, proc.stderr)
    cases = {
        "per_view": (three, PROBLEM_KEYS + TRUTH_KEYS, lambda v: v.update({f"dist{i}": dist(1) for i in (1, 2, 3)})),
        "shared": (three, PROBLEM_KEYS + TRUTH_KEYS, lambda v: v.update(K=v.pop("K1"), dist=dist(1))),
        "rig_per_view": (rig, STEREO_KEYS + STEREO_TRUTH_KEYS,
                         lambda v: v.update({f"dist{i}": dist(1) for i in (1, 2, 3, 4)})),
        "rig_shared": (rig, STEREO_KEYS + STEREO_TRUTH_KEYS, lambda v: v.update(K=v.pop("K1"), dist=dist(1))),
    }
    for name, (source, keys, change) in cases.items():
        values = read_matrices(source, keys)
        assert set(values) == set(keys), (name, set(keys) - set(values))
        change(values)
        if "K" in values:
            for k in ("K2", "K3", "K4"):
                values.pop(k, None)
        problem = tmp_path / f"{name}{extension}"
        write_problem(problem, values)
        proc, out = estimate(tmp_path, problem, name=f"{name}_result.yml")
        assert proc.returncode == 0, (name, proc.stderr)
        assert "R" in read_matrices(out, ["R"]), (name, out.read_text())


# tripose_stereo_chessboard's image list: OpenCV's stereo_calib.xml, or the same list in YAML or JSON.
STEREO_DATA = REPO / "test" / "data" / "stereo"


def image_names():
    text = (STEREO_DATA / "stereo_calib.xml").read_text()
    return [line.strip().strip('"') for line in text.splitlines() if line.strip().startswith('"')]


def list_text(extension, key, extra=False):
    names = image_names()
    assert len(names) == 26
    if extension == ".xml":
        body = "\n".join(f'"{n}"' for n in names)
        other = "<comment>calibration set</comment>\n" if extra else ""
        return f'<?xml version="1.0"?>\n<opencv_storage>\n<{key}>\n{body}</{key}>\n{other}</opencv_storage>\n'
    if extension == ".yml":
        other = 'comment: "calibration set"\n' if extra else ""
        return "%YAML:1.0\n---\n" + f"{key}:\n" + "".join(f'   - "{n}"\n' for n in names) + other
    other = ', "comment": "calibration set"' if extra else ""
    return '{\n"' + key + '": [' + ", ".join(f'"{n}"' for n in names) + "]" + other + "\n}\n"


def chessboard(data, list_name, *extra, output=None):
    args = [str(build_tool("tripose_stereo_chessboard")), "--data", str(data), "--list", list_name, "--pairs", "0,4"]
    if output:
        args += ["--output", str(output)]
    return subprocess.run(args + list(extra), capture_output=True, text=True, timeout=120)


def data_folder(tmp_path, list_name, text):
    """A copy of the stereo data set's folder (the images linked) with the given list file."""
    data = tmp_path / "stereo"
    data.mkdir()
    for image in STEREO_DATA.glob("*.jpg"):
        (data / image.name).symlink_to(image)
    (data / list_name).write_text(text)
    return data


@pytest.mark.parametrize("extension", [".xml", ".yml", ".json"])
def test_chessboard_list_with_a_misspelt_key_is_named(tmp_path, extension):
    name = f"list{extension}"
    data = data_folder(tmp_path, name, list_text(extension, "imagelists"))
    output = tmp_path / "result.yml"
    proc = chessboard(data, name, output=output)
    assert proc.returncode == 1, (proc.returncode, proc.stderr)
    assert f"unknown key 'imagelists' in {data / name} (did you mean 'imagelist'?)" in proc.stderr, proc.stderr
    assert not output.exists()


@pytest.mark.parametrize("extension", [".xml", ".yml", ".json"])
def test_chessboard_list_with_other_data(tmp_path, extension):
    # The list as written is read; another key is an error, unless --allow-unknown-keys.
    name = f"list{extension}"
    data = data_folder(tmp_path, name, list_text(extension, "imagelist", extra=True))
    proc = chessboard(data, name)
    assert proc.returncode == 1, (proc.returncode, proc.stderr)
    assert f"unknown key 'comment' in {data / name}" in proc.stderr, proc.stderr
    output = tmp_path / "result.yml"
    proc = chessboard(data, name, "--allow-unknown-keys", output=output)
    assert proc.returncode == 0, proc.stderr
    assert output.exists()
    (data / name).write_text(list_text(extension, "imagelist"))
    proc = chessboard(data, name)
    assert proc.returncode == 0, proc.stderr


def run_tracking_study(track_file, *extra):
    study = build_tool("tripose_tracking_study", folder="test/evaluation")
    return subprocess.run([str(study), "--data", str(REPO / "test" / "data" / "vgg" / "Merton-College-I"),
                           "--adjust", "--start", str(track_file), *extra], capture_output=True, text=True)


def test_tracking_study_start_file_key_is_checked(tmp_path):
    # The --start file is tripose_track_vgg's output; "pose" for "poses" is named with the nearest key.
    track = tmp_path / "track.yml"
    write_problem(track, {"pose": np.zeros((3, 12)), "window": np.array([[5.0]])})
    proc = run_tracking_study(track)
    assert proc.returncode == 1, (proc.stdout, proc.stderr)
    assert f"unknown key 'pose' in {track} (did you mean 'poses'?)" in proc.stderr, proc.stderr
    # Opted out, the key check passes and the file is then read for what it lacks: the poses.
    proc = run_tracking_study(track, "--allow-unknown-keys")
    assert proc.returncode == 1, (proc.stdout, proc.stderr)
    assert "unknown key" not in proc.stderr and "expected poses" in proc.stderr, proc.stderr
