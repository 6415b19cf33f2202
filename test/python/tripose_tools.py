"""Shared helpers of the Python tests: locating the built tools and making scenes with them."""
import os
import subprocess
from pathlib import Path

import cv2
import numpy as np

REPO = Path(__file__).resolve().parents[2]


def build_dir():
    return Path(os.environ.get("TRIPOSE_BUILD_DIR", REPO / "build"))


def build_tool(name):
    """Path of a built sample; a missing tool is an error (the test command builds them)."""
    path = build_dir() / "samples" / name
    if not path.exists():
        raise FileNotFoundError(f"{path} is not built; run scripts/test.sh or set TRIPOSE_BUILD_DIR")
    return path


def make_scene(tmp_path, points, lines, seed, noise=0.0, outliers=0.0, motion="large"):
    """A synthetic problem file with ground truth, written by tripose_make_scene."""
    out = Path(tmp_path) / f"scene_{points}p{lines}l_{seed}.yml"
    subprocess.run([str(build_tool("tripose_make_scene")), "--points", str(points), "--lines", str(lines),
                    "--motion", motion, "--noise", str(noise), "--outliers", str(outliers),
                    "--seed", str(seed), "--output", str(out)], check=True, capture_output=True, timeout=60)
    return out


def rotation_error(A, B):
    """Angle (rad) of A B^T, accurate near zero."""
    d = np.linalg.norm(np.asarray(A) - np.asarray(B)) / (2.0 * np.sqrt(2.0))
    return 2.0 * np.arcsin(min(1.0, d))
