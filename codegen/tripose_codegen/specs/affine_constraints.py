"""Stereo rig: the quadrics of SO(3) in the coefficients of an affine kernel.

Derivation. With view 4 the system is A v = b, b != 0; with fewer independent rows than
unknowns its solutions are v = v0 + sum_k c_k e_k (v0 a particular solution, e_1..e_d a basis
of the kernel of A). The metric scale is fixed by b, so R = [r1 r2 r3] must be a rotation, not a
scaled one. Substituting r(c) = r0 + sum_k c_k E_k (the rotation parts of v0 and e_k) into
quadrics q(r) that vanish on SO(3) gives, per quadric, a row of C with
    C [c_k^2 (k = 1..d), c_k c_l (k < l), c_k (k = 1..d), 1]^T = 0,
read off the exact Taylor expansion of q at r0 (H its constant Hessian, g its gradient):
    c_k^2: E_k^T H E_k / 2,   c_k c_l: E_k^T H E_l,   c_k: g(r0).E_k,   1: q(r0).

Rows, in this order:
    0-5   the orthonormality of the columns (the six constraints of betaConstraintsN3, now with
          unit norms because the scale is known): r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1,
          |r3|^2 - 1;
    6-10  the orthonormality of the rows p_i of R (R R^T = I): p1.p2, p2.p3, p3.p1,
          |p1|^2 - 1, |p2|^2 - 1 (|p3|^2 - 1 is the sum of rows 3-5 minus rows 9-10, since
          trace(R^T R) = trace(R R^T));
    11-19 the handedness det R = +1 as cofactors: r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2 (three
          components each).
These 20 quadrics are linearly independent and vanish exactly on SO(3); rows 0-5 alone vanish on
O(3). On SO(3) the extra rows add nothing, but in the linearization, where each monomial of c is
an unknown, they add independent equations. The d (d + 3) / 2 non-constant monomials exceed the
six column constraints from d = 3 on; the twenty quadrics determine them up to d = 5 (20
monomials), and at d = 6 (27 monomials) leave the 8-dimensional space of a minimal problem.
The handedness rows also have linear terms when v0 = 0 (no view 4: the homogeneous three-view
system), so they fix the sign that the quadratic constraints leave open.
"""

import itertools
from typing import List

import sympy

from ..spec import Family, Kernel, join_doc
from .common import pose_columns

SPEC_PATH = "codegen/tripose_codegen/specs/affine_constraints.py"

DIMENSIONS = (1, 2, 3, 4, 5, 6)


def monomials(c: List[sympy.Symbol]) -> List[sympy.Expr]:
    """[c_k^2, c_k c_l (k < l, lexicographic), c_k, 1]."""
    squares = [ck ** 2 for ck in c]
    products = [a * b for a, b in itertools.combinations(c, 2)]
    return squares + products + list(c) + [sympy.S.One]


def column_constraints(r1, r2, r3) -> List[sympy.Expr]:
    """R^T R = I: [r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1]."""
    return [r1.dot(r2), r2.dot(r3), r3.dot(r1), r1.dot(r1) - 1, r2.dot(r2) - 1, r3.dot(r3) - 1]


def row_constraints(r1, r2, r3) -> List[sympy.Expr]:
    """R R^T = I without its last diagonal entry: [p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1]."""
    R = sympy.Matrix.hstack(r1, r2, r3)
    p = [R[i, :].T for i in range(3)]
    return [p[0].dot(p[1]), p[1].dot(p[2]), p[2].dot(p[0]), p[0].dot(p[0]) - 1, p[1].dot(p[1]) - 1]


def handedness_constraints(r1, r2, r3) -> List[sympy.Expr]:
    """[r1 x r2 - r3; r2 x r3 - r1; r3 x r1 - r2], nine components."""
    out = []
    for a, b, c in ((r1, r2, r3), (r2, r3, r1), (r3, r1, r2)):
        out += list(a.cross(b) - c)
    return out


def so3_quadrics(r1, r2, r3) -> List[sympy.Expr]:
    """The twenty rows of the module docstring, in order."""
    return (column_constraints(r1, r2, r3) + row_constraints(r1, r2, r3)
            + handedness_constraints(r1, r2, r3))


