"""samples/python/pose_from_images.py with the installed package: its estimate on the bundled Merton
College I images is the C++ tool's on the problem the script writes (same matches, same seed).
The sample's matching and bad input are tested in test/python/test_pose_from_images.py."""
import subprocess
import sys

import cv2
import numpy as np

from cli_tool import REPO, estimate_tool

SCRIPT = REPO / "samples" / "python" / "pose_from_images.py"
MERTON = REPO / "test" / "data" / "vgg" / "Merton-College-I"
CALIB = REPO / "test" / "data" / "images" / "merton_college_i_calib.yml"
IMAGES = [MERTON / f"00{k}.jpg" for k in (1, 2, 3)]


def read(path, keys):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    values = {key: fs.getNode(key).mat() for key in keys}
    fs.release()
    return values


def rotation_error_deg(Ra, Rb):
    return np.degrees(np.arccos(np.clip((np.trace(Ra.T @ Rb) - 1) / 2, -1.0, 1.0)))


def test_estimate_through_the_package_is_the_tools(tmp_path):
    out = tmp_path / "result.yml"
    proc = subprocess.run([sys.executable, str(SCRIPT), "--calib", str(CALIB), "--images", *map(str, IMAGES),
                           "--output", str(out)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    result = read(out, ["R", "point_inliers"])
    again = tmp_path / "estimate.yml"
    # Both refine the inliers under the image front end's Cauchy loss (samples/common/image_estimation.hpp).
    tool = subprocess.run([str(estimate_tool()), "--input", str(out), "--output", str(again), "--allow-unknown-keys",
                           "--method", "ransac", "--loss", "cauchy", "--loss-scale", "0.5"],
                          capture_output=True, text=True, timeout=120)
    assert tool.returncode == 0, tool.stderr
    assert rotation_error_deg(result["R"], read(again, ["R"])["R"]) < 1e-3
    assert result["point_inliers"].sum() >= 0.7 * result["point_inliers"].size
