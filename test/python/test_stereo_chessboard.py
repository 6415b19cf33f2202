# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""tripose_stereo_chessboard on one frame pair of OpenCV's stereo calibration sample (test/data/stereo).

The tolerances come from the 78 pairs of doc/studies/stereo.md: over all of them the stereo RANSAC's
largest errors are 0.67 deg and 3.0 %, the stereo linear solver's on the lines alone 1.74 deg and
4.3 %. Each test takes about a second.
"""

import subprocess

import cv2
import numpy as np
import pytest

from tripose_tools import REPO, build_tool

DATA = REPO / "test" / "data" / "stereo"
PAIR = "0,4"  # left01/right01 -> left05/right05: 79 deg of rotation, 6 squares of translation


def run(tmp_path, *extra):
    out = tmp_path / "result.yml"
    proc = subprocess.run([str(build_tool("tripose_stereo_chessboard")), "--data", str(DATA), "--pairs", PAIR,
                           "--output", str(out), *extra], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    pair = fs.getNode("pairs").at(0)
    result = {}
    for method in ("stereo_ransac", "stereo_linear", "three_view_ransac"):
        node = pair.getNode(method)
        result[method] = (node.getNode("rot_deg").real(), node.getNode("t_rel").real()) \
            if int(node.getNode("ok").real()) else None
    result["lines_b"] = [int(np.all(np.isfinite(pair.getNode(f"lines{v}").mat()), axis=1).sum()) for v in (3, 4)]
    result["points"] = pair.getNode("points1").mat()
    return result


def test_stereo_ransac_matches_the_board_geometry(tmp_path):
    r = run(tmp_path, "--overlay", str(tmp_path / "overlay.png"))
    assert r["points"].shape == (54, 2)
    assert r["lines_b"] == [15, 15]  # every inner row and column of the 9x6 board, in both images at B
    for method in ("stereo_ransac", "three_view_ransac"):
        rot_deg, t_rel = r[method]
        assert rot_deg < 1.0 and t_rel < 0.04, (method, rot_deg, t_rel)
    overlay = cv2.imread(str(tmp_path / "overlay.png"))
    assert overlay is not None and overlay.shape == (480, 640, 3)


def test_detected_lines_alone_give_the_motion(tmp_path):
    # Without the corners the estimate rests on the detected segments and their association only.
    r = run(tmp_path, "--features", "lines")
    assert r["points"] is None or r["points"].size == 0
    rot_deg, t_rel = r["stereo_linear"]
    assert rot_deg < 2.0 and t_rel < 0.05, (rot_deg, t_rel)


def test_a_missing_list_file_is_named(tmp_path):
    proc = subprocess.run([str(build_tool("tripose_stereo_chessboard")), "--data", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1
    assert "stereo_calib.xml" in proc.stderr


def test_three_view_ransac_on_lines_alone_is_never_turned_over(tmp_path):
    # Every one of the 78 pairs (about 3 s). Seen through lines alone, the planar board admits the
    # pose turned by pi about its normal, which fits every line exactly but sees the segments behind
    # the camera (doc/studies/stereo.md, "Lines alone"); it once came back on 29 pairs. The largest error
    # is now 2.0 deg; 5 deg is the table's line between an inaccurate and a wrong answer.
    out = tmp_path / "lines.yml"
    proc = subprocess.run([str(build_tool("tripose_stereo_chessboard")), "--data", str(DATA), "--pairs", "all",
                           "--features", "lines", "--output", str(out)], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    pairs = fs.getNode("pairs")
    assert pairs.size() == 78
    worst = []
    for i in range(pairs.size()):
        node = pairs.at(i).getNode("three_view_ransac")
        assert int(node.getNode("ok").real()), i
        worst.append(node.getNode("rot_deg").real())
    assert max(worst) < 5.0, sorted(worst)[-5:]
