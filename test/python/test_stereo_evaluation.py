# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""test/evaluation/run_stereo_evaluation.py into a temporary folder (about 5 s): every artefact of
doc/studies/stereo.md is written, every frame pair is evaluated, and the methods that use the corners stay
within the errors doc/studies/stereo.md reports (the largest median there is 0.36 deg and 1.1 %).
"""

import json
import subprocess
import sys


from tripose_tools import REPO, build_tool, require_modules

DRIVER = REPO / "test" / "evaluation" / "run_stereo_evaluation.py"


def test_every_pair_is_evaluated(tmp_path):
    require_modules("poselib", "matplotlib")
    build_tool("tripose_stereo_chessboard")
    subprocess.run([sys.executable, str(DRIVER), "--out", str(tmp_path)], check=True, capture_output=True, timeout=300)
    assert (tmp_path / "errors.png").stat().st_size > 10_000
    assert "## Per pair" in (tmp_path / "tables.md").read_text()
    summary = json.loads((tmp_path / "data" / "summary.json").read_text())
    assert len(summary["pairs"]) == 78  # 13 frames, every unordered pair
    for method in ("stereo_ransac", "stereo_linear", "three_view_ransac", "three_view_linear", "tri+sqpnp",
                   "tri+poselib"):
        m = summary["medians"][method]
        assert m["failed"] == 0 and m["gross"] == 0, (method, m)
        assert m["rot_deg"] < 0.5 and m["t_rel"] < 0.015, (method, m)
