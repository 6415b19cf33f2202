import functools
import sys
from pathlib import Path

import numpy as np
import pytest

CODEGEN_DIR = Path(__file__).resolve().parents[1]
if str(CODEGEN_DIR) not in sys.path:
    sys.path.insert(0, str(CODEGEN_DIR))

from tripose_codegen.evaluate import numeric_kernel  # noqa: E402


@functools.lru_cache(maxsize=None)
def family(family_module: str):
    """The spec's Family, built once per session (building derives every kernel of it)."""
    import importlib

    return importlib.import_module(f"tripose_codegen.specs.{family_module}").family()


@functools.lru_cache(maxsize=None)
def kernel(family_module: str, name: str):
    """The double-precision evaluation of one generated kernel (built once per session)."""
    for k in family(family_module).kernels:
        if k.name == name:
            return numeric_kernel(k)
    raise KeyError(name)


@pytest.fixture
def rng():
    return np.random.default_rng(20240611)


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def skew(x):
    return np.array([[0, -x[2], x[1]], [x[2], 0, -x[0]], [-x[1], x[0], 0]])


def pose_vector(R, t):
    """v = [r1; r2; r3; t] with r_i the columns of R."""
    return np.concatenate([R[:, 0], R[:, 1], R[:, 2], t])


def similarity(n):
    s, cx, cy = n
    return np.array([[s, 0, -s * cx], [0, s, -s * cy], [0, 0, 1.0]])


class Scene:
    """Three calibrated views, view 1 = [I|0], generic points and lines in front of them."""

    def __init__(self, rng):
        self.R12, self.t12 = random_rotation(rng), rng.normal(size=3)
        self.R, self.t = random_rotation(rng), rng.normal(size=3)
        # Keep the structure in front of all cameras: shift it along each optical axis.
        self.rng = rng

    def cameras(self):
        return [(np.eye(3), np.zeros(3)), (self.R12, self.t12), (self.R, self.t)]

    def point(self):
        X = self.rng.normal(size=3) + np.array([0, 0, 6.0])
        return X, [R @ X + t for R, t in self.cameras()]

    def line(self):
        A = self.rng.normal(size=3) + np.array([0, 0, 6.0])
        B = self.rng.normal(size=3) + np.array([0, 0, 6.0])
        lines = []
        for R, t in self.cameras():
            l = np.cross(R @ A + t, R @ B + t)
            lines.append(l / np.linalg.norm(l[:2]))
        return lines
