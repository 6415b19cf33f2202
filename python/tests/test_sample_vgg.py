"""samples/python/estimate_pose.py on VGG Merton College I (views 0, 1, 2; bundled in
test/data/vgg): it runs and its pose of view 3 is as close to the sequence's camera as expected.

The sequence's cameras are themselves estimates (they reproject the structure with a median error
of 0.1-0.7 px), so the error cannot be required to vanish. The C++ demo (scripts/demo.sh,
tripose_demo_vgg: the linear estimate on all 241 points and 295 lines) reports 0.0079 deg; the
sample's linear estimate must print the same, which checks its numpy reader against the C++ one.
RANSAC with refinement (the maximum-likelihood pose over the three views) measures 0.0131 deg; the
bound 0.02 deg is 50 % above that, while a wrong reading of the data (a camera matrix, the frame of
view 1, a swapped coordinate) gives errors of degrees.
"""
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "samples" / "python" / "estimate_pose.py"
DATA = REPO / "test" / "data" / "vgg" / "Merton-College-I"


def test_sample_estimates_merton_college_i():
    proc = subprocess.run([sys.executable, str(SAMPLE), "--data", str(DATA)], capture_output=True, text=True,
                          timeout=120, cwd=REPO)
    assert proc.returncode == 0, proc.stderr
    assert "241 point and 295 line triplets" in proc.stdout, proc.stdout
    rotation = float(re.search(r"^Rotation error: ([0-9.]+) deg$", proc.stdout, re.M).group(1))
    translation = float(re.search(r"^Translation error: ([0-9.]+) % of \|t\|", proc.stdout, re.M).group(1))
    linear = float(re.search(r"^Linear estimate on all triplets: rotation error ([0-9.]+) deg$", proc.stdout,
                             re.M).group(1))
    assert rotation < 0.02, proc.stdout
    assert translation < 0.2, proc.stdout  # 2.5 times the figure in doc/accuracy.md
    assert linear == 0.0079, proc.stdout
