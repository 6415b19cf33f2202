#!/usr/bin/env python3
"""Regenerates tripose's coefficient kernels (modules/tripose/src/core/generated/) from the specs.

    python3 codegen/generate.py           # regenerate in place
    python3 codegen/generate.py --check   # regenerate into a temporary folder, print a unified
                                          # diff against the checked-in files, exit 1 if they differ
"""

import argparse
import difflib
import os
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
OUTPUT_DIR = REPO / "modules" / "tripose" / "src" / "core" / "generated"


def _ensure_stable_hashing() -> None:
    """sympy's results do not depend on string hashing, but fixing the seed removes any doubt
    that the emitted bytes could vary from run to run."""
    if os.environ.get("PYTHONHASHSEED") != "0":
        env = dict(os.environ, PYTHONHASHSEED="0")
        os.execve(sys.executable, [sys.executable, str(Path(__file__).resolve())] + sys.argv[1:], env)


def _render(module_name: str):
    sys.path.insert(0, str(HERE))
    import importlib

    from tripose_codegen.render import render_family

    module = importlib.import_module(f"tripose_codegen.specs.{module_name}")
    return render_family(module.family())


def generate_all(jobs: int):
    """{file name: contents} of every generated file."""
    sys.path.insert(0, str(HERE))
    from tripose_codegen.specs import FAMILY_MODULES

    files = {}
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            for result in pool.map(_render, FAMILY_MODULES):
                files.update(result)
    else:
        for name in FAMILY_MODULES:
            files.update(_render(name))
    return files


def write_files(files, directory: Path) -> None:
    directory.mkdir(parents=True, exist_ok=True)
    for name in sorted(files):
        (directory / name).write_text(files[name])


def diff_against(directory: Path, reference: Path) -> str:
    """Unified diff from the files in @p reference to those in @p directory ('' if identical)."""
    out = []
    names = sorted({p.name for p in directory.iterdir()} | {p.name for p in reference.glob("*")
                                                            if p.is_file()})
    for name in names:
        old = (reference / name).read_text().splitlines(keepends=True) if (reference / name).exists() else []
        new = (directory / name).read_text().splitlines(keepends=True) if (directory / name).exists() else []
        rel = f"modules/tripose/src/core/generated/{name}"
        out.extend(difflib.unified_diff(old, new, fromfile=f"a/{rel}", tofile=f"b/{rel}"))
    return "".join(out)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true",
                        help="regenerate into a temporary folder and diff against the checked-in files")
    parser.add_argument("--jobs", type=int, default=2, help="worker processes (default 2)")
    args = parser.parse_args()
    _ensure_stable_hashing()

    start = time.perf_counter()
    files = generate_all(args.jobs)
    elapsed = time.perf_counter() - start
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            write_files(files, Path(tmp))
            diff = diff_against(Path(tmp), OUTPUT_DIR)
        if diff:
            sys.stdout.write(diff)
            print(f"generated code is out of date: run `python3 codegen/generate.py` ({elapsed:.1f} s)",
                  file=sys.stderr)
            return 1
        print(f"generated code is up to date ({len(files)} files, {elapsed:.1f} s)")
        return 0
    write_files(files, OUTPUT_DIR)
    print(f"wrote {len(files)} files to {OUTPUT_DIR.relative_to(REPO)} ({elapsed:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
