"""The checked-in generated files are what the specs produce, byte for byte, whatever the
interpreter's string-hash seed (generate.py fixes the seed; this shows it does not need to)."""

import os
import subprocess
import sys
from pathlib import Path

CODEGEN_DIR = Path(__file__).resolve().parents[1]
GENERATED_DIR = CODEGEN_DIR.parent / "modules" / "tripose" / "src" / "core" / "generated"

SCRIPT = """
import sys
sys.path.insert(0, {codegen!r})
from pathlib import Path
from tripose_codegen.render import render_family
from tripose_codegen.specs import all_families
generated = Path({generated!r})
files = {{}}
for family in all_families():
    files.update(render_family(family))
stale = sorted(n for n, text in files.items() if not (generated / n).exists() or (generated / n).read_text() != text)
extra = sorted(p.name for p in generated.iterdir() if p.name not in files)
print("stale:", stale, "extra:", extra)
sys.exit(1 if stale or extra else 0)
"""


def test_generated_files_are_up_to_date_under_another_hash_seed():
    env = dict(os.environ, PYTHONHASHSEED="4242")
    script = SCRIPT.format(codegen=str(CODEGEN_DIR), generated=str(GENERATED_DIR))
    result = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
