import numpy as np
import sympy

from conftest import Scene, kernel, pose_vector, similarity, skew
from tripose_codegen.spec import Kernel
from tripose_codegen.specs import point_rows as spec


def test_factored_form_equals_normalized_tensor_contraction():
    """The kernel's factored form is identical to eqs. (8)-(12) written with tensor indices."""
    k = Kernel(name="reference", doc="")
    x1, x2, x3 = (sympy.symbols(f"x{i}_0:2", real=True) for i in (1, 2, 3))
    n1, n2, n3 = (sympy.symbols(f"s{i} cx{i} cy{i}", positive=True) for i in (1, 2, 3))
    R12 = sympy.Matrix(3, 3, sympy.symbols("R12_0:9", real=True))
    t12 = sympy.Matrix(sympy.symbols("t12_0:3", real=True))
    v = sympy.symbols("v0:12", real=True)
    factored = spec.factored_equations(k, x1, x2, x3, n1, n2, n3, R12, t12, v)
    lets = {}
    for s, e in k.lets:
        lets[s] = e.xreplace(lets)
    That = spec.normalized_tensor(spec.trifocal_tensor(R12, t12, v),
                                  spec.similarity(n1, inverse=True),
                                  spec.similarity(n2), spec.similarity(n3))
    literal = spec.trilinear_equations(x1, x2, x3, That)
    for f, l in zip(factored, literal):
        assert sympy.expand(f.xreplace(lets) - l) == 0


def trilinear_matrix(x1h, x2h, x3h, n1, n2, n3, R12, t12, R, t):
    """E = [x^2]x G ((R12 x1) t^T - t12 (R x1)^T) H^T [x^3]x, x1 = F^-1 x^1 (homogeneous)."""
    F, G, H = similarity(n1), similarity(n2), similarity(n3)
    x1 = np.linalg.solve(F, np.append(x1h, 1.0))
    M = np.outer(R12 @ x1, t) - np.outer(t12, R @ x1)
    return skew(np.append(x2h, 1.0)) @ G @ M @ H.T @ skew(np.append(x3h, 1.0))


def random_similarity(rng):
    return np.array([rng.uniform(0.5, 3.0), rng.normal(), rng.normal()])


def test_point_rows_equal_normalized_trilinear_matrix_entries(rng):
    point_rows = kernel("point_rows", "pointRows")
    for _ in range(20):
        x1, x2, x3 = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2)
        n1, n2, n3 = (random_similarity(rng) for _ in range(3))
        R12, t12 = rng.normal(size=(3, 3)), rng.normal(size=3)
        rows = point_rows(x1=x1, x2=x2, x3=x3, n1=n1, n2=n2, n3=n3,
                          R12=R12.ravel(), t12=t12)["rows"]
        rows = rows.reshape(4, 12)
        # Entry j of each row is the equation at v = e_j (the equations are linear in v).
        for j in range(12):
            e = np.zeros(12)
            e[j] = 1.0
            R, t = e[:9].reshape(3, 3).T, e[9:]
            E = trilinear_matrix(x1, x2, x3, n1, n2, n3, R12, t12, R, t)
            expected = [-E[1, 1], E[1, 0], E[0, 1], -E[0, 0]]  # eqs. (9)-(12)
            np.testing.assert_allclose(rows[:, j], expected, rtol=1e-12, atol=1e-12 * np.abs(E).max())


def exact_point_rows(rng, scene):
    point_rows = kernel("point_rows", "pointRows")
    X, xs = scene.point()
    xs = [x[:2] / x[2] for x in xs]
    ns = [random_similarity(rng) for _ in range(3)]
    xh = [n[0] * (x - n[1:]) for x, n in zip(xs, ns)]
    rows = point_rows(x1=xh[0], x2=xh[1], x3=xh[2], n1=ns[0], n2=ns[1], n3=ns[2],
                      R12=scene.R12.ravel(), t12=scene.t12)["rows"]
    return rows.reshape(4, 12)


def test_point_rows_have_rank_two_with_exact_data(rng):
    """The rank fact of the method notes: 4 equations per point, only 2 independent."""
    for _ in range(50):
        scene = Scene(rng)
        rows = exact_point_rows(rng, scene)
        s = np.linalg.svd(rows, compute_uv=False)
        assert s[1] / s[0] > 1e-6
        assert s[2] / s[0] < 1e-12
        v = pose_vector(scene.R, scene.t)
        np.testing.assert_allclose(rows @ v, 0, atol=1e-12 * s[0] * np.linalg.norm(v))


def test_kernel_dimension_is_twelve_minus_two_per_feature(rng):
    null_space = kernel("line_rows", "lineNullSpace")
    line_rows = kernel("line_rows", "lineRows")
    for points, lines in [(4, 0), (0, 4), (2, 2), (3, 1), (1, 3), (6, 0), (3, 3), (0, 6), (4, 2), (5, 0), (2, 3)]:
        scene = Scene(rng)
        A = [exact_point_rows(rng, scene) for _ in range(points)]
        for _ in range(lines):
            l1, l2, l3 = scene.line()
            q = null_space(l1=l1, l2=l2, R12=scene.R12.ravel(), t12=scene.t12)
            A.append(line_rows(qa=q["qa"], qb=q["qb"], l3=l3)["rows"].reshape(2, 12))
        A = np.vstack(A)
        s = np.linalg.svd(A, compute_uv=False)
        rank = int(np.sum(s > 1e-10 * s[0]))
        # The true pose is always in the kernel, so the rank is at most 11.
        assert rank == min(2 * (points + lines), 11), (points, lines, s)
