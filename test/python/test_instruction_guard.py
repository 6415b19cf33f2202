"""The speed guard: each hot path of the benchmarks (build/test/benchmark/tripose_instruction_guard)
counted in instructions under valgrind's callgrind, which unlike time does not move with the machine's
load, against its figure in test/benchmark/instruction_counts.txt. A path that costs more than its
figure by more than the file's tolerance fails, naming the recorded and measured counts; one that got
cheaper by more than the tolerance passes with a warning that its figure can be lowered.

Update the figures (after a change meant to cost more, or a cheaper one) with
    .venv/bin/python test/python/test_instruction_guard.py --update [path ...]
and commit the file together with the change."""
import re
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tripose_tools import REPO, build_dir, build_tool  # noqa: E402

COUNTS = REPO / "test" / "benchmark" / "instruction_counts.txt"


def read_counts(path=COUNTS):
    """(tolerance as a fraction, {path: instructions}) from the counts file."""
    tolerance, figures = None, {}
    for line in path.read_text().splitlines():
        fields = line.split("#", 1)[0].split()
        if not fields:
            continue
        if fields[0] == "tolerance_percent":
            tolerance = float(fields[1]) / 100.0
        else:
            figures[fields[0]] = int(fields[1])
    if tolerance is None:
        raise ValueError(f"{path} has no tolerance_percent line")
    return tolerance, figures


def count_instructions(name, out_dir):
    """Instructions executed inside tripose_guard_measured() by one run of the path `name`."""
    valgrind = shutil.which("valgrind")
    if valgrind is None:
        raise FileNotFoundError("valgrind is not installed; run scripts/install_dependencies.sh")
    out = Path(out_dir) / f"callgrind.{name}.out"
    # Only the hot path's calls are counted: the program makes its scenes outside that function.
    subprocess.run([valgrind, "--tool=callgrind", f"--callgrind-out-file={out}", "--collect-atstart=no",
                    "--toggle-collect=tripose_guard_measured",
                    str(build_tool("tripose_instruction_guard", "test/benchmark")), name],
                   check=True, capture_output=True, timeout=600)
    match = re.search(r"^(?:totals|summary):\s*(\d+)", out.read_text(), re.MULTILINE)
    if match is None:
        raise RuntimeError(f"no instruction total in {out}")
    return int(match.group(1))


def build_type():
    cache = build_dir() / "CMakeCache.txt"
    match = re.search(r"^CMAKE_BUILD_TYPE:\w+=(\w*)", cache.read_text(), re.MULTILINE) if cache.exists() else None
    return match.group(1) if match else ""


TOLERANCE, FIGURES = read_counts()


@pytest.mark.parametrize("name", sorted(FIGURES))
def test_instruction_count(name, tmp_path):
    # The figures are those of an optimised build; a debug build's counts say nothing about a change.
    if build_type() != "Release":
        pytest.skip(f"the figures are of a Release build; {build_dir()} is '{build_type()}'")
    recorded = FIGURES[name]
    measured = count_instructions(name, tmp_path)
    ratio = measured / recorded
    assert ratio <= 1.0 + TOLERANCE, (
        f"{name} costs more than its recorded figure: {measured} instructions measured, {recorded} recorded "
        f"(x{ratio:.3f}, tolerance {100 * TOLERANCE:.0f} %). If the change is meant to cost more, update "
        f"{COUNTS.relative_to(REPO)} in the same commit (python test/python/test_instruction_guard.py --update {name})")
    if ratio < 1.0 - TOLERANCE:
        warnings.warn(f"{name} got cheaper: {measured} instructions measured, {recorded} recorded (x{ratio:.3f}); "
                      f"lower its figure in {COUNTS.relative_to(REPO)} "
                      f"(python test/python/test_instruction_guard.py --update {name})")


def update(names):
    """Measures the named paths (all when none) and rewrites their figures, keeping the file's comments."""
    import tempfile
    _, figures = read_counts()
    names = names or sorted(figures)
    measured = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            if name not in figures:
                raise SystemExit(f"{name} is not in {COUNTS}")
            measured[name] = count_instructions(name, tmp)
            print(f"{name}: {figures[name]} -> {measured[name]} (x{measured[name] / figures[name]:.3f})")
    lines = []
    for line in COUNTS.read_text().splitlines(keepends=True):
        fields = line.split("#", 1)[0].split()
        if fields and fields[0] in measured:
            line = line.replace(fields[1], str(measured[fields[0]]), 1)
        lines.append(line)
    COUNTS.write_text("".join(lines))


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] != "--update":
        raise SystemExit("usage: test_instruction_guard.py --update [path ...]  (the test itself runs under pytest)")
    update(sys.argv[2:])
