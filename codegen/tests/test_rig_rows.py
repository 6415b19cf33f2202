import sys
from pathlib import Path

import numpy as np
import sympy

from conftest import kernel, pose_vector, random_rotation, similarity, skew
from tripose_codegen.spec import Kernel
from tripose_codegen.specs import point_rows
from tripose_codegen.specs import rig_rows as spec

# The stereo-rig prototype (a study beside the evaluation) holds the feature-count rule checked below.
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "test" / "evaluation" / "codegen"))


def random_similarity(rng):
    return np.array([rng.uniform(0.5, 3.0), rng.normal(), rng.normal()])


def view4(R12, t12, R, t):
    """P4 = [R12 R | R12 t + t12]."""
    return R12 @ R, R12 @ t + t12


def test_rig_line_rows_equal_point_on_plane_of_view_4(rng):
    rig_line_rows = kernel("rig_rows", "rigLineRows")
    for _ in range(20):
        qa, qb, l4 = rng.normal(size=4), rng.normal(size=4), rng.normal(size=3)
        R12, t12 = random_rotation(rng), rng.normal(size=3)
        R, t = rng.normal(size=(3, 3)), rng.normal(size=3)  # Any v: the rows are affine in it.
        out = rig_line_rows(qa=qa, qb=qb, l4=l4, R12=R12.ravel(), t12=t12)
        R4, t4 = view4(R12, t12, R, t)
        pi4 = np.concatenate([R4.T @ l4, [t4 @ l4]])
        residual = out["rows"].reshape(2, 12) @ pose_vector(R, t) - out["b"]
        np.testing.assert_allclose(residual, [qa @ pi4, qb @ pi4], rtol=1e-12, atol=1e-12)


def rig_trilinear_matrix(x1h, x2h, x4h, n1, n2, n4, R12, t12, R, t):
    """E4 = [x^2]x G M4(x1) H4^T [x^4]x with M4 built from P4 = [R12 R | R12 t + t12] directly."""
    F, G, H4 = similarity(n1), similarity(n2), similarity(n4)
    x1 = np.linalg.solve(F, np.append(x1h, 1.0))
    R4, t4 = view4(R12, t12, R, t)
    M4 = np.outer(R12 @ x1, t4) - np.outer(t12, R4 @ x1)
    return skew(np.append(x2h, 1.0)) @ G @ M4 @ H4.T @ skew(np.append(x4h, 1.0))


def test_rig_point_rows_equal_trilinear_entries_of_views_1_2_4(rng):
    rig_point_rows = kernel("rig_rows", "rigPointRows")
    for _ in range(20):
        x1, x2, x4 = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2)
        n1, n2, n4 = (random_similarity(rng) for _ in range(3))
        R12, t12 = random_rotation(rng), rng.normal(size=3)
        out = rig_point_rows(x1=x1, x2=x2, x4=x4, n1=n1, n2=n2, n4=n4, R12=R12.ravel(), t12=t12)
        rows, b = out["rows"].reshape(4, 12), out["b"]
        for _ in range(3):
            R, t = rng.normal(size=(3, 3)), rng.normal(size=3)
            E = rig_trilinear_matrix(x1, x2, x4, n1, n2, n4, R12, t12, R, t)
            expected = [-E[1, 1], E[1, 0], E[0, 1], -E[0, 0]]  # same entries as pointRows
            np.testing.assert_allclose(rows @ pose_vector(R, t) - b, expected, rtol=1e-12,
                                       atol=1e-12 * np.abs(E).max())


