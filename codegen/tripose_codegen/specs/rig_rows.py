"""Stereo rig (views 3 and 4 at time B): the rows that view 4 adds, affine in v.

Set-up. View 1 = left camera at time A, [I|0]; view 2 = right camera at time A, the known rig
[R12|t12]; view 3 = left camera at time B, [R|t], unknown; view 4 = right camera at time B,
    P4 = [R12 R | R12 t + t12].
P4 is affine in v = [r1; r2; r3; t]: its linear part is P3 seen through R12, its constant part
the rig translation t12. Every equation a feature gives in view 4 therefore reads
    rows . v = b
with a non-zero right-hand side b, and the metric scale comes from b, not from the norms of R.

Lines. With {qa, qb} the two homogeneous points of the 3D line from views 1 and 2 (the basis
lineNullSpace gives, unchanged), the back-projected plane of view 4 is
    pi4 = P4^T l4 = [R^T (R12^T l4); t^T (R12^T l4) + t12^T l4],
so with l4' = R12^T l4 each point q gives
    q^T pi4 = q[0] (r1.l4') + q[1] (r2.l4') + q[2] (r3.l4') + q[3] (t.l4') + q[3] (t12.l4) = 0:
the row of lineRows for the line l4' and the right-hand side b = -q[3] (t12.l4).

Points. The view-3 rows (point_rows.py) are the entries of
    E = [x^2]x G M(x1) H^T [x^3]x,   M(x) = (R12 x) t^T - t12 (R x)^T,   x1 = F^-1 x^1,
the trilinearity of views 1, 2, 3 after Hartley normalization. Views 1, 2, 4 have the same
tensor form with P3 replaced by P4, i.e. t -> R12 t + t12 and R -> R12 R:
    M4(x) = (R12 x) (R12 t + t12)^T - t12 (R12 R x)^T = M(x) R12^T + (R12 x) t12^T,
    E4 = [x^2]x G M4(x1) H4^T [x^4]x,
H4 the normalizing similarity of view 4; the equations are the same four entries of E4 as those
of E for view 3. M(x1) R12^T is linear in v, (R12 x1) t12^T is constant. In the factored
form of point_rows.py, with g_a = G^T (e_a - x^2_a e_3) and h_b = H4^T (e_b - x^4_b e_3),
    e(a, b) = (g_a.R12 x1) (h_b.(R12 t + t12)) - (g_a.t12) (h_b.(R12 R x1))
            = [(g_a.R12 x1) ((R12^T h_b).t) - (g_a.t12) ((R12^T h_b).(R x1))]
              + (g_a.R12 x1) (h_b.t12):
the view-3 equation with h_b replaced by R12^T h_b, plus the constant (g_a.R12 x1)(h_b.t12). Rows
are the gradients with respect to v, b the negated constant.
"""

import sympy

from ..spec import Family, Kernel
from .common import matrix, pose_columns
from .point_rows import similarity

SPEC_PATH = "codegen/tripose_codegen/specs/rig_rows.py"


def rig_pose(R12: sympy.Matrix, t12: sympy.Matrix, v):
    """(R4, t4) = (R12 R, R12 t + t12), the pose of view 4 as affine functions of v."""
    r1, r2, r3, t = pose_columns(v)
    R = sympy.Matrix.hstack(r1, r2, r3)
    return R12 * R, R12 * t + t12


def rig_line_equations(qa, qb, l4, R12, t12, v):
    """q^T pi4 for q in {qa, qb}, pi4 = [R4^T l4; t4^T l4] (the literal form, for tests)."""
    R4, t4 = rig_pose(R12, t12, v)
    l4 = sympy.Matrix(l4)
    pi4 = list(R4.T * l4) + [t4.dot(l4)]
    return [sum(q[i] * pi4[i] for i in range(4)) for q in (qa, qb)]


def factored_rig_point_equations(k, x1, x2, x4, n1, n2, n4, R12, t12, v):
    """The trilinear equations of views 1, 2, 4 in the factored form of point_rows.py with
    P3 = [R|t] replaced by P4 = [R12 R | R12 t + t12], with R12^T h_b staged so that the linear
    part costs what the view-3 rows cost:
        e(a, b) = (g_a.R12 x1) ((R12^T h_b).t + h_b.t12) - (g_a.t12) ((R12^T h_b).(R x1)),
    g_a = G^T (e_a - x^2_a e_3), h_b = H4^T (e_b - x^4_b e_3), x1 = F^-1 x^1 (homogeneous)."""
    r1, r2, r3, t = pose_columns(v)
    R = sympy.Matrix.hstack(r1, r2, r3)
    X1 = similarity(n1, inverse=True) * sympy.Matrix(list(x1) + [1])
    X1 = X1.applyfunc(k.let)
    R12x1 = (R12 * X1).applyfunc(k.let)
    G, H4 = similarity(n2), similarity(n4)
    e = sympy.eye(3)
    g = [(G.T * (e[:, a] - x2[a] * e[:, 2])).applyfunc(k.let) for a in range(2)]
    h = [(H4.T * (e[:, b] - x4[b] * e[:, 2])).applyfunc(k.let) for b in range(2)]
    R12h = [(R12.T * hb).applyfunc(k.let) for hb in h]
    ht12 = [k.let(hb.dot(t12)) for hb in h]
    equations = []
    for a in range(2):
        gR12x1 = k.let(g[a].dot(R12x1))
        gt12 = k.let(g[a].dot(t12))
        for b in range(2):
            equations.append(gR12x1 * (R12h[b].dot(t) + ht12[b]) - gt12 * R12h[b].dot(R * X1))
    return equations


