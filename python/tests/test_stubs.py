"""The type stubs of the extension (python/tripose/_tripose_ext.pyi) are the ones nanobind's stubgen
makes from the installed extension: a binding changed without its stubs fails here."""
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
STUBS = REPO / "python" / "tripose" / "_tripose_ext.pyi"
COMMAND = "python -m nanobind.stubgen -m tripose._tripose_ext -o python/tripose/_tripose_ext.pyi"


def test_stubs_are_the_extensions(tmp_path):
    pytest.importorskip("nanobind.stubgen")
    out = tmp_path / "_tripose_ext.pyi"
    proc = subprocess.run([sys.executable, "-m", "nanobind.stubgen", "-q", "-m", "tripose._tripose_ext", "-o",
                           str(out)], capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert out.read_text() == STUBS.read_text(), f"the stubs differ from the extension's; regenerate them: {COMMAND}"


def test_stubs_type_the_pose_result_and_the_options():
    text = STUBS.read_text()
    assert "def R(self, /) -> numpy.typing.NDArray[numpy.float64] | None" in text
    assert "options: RansacOptions | None" in text and "options: RefineOptions | None" in text
    assert "def min_inliers(self) -> int" in text
