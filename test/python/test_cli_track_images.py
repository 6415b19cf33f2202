"""End-to-end tests of `tripose_track_vgg --from-images` (test/evaluation): the correspondences come from the folder's
images through the image front end (frames 0 and 1 keep the sequence's poses). Run on the bundled
Merton College I images, also with frames inserted (noise, a camera that stands still or only
turns); bad input (a folder whose images do not match its cameras) is rejected with exit status 1,
the folder or image named, and nothing written."""
import shutil
import subprocess

import cv2
import numpy as np
import pytest

from tripose_tools import REPO, build_tool, files_in, read_matrices

VGG = REPO / "test" / "data" / "vgg"


def track(tmp_path, data, *options, name="track.yml"):
    out = tmp_path / name
    proc = subprocess.run([str(build_tool("tripose_track_vgg", folder="test/evaluation")), "--data", str(data), "--output", str(out),
                           "--from-images", *map(str, options)], capture_output=True, text=True, timeout=300)
    return proc, out


def test_merton_college_i_from_images(tmp_path):
    # Frame 2 is the one new frame: it must be registered from the images' tracks (figures in
    # doc/studies/real_images.md).
    proc, out = track(tmp_path, VGG / "Merton-College-I")
    assert proc.returncode == 0, proc.stderr
    assert "warning" not in proc.stderr  # frames 0-1 agree with their cameras
    values = read_matrices(out, ["poses", "status", "features", "rotation_error_deg"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0, 1])
    assert values["features"].ravel()[2] >= 200
    assert values["rotation_error_deg"].ravel()[2] < 0.2
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    assert fs.getNode("correspondences").string() == "images"
    assert fs.getNode("drift_percent").real() < 1.0
    fs.release()


def test_reduced_images(tmp_path):
    # Detected in the images reduced to 640 px (1.6 times), with the tolerances grown as much, frame 2
    # is still registered within half as much again as the full-size bound: the grown threshold admits
    # the reduced images' less precise matches (doc/studies/front_end_and_tracker.md).
    proc, out = track(tmp_path, VGG / "Merton-College-I", "--max-image-size", 640)
    assert proc.returncode == 0, proc.stderr
    assert "reduced by 1.60" in proc.stdout
    values = read_matrices(out, ["status", "features", "rotation_error_deg"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0, 1])
    assert values["features"].ravel()[2] >= 200
    assert values["rotation_error_deg"].ravel()[2] < 0.3