def test_factored_rig_point_rows_equal_normalized_tensor_of_view_4():
    """The kernel's factored form is identical to eqs. (8)-(12) with P3 replaced by P4."""
    k = Kernel(name="reference", doc="")
    x1, x2, x4 = (sympy.symbols(f"x{i}_0:2", real=True) for i in (1, 2, 4))
    n1, n2, n4 = (sympy.symbols(f"s{i} cx{i} cy{i}", positive=True) for i in (1, 2, 4))
    R12 = sympy.Matrix(3, 3, sympy.symbols("R12_0:9", real=True))
    t12 = sympy.Matrix(sympy.symbols("t12_0:3", real=True))
    v = sympy.symbols("v0:12", real=True)
    factored = spec.factored_rig_point_equations(k, x1, x2, x4, n1, n2, n4, R12, t12, v)
    lets = {}
    for s, e in k.lets:
        lets[s] = e.xreplace(lets)
    R4, t4 = spec.rig_pose(R12, t12, v)
    v4 = list(R4[:, 0]) + list(R4[:, 1]) + list(R4[:, 2]) + list(t4)
    That = point_rows.normalized_tensor(point_rows.trifocal_tensor(R12, t12, v4),
                                        point_rows.similarity(n1, inverse=True),
                                        point_rows.similarity(n2), point_rows.similarity(n4))
    literal = point_rows.trilinear_equations(x1, x2, x4, That)
    for f, l in zip(factored, literal):
        assert sympy.expand(f.xreplace(lets) - l) == 0


class RigScene:
    """Views 1-4 of a stereo rig, structure in front of all of them."""

    def __init__(self, rng):
        self.rng = rng
        self.R12, self.t12 = random_rotation(rng), rng.normal(size=3)
        self.R, self.t = random_rotation(rng), rng.normal(size=3)

    def cameras(self):
        return [(np.eye(3), np.zeros(3)), (self.R12, self.t12), (self.R, self.t),
                view4(self.R12, self.t12, self.R, self.t)]

    def v(self):
        return pose_vector(self.R, self.t)

    def point(self):
        X = self.rng.normal(size=3) + np.array([0, 0, 6.0])
        return [(R @ X + t)[:2] / (R @ X + t)[2] for R, t in self.cameras()]

    def line(self):
        A, B = (self.rng.normal(size=3) + np.array([0, 0, 6.0]) for _ in range(2))
        lines = [np.cross(R @ A + t, R @ B + t) for R, t in self.cameras()]
        return [l / np.linalg.norm(l[:2]) for l in lines]


def test_exact_rig_rows_hold_at_the_true_pose(rng):
    null_space = kernel("line_rows", "lineNullSpace")
    rig_line_rows = kernel("rig_rows", "rigLineRows")
    rig_point_rows = kernel("rig_rows", "rigPointRows")
    for _ in range(50):
        scene = RigScene(rng)
        v = scene.v()
        l1, l2, _, l4 = scene.line()
        q = null_space(l1=l1, l2=l2, R12=scene.R12.ravel(), t12=scene.t12)
        out = rig_line_rows(qa=q["qa"], qb=q["qb"], l4=l4, R12=scene.R12.ravel(), t12=scene.t12)
        rows = out["rows"].reshape(2, 12)
        scale = np.abs(rows).max() * np.abs(v).max()
        np.testing.assert_allclose(rows @ v, out["b"], rtol=0, atol=1e-12 * scale)
        assert np.linalg.matrix_rank(np.column_stack([rows, out["b"]]), tol=1e-8 * np.abs(rows).max()) == 2

        xs = scene.point()
        ns = [random_similarity(rng) for _ in range(4)]
        xh = [n[0] * (x - n[1:]) for x, n in zip(xs, ns)]
        out = rig_point_rows(x1=xh[0], x2=xh[1], x4=xh[3], n1=ns[0], n2=ns[1], n4=ns[3],
                             R12=scene.R12.ravel(), t12=scene.t12)
        rows = out["rows"].reshape(4, 12)
        augmented = np.column_stack([rows, -out["b"]])
        s = np.linalg.svd(augmented, compute_uv=False)
        np.testing.assert_allclose(rows @ v, out["b"], rtol=0, atol=1e-12 * s[0] * np.linalg.norm(v))
        # The rank fact of view 3 carries over: four equations, two independent.
        assert s[1] / s[0] > 1e-6
        assert s[2] / s[0] < 1e-12


def test_kernel_dimension_and_solution_count_match_numeric_ranks():
    """The prototype's kernel_dimension and solution_count (the counts the C++ solver will use)
    against the numeric ranks, exact data, every mix of up to four features (point or line, seen
    in views 3 and 4, in view 3 only or in view 4 only)."""
    import stereo_rig

    assert stereo_rig.check_counts(4, seeds=2) == []
