"""The suite tests the installed package (`pip install .`), never the source folder python/tripose:
that folder has no compiled extension, and importing it would test nothing that users get."""
from pathlib import Path
import sys

import pytest

TESTS = Path(__file__).resolve().parent
REPO = TESTS.parents[1]
SOURCE_PACKAGE = REPO / "python" / "tripose"

sys.path.insert(0, str(TESTS))  # scenes.py and the other helpers of the suite

try:
    import tripose  # noqa: E402
except ImportError as error:
    raise pytest.UsageError(f"cannot import the installed tripose package ({error}); install it with `pip install .`")

_location = Path(tripose.__file__).resolve()
if _location.is_relative_to(REPO / "python"):
    raise pytest.UsageError(f"tripose was imported from the source tree ({_location}), not from the installed "
                            f"package; install it with `pip install .` and run pytest without python/ on sys.path")
if not hasattr(tripose, "_tripose_ext") or not Path(tripose._tripose_ext.__file__).is_file():
    raise pytest.UsageError(f"tripose at {_location} has no compiled extension _tripose_ext; install the package "
                            f"with `pip install .`")
