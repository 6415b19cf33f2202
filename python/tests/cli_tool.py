"""The C++ command-line tool tripose_estimate, which some tests hold the package against (built in
build/samples, or in the build folder that TRIPOSE_BUILD_DIR names)."""
import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


def estimate_tool():
    """The tool's path; the test fails (it does not skip) when it is not built."""
    build = Path(os.environ.get("TRIPOSE_BUILD_DIR", REPO / "build"))
    tool = build / "samples" / "tripose_estimate"
    if not tool.is_file():
        pytest.fail(f"{tool} is not built: build it with `cmake --build {build} --target tripose_estimate` "
                    f"(or set TRIPOSE_BUILD_DIR to a build folder that has it)")
    return tool