def test_images_and_sequence_correspondences_differ(tmp_path):
    # The option changes where the features come from: the tracked feature counts differ.
    from_images, _ = track(tmp_path, VGG / "Merton-College-I")
    assert from_images.returncode == 0, from_images.stderr
    images = read_matrices(tmp_path / "track.yml", ["features"])["features"].ravel()
    proc = subprocess.run([str(build_tool("tripose_track_vgg", folder="test/evaluation")), "--data", str(VGG / "Merton-College-I"), "--output",
                           str(tmp_path / "own.yml")], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    own = read_matrices(tmp_path / "own.yml", ["features"])["features"].ravel()
    assert images[2] != own[2]


def test_folder_without_images_is_rejected(tmp_path):
    data = tmp_path / "Wadham-College"
    shutil.copytree(VGG / "Wadham-College", data)
    before = files_in(tmp_path)
    proc, out = track(tmp_path, data)
    assert proc.returncode == 1, proc.stdout
    assert str(data) in proc.stderr and "--from-images" in proc.stderr
    assert not out.exists() and files_in(tmp_path) == before


def test_images_out_of_the_cameras_order_are_reported(tmp_path):
    # The first two images swapped: frames 0 and 1 take the cameras' poses, and their descriptor
    # matches, found without those poses, do not follow them (as tripose_images' check).
    data = tmp_path / "Merton-College-I"
    shutil.copytree(VGG / "Merton-College-I", data)
    (data / "001.jpg").rename(data / "swap.jpg")
    (data / "002.jpg").rename(data / "001.jpg")
    (data / "swap.jpg").rename(data / "002.jpg")
    proc, _ = track(tmp_path, data)
    assert "warning: the images of frames 0 and 1" in proc.stderr and "001.jpg" in proc.stderr, proc.stderr


def test_blank_image_in_the_folder_is_rejected(tmp_path):
    data = tmp_path / "Merton-College-I"
    shutil.copytree(VGG / "Merton-College-I", data)
    cv2.imwrite(str(data / "003.jpg"), np.zeros((768, 1024), np.uint8))
    before = files_in(tmp_path)
    proc, out = track(tmp_path, data)
    assert proc.returncode == 1, proc.stdout
    assert "003.jpg" in proc.stderr and "blank" in proc.stderr
    assert not out.exists() and files_in(tmp_path) == before


def merton_with_frames_inserted(folder, images):
    """Merton College I with @p images inserted after its second frame (their cameras copies of that
    frame's, no correspondences): 001, 002, the inserted ones from 003 on, then Merton's 003."""
    source = VGG / "Merton-College-I"
    folder.mkdir()
    names = ["001", "002"] + [f"{3 + i:03d}" for i in range(len(images))] + [f"{3 + len(images):03d}"]
    for old, new in (("001", names[0]), ("002", names[1]), ("003", names[-1])):
        for suffix in (".P", ".corners", ".lines", ".jpg"):
            shutil.copy(source / (old + suffix), folder / (new + suffix))
    for name, image in zip(names[2:-1], images):
        for suffix in (".P", ".corners", ".lines"):
            shutil.copy(source / ("002" + suffix), folder / (name + suffix))
        cv2.imwrite(str(folder / (name + ".jpg")), image)
    for name in ("nview-corners", "nview-lines"):
        rows = [line.split() for line in (source / name).read_text().splitlines() if line.strip()]
        (folder / name).write_text("".join(" ".join(r[:2] + ["*"] * len(images) + r[2:]) + "\n" for r in rows))
    for name in ("p3d", "l3d"):
        shutil.copy(source / name, folder / name)
    return folder


@pytest.mark.parametrize("frames_of_noise", [1, 2])
def test_frame_that_matches_no_neighbour_is_passed_over(tmp_path, frames_of_noise):
    # Images of blurred noise between frames 1 and 2 share no geometry with them: they are lost, and
    # the frame after them is matched to frame 1, two or three frames back, so the tracks go on.
    # Matched to the frame before it alone, every track would end at the noise and every later frame
    # would be lost.
    rng = np.random.default_rng(3)
    noise = [cv2.GaussianBlur((rng.random((768, 1024)) * 255).astype(np.uint8), (0, 0), 2)
             for _ in range(frames_of_noise)]
    proc, out = track(tmp_path, merton_with_frames_inserted(tmp_path / "Merton", noise))
    assert proc.returncode == 0, proc.stderr
    values = read_matrices(out, ["status", "features", "rotation_error_deg"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0] + [2] * frames_of_noise + [1])
    assert values["features"].ravel()[-1] >= 200
    assert values["rotation_error_deg"].ravel()[-1] < 0.2


def test_camera_standing_still_adds_no_keyframes(tmp_path):
    # The second image four times more: a camera that stood still. Those frames are registered at
    # frame 1's pose but add no baseline, so they are not keyframes, and the third image is registered
    # against frames 0 and 1 (measured 0.065 deg; registered against the four copies, with every
    # registered frame a keyframe, it is 0.31 deg and 33 % of the path off).
    still = cv2.imread(str(VGG / "Merton-College-I" / "002.jpg"))
    data = merton_with_frames_inserted(tmp_path / "Merton", [still] * 4)
    proc, out = track(tmp_path, data)
    assert proc.returncode == 0, proc.stderr
    assert "not a keyframe" in proc.stdout
    values = read_matrices(out, ["status", "keyframe", "rotation_error_deg", "position_error"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0, 1, 1, 1, 1, 1])
    np.testing.assert_array_equal(values["keyframe"].ravel(), [1, 1, 0, 0, 0, 0, 1])
    assert np.all(values["rotation_error_deg"].ravel()[2:6] < 0.05)
    assert values["rotation_error_deg"].ravel()[6] < 0.2


def test_camera_that_only_turns_is_no_keyframe(tmp_path):
    # Frame 1's image turned by 2 degrees about its camera's centre (the homography K R K^-1; its
    # camera turned the same way), inserted after it: registered, but without a baseline to frame 1
    # it is no keyframe, and the third image is registered against frames 0 and 1 (measured 0.002
    # and 0.027 deg; 0.074 deg for the third with the turned frame a keyframe).
    source = VGG / "Merton-College-I"
    camera = np.loadtxt(source / "002.P")
    K = cv2.decomposeProjectionMatrix(camera)[0]
    H = K @ cv2.Rodrigues(np.array([0.0, np.radians(2.0), 0.0]))[0] @ np.linalg.inv(K)
    image = cv2.imread(str(source / "002.jpg"))
    turned = cv2.warpPerspective(image, H, (image.shape[1], image.shape[0]))
    data = merton_with_frames_inserted(tmp_path / "Merton", [turned])
    np.savetxt(data / "003.P", H @ camera)
    proc, out = track(tmp_path, data)
    assert proc.returncode == 0, proc.stderr
    values = read_matrices(out, ["status", "keyframe", "rotation_error_deg"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0, 1, 1])
    np.testing.assert_array_equal(values["keyframe"].ravel(), [1, 1, 0, 1])
    errors = values["rotation_error_deg"].ravel()
    assert errors[2] < 0.05 and errors[3] < 0.2


def test_observations_are_the_tracks_at_the_sequence_cameras(tmp_path):
    # --observations writes the tracks the frames were registered from; most fit the sequence's
    # cameras within a pixel (test/evaluation/track_observation_residuals.py: a wrong link shows as pixels).
    tracks = tmp_path / "tracks.yml"
    proc, _ = track(tmp_path, VGG / "Merton-College-I", "--observations", tracks)
    assert proc.returncode == 0, proc.stderr
    import sys
    sys.path.insert(0, str(REPO / "test" / "evaluation"))
    from track_observation_residuals import point_residuals, read_observations, segment_residuals
    points, lines = read_observations(tracks)
    assert len(points) == 3 and all(p.shape[1] == 2 for p in points) and all(l.shape[1] == 4 for l in lines)
    # Every track has a row in every frame; frame 2 sees at least as many as it was registered from.
    assert len({p.shape[0] for p in points}) == 1 and len({l.shape[0] for l in lines}) == 1
    features = read_matrices(tmp_path / "track.yml", ["features"])["features"].ravel()
    assert np.isfinite(points[2][:, 0]).sum() + np.isfinite(lines[2][:, 0]).sum() >= features[2]
    cameras = [np.loadtxt(p) for p in sorted((VGG / "Merton-College-I").glob("*.P"))]
    for residuals in (point_residuals(points, cameras), segment_residuals(lines, cameras)):
        seen = residuals[2][np.isfinite(residuals[2])]
        assert len(seen) >= 50 and np.median(seen) < 0.5


def test_output_that_cannot_be_written_is_rejected(tmp_path):
    # Before the sequence is read: a sequence's run takes seconds to minutes.
    proc, out = track(tmp_path, VGG / "Merton-College-I", name="no_folder/track.yml")
    assert proc.returncode == 1 and f"--output {out}" in proc.stderr and "cannot be written" in proc.stderr
    assert files_in(tmp_path) == []