def affine_rows(equations, v):
    """(rows, b) of equations affine in v: equation = rows . v - b."""
    rows, rhs = [], []
    zero = {vj: 0 for vj in v}
    for equation in equations:
        rows += [equation.diff(vj) for vj in v]
        rhs.append(-sympy.expand(equation).xreplace(zero))
    return rows, rhs


def rig_line_rows_kernel() -> Kernel:
    k = Kernel(
        name="rigLineRows",
        doc="""
        The two rows of A and entries of b contributed by a line seen in view 4 (the right camera
        at time B, P4 = [R12 R | R12 t + t12]): the points qa, qb of the 3D line from views 1 and 2
        project onto l4, q^T P4^T l4 = 0. With l4' = R12^T l4,
            q[0] (r1.l4') + q[1] (r2.l4') + q[2] (r3.l4') + q[3] (t.l4') = -q[3] (t12.l4),
        i.e. rows . v = b with
            rows[12*i + 3*k + j] = q_i[k] * l4'[j]   (k = 0..3, j = 0..2),
            b[i] = -q_i[3] * (t12.l4),
        row 0 for qa, row 1 for qb. qa, qb and (R12, t12) are those of lineNullSpace; the rows of
        view 3 (lineRows) are the same with l4' -> l3 and b = 0.
        """,
    )
    qa = k.input("qa", 4, "first point of the 3D line (lineNullSpace)")
    qb = k.input("qb", 4, "second point of the 3D line (lineNullSpace)")
    l4 = k.input("l4", 3, "the line in view 4, calibrated homogeneous (a, b, c)")
    R12 = matrix(k.input("R12", 9, "rotation of the rig (view 2), row-major"), 3, 3)
    t12 = sympy.Matrix(k.input("t12", 3, "translation of the rig (view 2)"))
    l4p = (R12.T * sympy.Matrix(l4)).applyfunc(k.let)
    t12l4 = k.let(t12.dot(sympy.Matrix(l4)))
    v = sympy.symbols("v0:12", real=True)
    r1, r2, r3, t = pose_columns(v)
    equations = [q[0] * r1.dot(l4p) + q[1] * r2.dot(l4p) + q[2] * r3.dot(l4p) + q[3] * t.dot(l4p)
                 + q[3] * t12l4 for q in (qa, qb)]
    rows, rhs = affine_rows(equations, v)
    k.output("rows", rows, "2x12 row-major, the rows of qa and qb")
    k.output("b", rhs, "2 right-hand sides, rows . v = b")
    return k


def rig_point_rows_kernel() -> Kernel:
    k = Kernel(
        name="rigPointRows",
        doc="""
        The four rows of A and entries of b contributed by a point seen in view 4 (the right
        camera at time B, P4 = [R12 R | R12 t + t12]): the trilinearity of views 1, 2, 4, Hartley-
        normalized exactly as pointRows normalizes views 1, 2, 3, with P3 replaced by P4.

        With M(x) = (R12 x) t^T - t12 (R x)^T, x1 = F^-1 x^1 (homogeneous) and H4 the normalizing
        similarity of view 4, the equations are the entries -E(2,2), E(2,1), E(1,2), -E(1,1)
        (1-based) of
            E = [x^2]x G M4(x1) H4^T [x^4]x,   M4(x) = M(x) R12^T + (R12 x) t12^T,
        M4 being M of P4 = [R12 R | R12 t + t12]. The part M(x1) R12^T is linear in v (rows); the
        part (R12 x1) t12^T is constant, and b is minus its share of the four entries:
        rows . v = b.
        With exact data [rows | b] has rank 2. A point seen in views 3 and 4 gives 3 independent
        equations with pointRows, not 4: both views together triangulate it at time B, and the
        fourth equation is their epipolar constraint, which exact data satisfies anyway.
        """,
    )
    x1 = k.input("x1", 2, "Hartley-normalized calibrated point in view 1, x^ = s (x - c)")
    x2 = k.input("x2", 2, "Hartley-normalized calibrated point in view 2")
    x4 = k.input("x4", 2, "Hartley-normalized calibrated point in view 4")
    n1 = k.input("n1", 3, "normalizing similarity F of view 1 as (s, cx, cy)")
    n2 = k.input("n2", 3, "normalizing similarity G of view 2 as (s, cx, cy)")
    n4 = k.input("n4", 3, "normalizing similarity H4 of view 4 as (s, cx, cy)")
    R12 = matrix(k.input("R12", 9, "rotation of the rig (view 2), row-major"), 3, 3)
    t12 = sympy.Matrix(k.input("t12", 3, "translation of the rig (view 2)"))
    v = sympy.symbols("v0:12", real=True)
    equations = factored_rig_point_equations(k, x1, x2, x4, n1, n2, n4, R12, t12, v)
    rows, rhs = affine_rows(equations, v)
    k.output("rows", rows, "4x12 row-major, the view-4 analogues of eqs. (9)-(12)")
    k.output("b", rhs, "4 right-hand sides, rows . v = b")
    return k


def family() -> Family:
    return Family(
        stem="rig_rows",
        title="Rows of A v = b from view 4 of a stereo rig (the right camera at time B).",
        doc="""
        Views: 1 = [I|0] and 2 = [R12|t12] (the rig, known) at time A; 3 = [R|t] (unknown) and
        4 = [R12 R | R12 t + t12] at time B. v = [r1; r2; r3; t] (r_i: the columns of R), matrices
        row-major. View 3 contributes the homogeneous rows of lineRows / pointRows; view 4 the
        affine rows below, so that A v = b with b != 0 fixes the metric scale.
        """,
        spec_module=SPEC_PATH,
        kernels=[rig_line_rows_kernel(), rig_point_rows_kernel()],
    )
