"""Point triplets (paper Sec. III-B): four rows of A per point, eqs. (9)-(12).

Derivation. With P1 = [I|0], P2 = [a1 a2 a3 a4] = [R12|t12] and P3 = [b1 b2 b3 b4] = [R|t], the
trifocal tensor is T_i^{jk} = a_i^j b_4^k - a_4^j b_i^k, linear in v = [r1; r2; r3; t]. Hartley
normalization x^ = F x1, G x2, H x3 transforms it by eq. (8),
    T^_i^{jk} = (F^-1)^r_i G^j_s H^k_t T_r^{st},
and eqs. (9)-(12) contract T^ with the normalized points. Each row of A is the gradient of one
equation with respect to v (the equations are linear in v).
"""

import sympy

from ..spec import Family, Kernel
from .common import matrix, pose_columns

SPEC_PATH = "codegen/tripose_codegen/specs/point_rows.py"


def similarity(n, inverse=False) -> sympy.Matrix:
    """F = [s 0 -s*cx; 0 s -s*cy; 0 0 1] for n = (s, cx, cy), or its inverse."""
    s, cx, cy = n
    if inverse:
        return sympy.Matrix([[1 / s, 0, cx], [0, 1 / s, cy], [0, 0, 1]])
    return sympy.Matrix([[s, 0, -s * cx], [0, s, -s * cy], [0, 0, 1]])


def trifocal_tensor(R12: sympy.Matrix, t12: sympy.Matrix, v):
    """T[r][s][t] = a_r^s b_4^t - a_4^s b_r^t (zero-based indices, r = 0..2)."""
    a = [R12[:, 0], R12[:, 1], R12[:, 2], t12]
    b = pose_columns(v)
    return [[[a[r][s] * b[3][t] - a[3][s] * b[r][t] for t in range(3)] for s in range(3)]
            for r in range(3)]


def normalized_tensor(T, Finv, G, H):
    """Eq. (8): T^_i^{jk} = sum_{r,s,t} (F^-1)_{ri} G_{js} H_{kt} T_r^{st}."""
    return [[[sum(Finv[r, i] * G[j, s] * H[k, t] * T[r][s][t]
                  for r in range(3) for s in range(3) for t in range(3))
              for k in range(3)] for j in range(3)] for i in range(3)]


def trilinear_equations(x1, x2, x3, That):
    """Eqs. (9)-(12) in this order: (i, l) = (1,1), (1,2), (2,1), (2,2) in the paper's 1-based
    indices, with x^_1 = (x1[0], x1[1], 1) and likewise for views 2 and 3."""
    X1 = list(x1) + [1]
    X2 = list(x2) + [1]
    X3 = list(x3) + [1]
    equations = []
    for i in range(2):
        for l in range(2):
            equations.append(sum(
                X1[k] * (X2[i] * X3[l] * That[k][2][2] - X3[l] * That[k][i][2]
                         - X2[i] * That[k][2][l] + That[k][i][l])
                for k in range(3)))
    return equations


def factored_equations(k, x1, x2, x3, n1, n2, n3, R12, t12, v):
    """Eqs. (9)-(12) in the factored form the kernel evaluates (tests check that it equals
    trilinear_equations(normalized_tensor(...)) identically):
        e(a, b) = (G^T alpha_a)^T M(F^-1 x^1) (H^T beta_b),  M(x) = (R12 x) t^T - t12 (R x)^T,
    with alpha_a = e_a - x^2^a e_3, beta_b = e_b - x^3^b e_3 (zero-based a, b in {0, 1}).
    Eq. (8) gives sum_k x^1^k T^_k = G (sum_r x1^r T_r) H^T with x1 = F^-1 x^1, and
    sum_r x1^r T_r = M(x1); the bracket of eqs. (9)-(12) is alpha_a^T (.) beta_b.
    Staged intermediates of @p k keep the products shared instead of expanded."""
    r1, r2, r3, t = pose_columns(v)
    R = sympy.Matrix.hstack(r1, r2, r3)
    X1 = similarity(n1, inverse=True) * sympy.Matrix(list(x1) + [1])
    X1 = X1.applyfunc(k.let)
    R12x1 = (R12 * X1).applyfunc(k.let)
    G, H = similarity(n2), similarity(n3)
    e = sympy.eye(3)
    g = [(G.T * (e[:, a] - x2[a] * e[:, 2])).applyfunc(k.let) for a in range(2)]
    h = [(H.T * (e[:, b] - x3[b] * e[:, 2])).applyfunc(k.let) for b in range(2)]
    equations = []
    for a in range(2):
        gR12x1 = k.let(g[a].dot(R12x1))
        gt12 = k.let(g[a].dot(t12))
        for b in range(2):
            equations.append(gR12x1 * h[b].dot(t) - gt12 * h[b].dot(R * X1))
    return equations


def point_rows_kernel() -> Kernel:
    k = Kernel(
        name="pointRows",
        doc="""
        The four rows of A contributed by one point triplet (paper Sec. III-B, eqs. 8-12).

        With P2 = [a1 a2 a3 a4] = [R12|t12], P3 = [b1 b2 b3 b4] = [R|t], the trifocal tensor
        T_i^{jk} = a_i^j b_4^k - a_4^j b_i^k and the normalized tensor (eq. 8)
            T^_i^{jk} = (F^-1)^r_i G^j_s H^k_t T_r^{st},
        row e (e = 0..3 for eqs. 9..12, (a, b) = (1,1), (1,2), (2,1), (2,2)) holds the coefficients
        on v = [r1; r2; r3; t] of
            x^1^k (x^2^a x^3^b T^_k^33 - x^3^b T^_k^a3 - x^2^a T^_k^3b + T^_k^ab) = 0,
        x^_j the normalized points with third coordinate 1. Equivalently, with
        M(x) = (R12 x) t^T - t12 (R x)^T and x1 = F^-1 x^1 (homogeneous), the equations are the
        entries -E(2,2), E(2,1), E(1,2), -E(1,1) of E = [x^2]x G M(x1) H^T [x^3]x (1-based).
        With exact data the four rows have rank 2.
        """,
    )
    x1 = k.input("x1", 2, "Hartley-normalized calibrated point in view 1, x^ = s (x - c)")
    x2 = k.input("x2", 2, "Hartley-normalized calibrated point in view 2")
    x3 = k.input("x3", 2, "Hartley-normalized calibrated point in view 3")
    n1 = k.input("n1", 3, "normalizing similarity F of view 1 as (s, cx, cy)")
    n2 = k.input("n2", 3, "normalizing similarity G of view 2 as (s, cx, cy)")
    n3 = k.input("n3", 3, "normalizing similarity H of view 3 as (s, cx, cy)")
    R12 = matrix(k.input("R12", 9, "rotation of view 2, row-major"), 3, 3)
    t12 = sympy.Matrix(k.input("t12", 3, "translation of view 2"))
    v = sympy.symbols("v0:12", real=True)
    rows = []
    for equation in factored_equations(k, x1, x2, x3, n1, n2, n3, R12, t12, v):
        rows += [equation.diff(vj) for vj in v]
    k.output("rows", rows, "4x12 row-major, eqs. (9)-(12)")
    return k


def family() -> Family:
    return Family(
        stem="point_rows",
        title="Rows of A from point triplets (paper Sec. III-B).",
        doc="""
        v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
        """,
        spec_module=SPEC_PATH,
        kernels=[point_rows_kernel()],
    )
