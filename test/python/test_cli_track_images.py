"""End-to-end tests of `tripose_track --from-images`: the correspondences come from the folder's
images through the image front end (frames 0 and 1 keep the sequence's poses). Run on the bundled
Merton College I images; bad input (a folder whose images do not match its cameras) is rejected
with exit status 1, the folder or image named, and nothing written."""
import shutil
import subprocess

import cv2
import numpy as np

from tripose_tools import REPO, build_tool, files_in, read_matrices

VGG = REPO / "test" / "data" / "vgg"


def track(tmp_path, data, *options):
    out = tmp_path / "track.yml"
    proc = subprocess.run([str(build_tool("tripose_track")), "--data", str(data), "--output", str(out),
                           "--from-images", *map(str, options)], capture_output=True, text=True, timeout=300)
    return proc, out


def test_merton_college_i_from_images(tmp_path):
    # Frame 2 is the one new frame: it must be registered from the images' tracks (figures in
    # doc/real_images.md).
    proc, out = track(tmp_path, VGG / "Merton-College-I")
    assert proc.returncode == 0, proc.stderr
    values = read_matrices(out, ["poses", "status", "features", "rotation_error_deg"])
    np.testing.assert_array_equal(values["status"].ravel(), [0, 0, 1])
    assert values["features"].ravel()[2] >= 200
    assert values["rotation_error_deg"].ravel()[2] < 0.2
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    assert fs.getNode("correspondences").string() == "images"
    assert fs.getNode("drift_percent").real() < 1.0
    fs.release()


def test_images_and_sequence_correspondences_differ(tmp_path):
    # The option changes where the features come from: the tracked feature counts differ.
    from_images, _ = track(tmp_path, VGG / "Merton-College-I")
    assert from_images.returncode == 0, from_images.stderr
    images = read_matrices(tmp_path / "track.yml", ["features"])["features"].ravel()
    proc = subprocess.run([str(build_tool("tripose_track")), "--data", str(VGG / "Merton-College-I"), "--output",
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


def test_blank_image_in_the_folder_is_rejected(tmp_path):
    data = tmp_path / "Merton-College-I"
    shutil.copytree(VGG / "Merton-College-I", data)
    cv2.imwrite(str(data / "003.jpg"), np.zeros((768, 1024), np.uint8))
    before = files_in(tmp_path)
    proc, out = track(tmp_path, data)
    assert proc.returncode == 1, proc.stdout
    assert "003.jpg" in proc.stderr and "blank" in proc.stderr
    assert not out.exists() and files_in(tmp_path) == before