def taylor_coefficients(q: sympy.Expr, r, r0, E) -> List[sympy.Expr]:
    """Coefficients of q(r0 + sum_k c_k E[k]) on monomials(c), for q quadratic in the symbols r.
    The exact Taylor expansion at r0: with H the (constant) Hessian and g the gradient,
        c_k^2: E_k^T H E_k / 2,  c_k c_l: E_k^T H E_l,  c_k: g(r0).E_k,  1: q(r0);
    built term by term, which is far cheaper than expanding q in the 9 (d + 1) inputs."""
    H = sympy.hessian(q, r)
    at_r0 = dict(zip(r, r0))
    g0 = [q.diff(ri).xreplace(at_r0) for ri in r]
    nonzero = [(i, j, H[i, j]) for i in range(len(r)) for j in range(len(r)) if H[i, j] != 0]

    def bilinear(a, b):
        return sum(h * a[i] * b[j] for i, j, h in nonzero)

    d = len(E)
    squares = [bilinear(E[k], E[k]) / 2 for k in range(d)]
    products = [bilinear(E[k], E[l]) for k, l in itertools.combinations(range(d), 2)]
    linear = [sum(g0[i] * E[k][i] for i in range(len(r))) for k in range(d)]
    return [sympy.expand(x) for x in squares + products + linear + [q.xreplace(at_r0)]]


def _listing(d: int, term, sep: str) -> str:
    """term(1) sep term(2) ... with an ellipsis past three terms."""
    if d <= 3:
        return sep.join(term(k) for k in range(1, d + 1))
    return f"{term(1)}{sep}...{sep}{term(d)}"


def affine_constraints_kernel(d: int) -> Kernel:
    n = len(monomials(sympy.symbols(f"c1:{d + 1}")))
    combination = _listing(d, lambda j: f"c{j} e{j}", " + ")
    basis = _listing(d, lambda j: f"e{j}", "|")
    k = Kernel(
        name=f"affineConstraintsD{d}",
        doc=join_doc(f"""
        Affine kernel of dimension {d}: the twenty quadrics of SO(3) on
        v = v0 + {combination} as a 20x{n} matrix C with C m(c) = 0,
            m(c) = [c_k^2 (k = 1..{d}), c_k c_l (k < l, lexicographic), c_k (k = 1..{d}), 1].
        Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - 1, |r2|^2 - 1, |r3|^2 - 1 (the column
        orthonormality; these six alone are the constraints of betaConstraintsN3 with the scale
        fixed); p1.p2, p2.p3, p3.p1, |p1|^2 - 1, |p2|^2 - 1 (p_i the rows of R); the components
        of r1 x r2 - r3, r2 x r3 - r1, r3 x r1 - r2.
        """),
    )
    v0 = k.input("v0", 12, "particular solution of A v = b, [r1; r2; r3; t]")
    e = k.input("e", 12 * d, f"the kernel basis {basis} concatenated, each [r1; r2; r3; t]")
    # Only the rotation part enters the quadrics.
    E = [e[12 * j:12 * j + 9] for j in range(d)]
    r = sympy.symbols("r0:9")
    r1, r2, r3, _ = pose_columns(list(r) + [0, 0, 0])
    C = []
    for q in so3_quadrics(r1, r2, r3):
        C += taylor_coefficients(sympy.expand(q), r, v0[:9], E)
    k.output("C", C, f"20x{n} row-major, see the row and column order above")
    return k


def family() -> Family:
    return Family(
        stem="affine_constraints",
        title="Stereo rig: the quadrics of SO(3) in the coefficients of an affine kernel.",
        doc="""
        A v = b (views 3 and 4 of a stereo rig, b != 0) with a kernel of dimension d:
        v = v0 + sum_k c_k e_k, v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
        Rows 0-5 of every C are the column orthonormality with unit norms (the scale is fixed by
        b); rows 6-19 the row orthonormality and the handedness, with which C m(c) = 0 solved
        for the monomials as unknowns gives the pose for d <= 5, and d = 6 (six constraints,
        finitely many poses) becomes an eigenproblem (codegen/README.md, "Stereo rig").
        """,
        spec_module=SPEC_PATH,
        kernels=[affine_constraints_kernel(d) for d in DIMENSIONS],
    )
