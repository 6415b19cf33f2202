"""End-to-end tests of `tripose_images` (three images to a pose) on the bundled Merton College I
images, and of its rejection of bad input: exit status 1, a message naming the file, key or
argument, and nothing written.

The calibration (test/data/images/merton_college_i_calib.yml) was written by
`tripose_images_report --data test/data/vgg/Merton-College-I --calib-output ...` from the sequence's
cameras; one test derives it again here, independently, from the .P files."""
import re
import subprocess

import cv2
import numpy as np
import pytest

from tripose_tools import (MERTON, MERTON_CALIB, REPO, build_tool, enlarged_merton, files_in, merton_greys_in_bits,
                           offsets_to_nearest, read_matrices, rotation_error, run_with_peak_memory,
                           write_inverted_pose_calibration, write_nan_tiff, write_problem, write_turned_jpeg)

CALIB = MERTON_CALIB
MODEL_HOUSE = REPO / "test" / "data" / "vgg" / "Model-House"
IMAGES = [MERTON / f"00{k}.jpg" for k in (1, 2, 3)]
PROBLEM_KEYS = ["K1", "K2", "K3", "R12", "t12", "points1", "points2", "points3", "lines1", "lines2", "lines3"]


def run_images(tmp_path, *options, calib=CALIB, images=IMAGES, name="result.yml"):
    out = tmp_path / name
    proc = subprocess.run([str(build_tool("tripose_images")), "--calib", str(calib), "--images", *map(str, images),
                           "--output", str(out), *map(str, options)], capture_output=True, text=True, timeout=300)
    return proc, out


def truth():
    values = read_matrices(CALIB, ["R_gt", "t_gt"])
    return values["R_gt"], values["t_gt"].ravel()


@pytest.fixture(scope="module")
def merton_result(tmp_path_factory):
    tmp_path = tmp_path_factory.mktemp("merton")
    proc, out = run_images(tmp_path, "--overlay", tmp_path / "overlay.png", "--matches", tmp_path / "matches.png")
    assert proc.returncode == 0, proc.stderr
    assert "warning" not in proc.stderr  # the calibration agrees with the images
    return tmp_path, out


def test_calibration_is_the_sequence_cameras():
    # K from the RQ decomposition of each P, poses relative to the first camera (view 1 = world).
    Ks, Rs, ts = [], [], []
    for k in (1, 2, 3):
        K, R, centre = cv2.decomposeProjectionMatrix(np.loadtxt(MERTON / f"00{k}.P"))[:3]
        signs = np.diag(np.sign(np.diag(K)))
        K, R = K @ signs / K[2, 2], signs @ R
        if np.linalg.det(R) < 0:  # P is defined up to scale, the sign included
            R = -R
        Ks.append(K)
        Rs.append(R)
        ts.append(-R @ (centre[:3, 0] / centre[3, 0]))
    values = read_matrices(CALIB, ["K1", "K2", "K3", "R12", "t12", "R_gt", "t_gt"])
    for k in range(3):
        np.testing.assert_allclose(values[f"K{k + 1}"], Ks[k], atol=1e-6)
    for key, b in (("R12", 1), ("R_gt", 2)):
        R = Rs[b] @ Rs[0].T
        np.testing.assert_allclose(values[key], R, atol=1e-9)
        np.testing.assert_allclose(values["t12" if b == 1 else "t_gt"].ravel(), ts[b] - R @ ts[0], atol=1e-9)


def test_merton_triplet_pose(merton_result):
    # doc/studies/real_images.md has the figures of this triplet; the bounds leave room for other OpenCV
    # builds' detectors, not for a wrong pose.
    _, out = merton_result
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    assert fs.getNode("num_solutions").real() == 1
    tracks, triplets = int(fs.getNode("num_point_tracks").real()), int(fs.getNode("num_segment_triplets").real())
    inliers = int(fs.getNode("num_inliers").real())
    fs.release()
    assert tracks >= 200 and triplets >= 30
    assert inliers >= 0.7 * (tracks + triplets)
    R_gt, t_gt = truth()
    result = read_matrices(out, ["R", "t", "point_inliers", "line_inliers"])
    assert np.degrees(rotation_error(result["R"], R_gt)) < 0.2
    assert np.linalg.norm(result["t"].ravel() - t_gt) < 0.02 * np.linalg.norm(t_gt)
    assert result["point_inliers"].size == tracks and result["line_inliers"].size == triplets


