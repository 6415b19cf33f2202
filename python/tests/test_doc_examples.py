"""The Python examples of README.md and doc/getting_started_python.md run as written.

The estimation examples run in one namespace each, in the page's order (the guide's first example
builds the scene the others use; the README's quick start takes its arrays from that scene). The
tracking examples need images and OpenCV's contrib modules and are left to the tracker's tests.
"""
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
GUIDE = REPO / "doc" / "getting_started_python.md"
README = REPO / "README.md"


def python_blocks(path):
    if not path.exists():
        pytest.skip(f"{path.name} is not beside the tests (an installed package's tests)")
    return re.findall(r"```python\n(.*?)```", path.read_text(), re.S)


def estimation_blocks(path):
    """The examples that need no images: those that neither track nor detect."""
    return [b for b in python_blocks(path) if "Tracker(" not in b and "tripose.images" not in b]


def scene():
    namespace = {}
    exec(python_blocks(GUIDE)[0], namespace)
    return namespace


def test_the_guide_estimation_examples_run_in_order(capsys):
    blocks = estimation_blocks(GUIDE)
    assert len(blocks) >= 3, "the guide's three estimation examples (candidates, RANSAC, refinement)"
    namespace = {}
    for code in blocks:
        exec(code, namespace)
    assert namespace["result"].R is not None and namespace["result"].num_inliers == 20
    assert namespace["refined"].rms < 1e-6


def test_the_readme_quick_start_runs_on_the_guide_scene(capsys):
    blocks = estimation_blocks(README)
    assert blocks, "the README's Python quick start"
    for code in blocks:
        namespace = scene()
        for k in range(3):
            namespace[f"points{k + 1}"] = namespace["points"][k]
            namespace[f"lines{k + 1}"] = namespace["lines"][k]
        exec(code, namespace)
        assert namespace["result"].num_inliers == 20
        assert namespace["options"].refine_options.loss == "cauchy"
