"""Line triplets (paper Sec. III-A): two rows of A per line, and the null space they need.

Derivation. The back-projected planes are pi1 = [l1; 0], pi2 = [R12^T l2; t12^T l2] and
pi3 = [R^T l3; t^T l3]; M = [pi1 pi2 pi3] has rank 2. The QR (Householder) elimination of the two
known columns leaves the two scalars q^T pi3 for q in an orthonormal basis {qa, qb} of the null
space of [pi1 pi2]^T (the last two columns of Q). Each row of A is the gradient of q^T pi3 with
respect to v = [r1; r2; r3; t]. Any orthonormal basis of that null space gives the same rows up to
a 2x2 rotation, hence the same A^T A and the same least-squares solution; lineNullSpace builds
one in closed form instead of running the Householder steps:
  n1 = l1, n2 = R12^T l2, d2 = t12.l2, d = n1 x n2 (direction of the 3D line), m = n1 x d,
  qa = [d; 0] / |d|,  qb = [d2 m; |d|^2] / (|d| sqrt(d2^2 |n1|^2 + |d|^2)),
using n2.m = -|d|^2 and |m| = |n1| |d|.
"""

import sympy

from ..spec import Family, Kernel
from .common import matrix, pose_columns

SPEC_PATH = "codegen/tripose_codegen/specs/line_rows.py"


def line_rows_kernel() -> Kernel:
    k = Kernel(
        name="lineRows",
        doc="""
        The two rows of A contributed by one line triplet (paper Sec. III-A, eqs. 1-3).

        For q in {qa, qb}, a homogeneous point of the 3D line defined by views 1 and 2, the
        constraint q^T pi3 = 0 with pi3 = [R^T l3; t^T l3] reads
            q[0] (r1.l3) + q[1] (r2.l3) + q[2] (r3.l3) + q[3] (t.l3) = 0,
        linear in v = [r1; r2; r3; t]. Row 0 is the row of qa, row 1 the row of qb:
            rows[12*i + 3*k + j] = q_i[k] * l3[j]   (k = 0..3, j = 0..2).
        """,
    )
    qa = k.input("qa", 4, "first point of the 3D line (null space of [pi1 pi2]^T)")
    qb = k.input("qb", 4, "second point of the 3D line (null space of [pi1 pi2]^T)")
    l3 = k.input("l3", 3, "the line in view 3, calibrated homogeneous (a, b, c)")
    v = sympy.symbols("v0:12", real=True)
    r1, r2, r3, t = pose_columns(v)
    R = sympy.Matrix.hstack(r1, r2, r3)
    pi3 = sympy.Matrix.vstack(R.T * sympy.Matrix(l3), t.T * sympy.Matrix(l3))
    rows = []
    for q in (qa, qb):
        constraint = sympy.expand((sympy.Matrix(q).T * pi3)[0])
        rows += [constraint.diff(vj) for vj in v]
    k.output("rows", rows, "2x12 row-major, the rows of qa and qb")
    return k


def line_null_space_kernel() -> Kernel:
    k = Kernel(
        name="lineNullSpace",
        doc="""
        An orthonormal basis {qa, qb} of the null space of [pi1 pi2]^T, where
        pi1 = [l1; 0] and pi2 = [R12^T l2; t12^T l2] are the planes back-projected from views 1
        and 2 (the two homogeneous points of their 3D line that lineRows needs).

        Closed form (equivalent to the last two columns of the Householder Q up to a 2x2
        rotation, which leaves A^T A unchanged): with n1 = l1, n2 = R12^T l2, d2 = t12.l2,
        d = n1 x n2 and m = n1 x d,
            qa = [d; 0] / |d|,   qb = [d2 m; |d|^2] / (|d| sqrt(d2^2 |n1|^2 + |d|^2)).
        qa is the line's point at infinity. Degenerate (division by zero) when d = 0, i.e. when
        the two planes are parallel: the line lies in an epipolar plane of views 1-2 and cannot be
        triangulated; callers reject such lines before calling.
        """,
    )
    l1 = sympy.Matrix(k.input("l1", 3, "the line in view 1, calibrated homogeneous (a, b, c)"))
    l2 = sympy.Matrix(k.input("l2", 3, "the line in view 2, calibrated homogeneous (a, b, c)"))
    R12 = matrix(k.input("R12", 9, "rotation of view 2, row-major"), 3, 3)
    t12 = sympy.Matrix(k.input("t12", 3, "translation of view 2"))
    n1 = l1
    n2 = (R12.T * l2).applyfunc(k.let)
    d2 = k.let(t12.dot(l2))
    d = n1.cross(n2).applyfunc(k.let)
    m = n1.cross(d).applyfunc(k.let)
    dd = k.let(d.dot(d))
    inv_d = k.let(1 / sympy.sqrt(dd))
    inv_b = k.let(inv_d / sympy.sqrt(d2 ** 2 * n1.dot(n1) + dd))
    qa = [d[0] * inv_d, d[1] * inv_d, d[2] * inv_d, sympy.S.Zero]
    qb = [d2 * inv_b * m[0], d2 * inv_b * m[1], d2 * inv_b * m[2], dd * inv_b]
    k.output("qa", qa, "unit 4-vector, the point at infinity of the line")
    k.output("qb", qb, "unit 4-vector orthogonal to qa")
    return k


def family() -> Family:
    return Family(
        stem="line_rows",
        title="Rows of A from line triplets (paper Sec. III-A).",
        doc="""
        v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
        """,
        spec_module=SPEC_PATH,
        kernels=[line_null_space_kernel(), line_rows_kernel()],
    )