def test_result_is_a_problem_tripose_estimate_solves_again(merton_result, tmp_path):
    _, out = merton_result
    problem = read_matrices(out, PROBLEM_KEYS)
    assert all(problem[k].shape[0] == problem["points1"].shape[0] for k in ("points2", "points3"))
    assert all(problem[k].shape[0] == problem["lines1"].shape[0] for k in ("lines2", "lines3"))
    again = tmp_path / "again.yml"
    # tripose_images refines under the Cauchy loss of samples/common/image_estimation.hpp.
    proc = subprocess.run([str(build_tool("tripose_estimate")), "--input", str(out), "--output", str(again), "--allow-unknown-keys",
                           "--method", "ransac", "--loss", "cauchy", "--loss-scale", "0.5"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    first, second = read_matrices(out, ["R"])["R"], read_matrices(again, ["R"])["R"]
    assert np.degrees(rotation_error(first, second)) < 1e-3


def test_overlay_is_the_third_image_with_drawings(merton_result):
    tmp_path, _ = merton_result
    overlay = cv2.imread(str(tmp_path / "overlay.png"))
    third = cv2.imread(str(IMAGES[2]))
    assert overlay is not None and overlay.shape == third.shape
    # Drawn pixels differ strongly; two JPEG decoders may differ by a level or two everywhere.
    changed = (np.abs(overlay.astype(int) - third.astype(int)).max(axis=2) > 40).mean()
    assert 0.005 < changed < 0.5


def test_matches_picture_shows_the_three_views(merton_result):
    tmp_path, _ = merton_result
    picture = cv2.imread(str(tmp_path / "matches.png"))
    third = cv2.imread(str(IMAGES[2]))
    assert picture is not None
    # Three 1024x768 views side by side, scaled to 1800 px in all.
    assert picture.shape[1] == 1800 and abs(picture.shape[0] - round(768 * 1800 / 3072)) <= 1
    # The third panel is the third image (dimmed) with green inliers drawn on it.
    panel = picture[:, 1200:]
    green = (panel[..., 1] > 150) & (panel[..., 0] < 100) & (panel[..., 2] < 100)
    assert 0.002 < green.mean() < 0.5
    expected = cv2.resize(third, (600, picture.shape[0]), interpolation=cv2.INTER_AREA).astype(float) * 0.6 + 40
    undrawn = ~green & (panel[..., 2] < 150)
    assert np.median(np.abs(panel.astype(float) - expected)[undrawn]) < 4  # 0.2 measured; another view: 18


@pytest.mark.parametrize("kinds", ["points", "lines"])
def test_one_kind_of_feature(tmp_path, kinds):
    proc, out = run_images(tmp_path, "--features", kinds)
    assert proc.returncode == 0, proc.stderr
    values = read_matrices(out, PROBLEM_KEYS + ["R"])
    absent = "lines1" if kinds == "points" else "points1"
    assert absent not in values
    # Either kind alone still fixes the pose well below this bound (doc/studies/real_images.md).
    assert np.degrees(rotation_error(values["R"], truth()[0])) < 0.3


# Barrel distortion of a wide-angle lens: about 30 px at the corners of these 1024x768 images.
DISTORTION = np.array([-0.15, 0.05, 0.0, 0.0, 0.0])
BOUND_DEG = 0.1


def distorted_copy(path, K, out):
    """The image as a camera with K and DISTORTION would have taken it: each pixel samples the
    original (a pinhole image) at its undistorted position."""
    image = cv2.imread(str(path))
    h, w = image.shape[:2]
    grid = np.stack(np.meshgrid(np.arange(w, dtype=np.float64), np.arange(h, dtype=np.float64)), axis=-1)
    ideal = cv2.undistortPoints(grid.reshape(-1, 1, 2), K, DISTORTION, P=K).reshape(h, w, 2).astype(np.float32)
    cv2.imwrite(str(out), cv2.remap(image, ideal[..., 0], ideal[..., 1], cv2.INTER_CUBIC,
                                    borderMode=cv2.BORDER_REFLECT))
    return out


@pytest.fixture(scope="module")
def distorted(tmp_path_factory):
    """The Merton triplet distorted, a calibration with `dist`, and the same images undistorted by cv2."""
    tmp_path = tmp_path_factory.mktemp("distorted")
    values = read_matrices(CALIB, ["K1", "K2", "K3", "R12", "t12"])
    images, undistorted = [], []
    for k in range(3):
        K = values[f"K{k + 1}"]
        images.append(distorted_copy(IMAGES[k], K, tmp_path / f"distorted{k + 1}.png"))
        path = tmp_path / f"undistorted{k + 1}.png"
        cv2.imwrite(str(path), cv2.undistort(cv2.imread(str(images[-1])), K, DISTORTION))
        undistorted.append(path)
    calib = tmp_path / "calib_dist.yml"
    write_problem(calib, {**values, "dist": DISTORTION.reshape(1, 5)})
    return tmp_path, calib, images, undistorted


def pose_error_deg(out):
    values = read_matrices(out, ["R"])
    return np.degrees(rotation_error(values["R"], truth()[0])) if "R" in values else np.inf


def test_distortion_given_is_undistorting_first(distorted):
    tmp_path, calib, images, undistorted = distorted
    # dist given: the front end undistorts the feature positions.
    proc, with_dist = run_images(tmp_path, calib=calib, images=images, name="with_dist.yml")
    assert proc.returncode == 0, proc.stderr
    # The images undistorted first, no dist.
    proc, first = run_images(tmp_path, images=undistorted, name="undistorted_first.yml")
    assert proc.returncode == 0, proc.stderr
    a, b = read_matrices(with_dist, ["R", "points3"]), read_matrices(first, ["R", "points3"])
    # Both see the scene through the same pinhole camera: as many tracks within a tenth, and poses as
    # close to the truth as on the original images (0.021 and 0.038 deg against 0.018 deg,
    # doc/studies/real_images.md), below the bound that ignoring the distortion breaks (the test below).
    assert abs(len(a["points3"]) - len(b["points3"])) <= 0.1 * len(b["points3"])
    assert pose_error_deg(with_dist) < BOUND_DEG and pose_error_deg(first) < BOUND_DEG
    assert np.degrees(rotation_error(a["R"], b["R"])) < BOUND_DEG
    # The result is a problem in undistorted pixels: no dist in it.
    assert "dist" not in read_matrices(with_dist, ["dist"])


def test_distortion_given_with_reduced_detection(distorted):
    # Reduced to 640 px, the positions come back to the images' pixels before they are undistorted
    # with the images' K: measured 0.039 deg, and 0.195 deg with the two steps the other way round.
    tmp_path, calib, images, _ = distorted
    proc, out = run_images(tmp_path, "--max-image-size", 640, calib=calib, images=images, name="reduced_dist.yml")
    assert proc.returncode == 0, proc.stderr
    assert "reduced by 1.60" in proc.stdout
    assert pose_error_deg(out) < BOUND_DEG


def test_distortion_ignored_spoils_the_pose(distorted):
    # The same distorted images read as pinhole ones: what the test above guards against.
    tmp_path, _, images, _ = distorted
    proc, out = run_images(tmp_path, images=images, name="ignored.yml")
    assert proc.returncode == 0, proc.stderr
    assert pose_error_deg(out) > BOUND_DEG  # 0.22 deg measured


def test_exif_orientation_is_applied(tmp_path):
    # The third image stored turned, with the EXIF tag that turns it back: read without the tag, it
    # gave a pose 91 deg off (with 493 inliers); read as every OpenCV reader does by default, the pose.
    turned = write_turned_jpeg(cv2.imread(str(IMAGES[2])), tmp_path / "turned.jpg")
    assert cv2.imread(str(turned), cv2.IMREAD_UNCHANGED).shape[:2] == (1024, 768)
    proc, out = run_images(tmp_path, images=[IMAGES[0], IMAGES[1], turned])
    assert proc.returncode == 0, proc.stderr
    assert pose_error_deg(out) < BOUND_DEG  # measured 0.017 deg


@pytest.mark.parametrize("bits", [12, 16])
def test_images_of_more_than_eight_bits(tmp_path, bits):
    # A camera's 12 bits stored in 16-bit PNGs (15-4095 here), or 16 bits: stretched from their lowest
    # to their highest value, they give the features of the same greys in 8 bits, to the pixel. Before,
    # the front end refused them; keeping the top byte alone, as OpenCV's conversion to 8 bits does,
    # leaves 16 grey levels of 12 bits and no point track (measured with the Python sample: 0 tracks).
    deeper, eight = merton_greys_in_bits(tmp_path, bits)
    proc, out = run_images(tmp_path, images=deeper, name="deeper.yml")
    assert proc.returncode == 0, proc.stderr
    proc, reference = run_images(tmp_path, images=eight, name="eight.yml")
    assert proc.returncode == 0, proc.stderr
    keys = ["points1", "points3", "lines1", "lines3", "R"]
    values, expected = read_matrices(out, keys), read_matrices(reference, keys)
    for key in keys:
        np.testing.assert_array_equal(values[key], expected[key], err_msg=key)
    assert pose_error_deg(out) < BOUND_DEG  # measured 0.014 deg


@pytest.mark.parametrize("mistake", ["inverted pose", "images swapped"])
def test_calibration_that_contradicts_the_images_is_reported(tmp_path, mistake):
    # View 2's pose given as its inverse, or images 1 and 2 in the other order: the front end still
    # matches along the wrong epipolar lines and finds a pose 8 deg off (inverted, 23 inliers). The
    # descriptor matches of images 1-2, found without the calibration, show it: 2 % of them lie on
    # its epipolar lines, against 73-88 % on the VGG pairs with their own cameras.
    images = list(IMAGES)
    calib = CALIB
    if mistake == "inverted pose":
        calib = write_inverted_pose_calibration(tmp_path / "calib.yml")
    else:
        images[0], images[1] = images[1], images[0]
    proc, _ = run_images(tmp_path, calib=calib, images=images)
    assert proc.returncode == 0, proc.stderr
    assert "warning: images 1 and 2 do not follow R12, t12" in proc.stderr and str(calib) in proc.stderr
    assert "not its inverse" in proc.stderr


def test_unrelated_third_image_gives_no_pose(tmp_path):
    # A third image of blurred noise shares a handful of chance matches with the other two (2 point
    # tracks and 5 segment triplets here): no reliable pose, said so, exit status 3, nothing written.
    rng = np.random.default_rng(0)
    noise = tmp_path / "noise.png"
    cv2.imwrite(str(noise), cv2.GaussianBlur((rng.random((768, 1024)) * 255).astype(np.uint8), (0, 0), 2))
    proc, out = run_images(tmp_path, "--overlay", tmp_path / "overlay.png", images=[IMAGES[0], IMAGES[1], noise])
    assert proc.returncode == 3, proc.stdout + proc.stderr
    assert "no reliable pose" in proc.stderr and "fewer than the 15 a pose needs" in proc.stderr
    assert not out.exists() and not (tmp_path / "overlay.png").exists()


def test_triplet_that_too_few_features_support_gives_no_pose(tmp_path):
    # Model House frames 4, 6 and 9 (wide steps around the house) share 19 point tracks and 10
    # segment triplets; the best pose agrees with 5 of them and was 156 degrees off. Fewer inliers
    # than the floor (RansacParams::minInliers, 15): exit status 3, the counts said, nothing written.
    calib = tmp_path / "calib.yml"
    subprocess.run([str(build_tool("tripose_images_report", folder="test/evaluation")), "--data", str(MODEL_HOUSE),
                    "--calib-output", str(calib), "--views", "4", "6", "9"], check=True, capture_output=True, timeout=60)
    images = [MODEL_HOUSE / f"house.00{k}.pgm" for k in (4, 6, 9)]
    proc, out = run_images(tmp_path, "--overlay", tmp_path / "overlay.png", calib=calib, images=images)
    assert proc.returncode == 3, proc.stdout + proc.stderr
    # The counts of the matching (measured: 19 and 10) and the best pose's inliers (5).
    said = re.search(r"no reliable pose: (\d+) point tracks and (\d+) segment triplets matched, (\d+) inliers, "
                     r"fewer than the 15 a pose needs", proc.stderr)
    assert said, proc.stderr
    tracks, triplets, inliers = map(int, said.groups())
    assert f"{tracks} point tracks;" in proc.stdout and f"{triplets} segment triplets" in proc.stdout
    assert inliers < 15 and tracks + triplets >= 15
    assert not out.exists() and not (tmp_path / "overlay.png").exists()


def test_image_with_values_that_are_not_numbers(tmp_path):
    # A float TIFF with a NaN cannot be stretched onto 8 bits.
    broken = write_nan_tiff(tmp_path / "nan.tiff")
    expect_rejected(tmp_path, "not finite", images=[IMAGES[0], IMAGES[1], broken])
    expect_rejected(tmp_path, str(broken), images=[IMAGES[0], IMAGES[1], broken])


def expect_rejected(tmp_path, names, *options, **inputs):
    before = files_in(tmp_path)
    proc, out = run_images(tmp_path, *options, **inputs)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert names in proc.stderr, proc.stderr
    assert not out.exists()
    assert files_in(tmp_path) == before


def test_missing_image(tmp_path):
    missing = tmp_path / "no_such.png"
    expect_rejected(tmp_path, str(missing), images=[IMAGES[0], missing, IMAGES[2]])


def test_undecodable_image(tmp_path):
    broken = tmp_path / "broken.jpg"
    broken.write_bytes(IMAGES[1].read_bytes()[:200])
    expect_rejected(tmp_path, str(broken), images=[IMAGES[0], broken, IMAGES[2]])


def test_blank_image(tmp_path):
    blank = tmp_path / "blank.png"
    cv2.imwrite(str(blank), np.full((768, 1024), 90, np.uint8))
    proc, out = run_images(tmp_path, images=[IMAGES[0], IMAGES[1], blank])
    assert proc.returncode == 1 and str(blank) in proc.stderr and "blank" in proc.stderr
    assert not out.exists()


@pytest.mark.parametrize("scale", [0.5, 2.0])
def test_image_of_another_size_than_the_calibration(tmp_path, scale):
    scaled = tmp_path / "scaled.png"
    image = cv2.imread(str(IMAGES[2]))
    cv2.imwrite(str(scaled), cv2.resize(image, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA))
    proc, out = run_images(tmp_path, images=[IMAGES[0], IMAGES[1], scaled])
    assert proc.returncode == 1, proc.stdout
    assert str(scaled) in proc.stderr and "K3" in proc.stderr
    assert not out.exists()


def test_too_few_features(tmp_path):
    # A disc on a plain background: a blob or two, no segment of 20 px.
    images = []
    for k in range(3):
        path = tmp_path / f"disc{k}.png"
        image = np.full((768, 1024), 100, np.uint8)
        cv2.circle(image, (500 + 10 * k, 380), 25, 220, -1)
        cv2.imwrite(str(path), image)
        images.append(path)
    proc, out = run_images(tmp_path, images=images)
    assert proc.returncode == 1, proc.stdout
    assert "too few features" in proc.stderr and str(images[0]) in proc.stderr
    assert not out.exists()


@pytest.mark.parametrize("key", ["K2", "R12", "t12"])
def test_calibration_without_a_needed_key(tmp_path, key):
    values = read_matrices(CALIB, ["K1", "K2", "K3", "R12", "t12"])
    del values[key]
    calib = tmp_path / "calib.yml"
    fs = cv2.FileStorage(str(calib), cv2.FILE_STORAGE_WRITE)
    for k, v in values.items():
        fs.write(k, v)
    fs.release()
    before = files_in(tmp_path)
    proc, out = run_images(tmp_path, calib=calib)
    assert proc.returncode == 1, proc.stdout
    assert str(calib) in proc.stderr and f"'{key}'" in proc.stderr
    assert not out.exists() and files_in(tmp_path) == before


def test_calibration_without_a_baseline(tmp_path):
    # Views 1 and 2 at one place: rejected as bad input before the features are computed. Before, the
    # solver rejected it after them, with exit status 2.
    values = read_matrices(CALIB, ["K1", "K2", "K3", "R12"])
    values["t12"] = np.zeros((3, 1))
    calib = tmp_path / "calib.yml"
    write_problem(calib, values)
    proc, out = run_images(tmp_path, calib=calib)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert str(calib) in proc.stderr and "'t12'" in proc.stderr and "non-zero" in proc.stderr
    assert "points" not in proc.stdout  # no feature was detected
    assert not out.exists()


@pytest.mark.parametrize("option,where", [("--output", "no_folder/result.yml"), ("--output", "a_folder"),
                                          ("--overlay", "no_folder/overlay.png"), ("--matches", "no_folder/m.png")])
def test_output_that_cannot_be_written(tmp_path, option, where):
    # Found before any work: the run ended in "cannot write" after it, and with --overlay in a missing
    # folder it had written the result, then failed (exit status 1 beside an output file).
    (tmp_path / "a_folder").mkdir()
    target = tmp_path / where
    before = files_in(tmp_path)
    if option == "--output":
        proc, _ = run_images(tmp_path, name=where)
    else:
        proc, _ = run_images(tmp_path, option, target)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert f"{option} {target}" in proc.stderr and "cannot be written" in proc.stderr, proc.stderr
    assert "points" not in proc.stdout  # no feature was detected
    assert files_in(tmp_path) == before


def test_missing_calibration_file(tmp_path):
    expect_rejected(tmp_path, "no_calib.yml", calib=tmp_path / "no_calib.yml")


@pytest.mark.parametrize("options,names", [(["--features", "edges"], "--features"),
                                           (["--threshold", "-1"], "--threshold"),
                                           (["--max-image-size", "-1"], "--max-image-size")])
def test_bad_arguments(tmp_path, options, names):
    expect_rejected(tmp_path, names, *options)


def test_two_images_are_rejected(tmp_path):
    expect_rejected(tmp_path, "--images", images=IMAGES[:2])


# --- images larger than --max-image-size --------------------------------------------------------

ENLARGEMENT = 4  # 4096 x 3072, a 12-megapixel camera's size


@pytest.fixture(scope="module")
def enlarged(tmp_path_factory):
    """The Merton triplet enlarged four times and its calibration: the original's pixel centre x lies at
    4 x + 1.5."""
    tmp_path = tmp_path_factory.mktemp("enlarged")
    return (tmp_path, *enlarged_merton(tmp_path, ENLARGEMENT))


def test_large_images_are_detected_reduced(enlarged):
    tmp_path, calib, images = enlarged
    out = tmp_path / "default.yml"
    status, peak, output = run_with_peak_memory([build_tool("tripose_images"), "--calib", calib, "--images", *images,
                                                 "--output", out], timeout=300)
    assert status == 0, output
    # Detected at 1600 x 1200 (the default --max-image-size), pixel tolerances 2.56 times the given ones.
    assert "reduced by 2.56" in output, output
    # Measured 0.032 deg (0.021 on the original images); 1.1 GB at its peak, against 4.8 GB and five
    # times the time for the full images (--max-image-size 0; doc/studies/real_images.md).
    assert pose_error_deg(out) < BOUND_DEG
    assert peak < 2048, peak
    # The estimate's tolerances are the given ones (2 px, loss scale 0.5 px) times the reduction, and
    # the result says so: with them tripose_estimate solves the written problem again.
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    scale, threshold, loss_scale = (fs.getNode(k).real() for k in ("pixel_scale", "threshold", "loss_scale"))
    fs.release()
    assert scale == pytest.approx(2.56) and threshold == pytest.approx(2 * scale)
    assert loss_scale == pytest.approx(0.5 * scale)
    again = tmp_path / "again.yml"
    proc = subprocess.run([str(build_tool("tripose_estimate")), "--input", str(out), "--output", str(again),
                           "--allow-unknown-keys", "--method", "ransac", "--threshold", str(threshold), "--loss",
                           "cauchy", "--loss-scale", str(loss_scale)], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    first, second = read_matrices(out, ["R"])["R"], read_matrices(again, ["R"])["R"]
    assert np.degrees(rotation_error(first, second)) < 1e-3


def test_reduced_detection_places_features_in_the_images_pixels(enlarged, merton_result):
    # Reduced to the original's size, the enlarged images give the original's features, in the
    # enlarged images' pixels: mapped back, the tracks found in both must coincide.
    tmp_path, calib, images = enlarged
    proc, out = run_images(tmp_path, "--max-image-size", 1024, calib=calib, images=images, name="reduced.yml")
    assert proc.returncode == 0, proc.stderr
    reduced = (read_matrices(out, ["points3"])["points3"] - 1.5) / ENLARGEMENT
    original = read_matrices(merton_result[1], ["points3"])["points3"]
    offsets = offsets_to_nearest(reduced, original)
    near = np.hypot(*offsets.T) < 1
    # Measured: 0.002 px over 519 of 844 tracks; pixel centres mapped as corners would be 0.375 px off.
    assert near.sum() > 0.4 * len(reduced)
    assert np.all(np.abs(np.median(offsets[near], axis=0)) < 0.05), np.median(offsets[near], axis=0)
    assert pose_error_deg(out) < BOUND_DEG
