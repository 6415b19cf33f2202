"""Symbolic building blocks shared by the specs."""

from typing import List, Sequence

import symengine
import sympy


def matrix(symbols: Sequence[sympy.Expr], rows: int, cols: int) -> sympy.Matrix:
    """A row-major flat array as a sympy Matrix."""
    return sympy.Matrix(rows, cols, list(symbols))


def pose_columns(v: Sequence[sympy.Expr]):
    """(r1, r2, r3, t) of v = [r1; r2; r3; t] as 3x1 matrices (r_i: the columns of R)."""
    return [sympy.Matrix(v[3 * k:3 * k + 3]) for k in range(4)]


def rotation_constraints(r1, r2, r3) -> List[sympy.Expr]:
    """The quadrics on the columns of R: orthogonality and the squared norms,
    [r1.r2, r2.r3, r3.r1, |r1|^2, |r2|^2, |r3|^2]."""
    return [r1.dot(r2), r2.dot(r3), r3.dot(r1), r1.dot(r1), r2.dot(r2), r3.dot(r3)]


def homogeneous_constraints(r1, r2, r3) -> List[sympy.Expr]:
    """The five homogeneous quadrics of a scaled rotation:
    [r1.r2, r2.r3, r3.r1, |r1|^2 - |r2|^2, |r2|^2 - |r3|^2]."""
    c = rotation_constraints(r1, r2, r3)
    return c[:3] + [c[3] - c[4], c[4] - c[5]]


def coefficients(expr: sympy.Expr, monomials: Sequence[sympy.Expr], variables: Sequence[sympy.Symbol]):
    """Coefficients of @p expr, a polynomial in @p variables, on @p monomials (which must cover
    every monomial of expr). The expansion is done by symengine, which is much faster than sympy
    on these sizes; the coefficients come back as sympy expressions."""
    expanded = symengine.expand(symengine.sympify(expr))
    poly = sympy.Poly(sympy.sympify(expanded), *variables)
    terms = dict(poly.terms())
    out = []
    for m in monomials:
        key = sympy.Poly(m, *variables).monoms()[0]
        out.append(terms.pop(key, sympy.S.Zero))
    if any(c != 0 for c in terms.values()):
        raise ValueError(f"monomials not covered: {sorted(terms)}")
    return out
