#!/usr/bin/env python3
"""Measurements behind the N = 4 design choice (reported in doc/studies/accuracy.md,
"The N = 4 null vector").

Compares ways to obtain the null vector u(b3) of the 5x6 matrix of eq. (24):
  staged      the generated kernel: matrix coefficients expanded in v, minors by a memoized
              cofactor expansion with exact polynomial arithmetic in b3 (what generate.py emits);
  expanded    every coefficient of u expanded as a polynomial in the 50 matrix coefficients
              (symengine), then common-subexpression elimination;
  in v        minors expanded directly in the 48 entries of v (term counts of 2x2 and 3x3 minors:
              the 5x5 ones exhaust memory);
  numeric     5x5 determinants by LU at 5 Chebyshev values of b3, then interpolation.
Accuracy: relative error of u's coefficients against a 50-digit evaluation of the same program,
over random orthonormal kernel vectors (as an SVD returns them).

    .venv/bin/python test/evaluation/codegen/measure_n4.py [--skip-expanded]
"""

import argparse
import itertools
import sys
import time
from pathlib import Path

import mpmath
import numpy as np
import symengine
import sympy

# The generator the measured kernels come from.
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "codegen"))

from tripose_codegen.cse import build_program, program_op_count  # noqa: E402
from tripose_codegen.evaluate import compile_program  # noqa: E402
from tripose_codegen.spec import Kernel  # noqa: E402
from tripose_codegen.specs import beta_n4  # noqa: E402


def timed(fn):
    start = time.perf_counter()
    result = fn()
    return result, time.perf_counter() - start


def staged():
    kernel, t_spec = timed(beta_n4.null_vector_kernel)
    program, t_cse = timed(lambda: build_program(kernel))
    return kernel, program, t_spec + t_cse


def expanded_in_matrix_coefficients():
    """u's coefficients as expanded polynomials in the 50 matrix coefficients."""
    m = [[[sympy.Symbol(f"m{r}_{c}_{d}") for d in range(beta_n4.COLUMN_DEGREES[c] + 1)]
          for c in range(6)] for r in range(5)]
    x = symengine.Symbol("x")
    start = time.perf_counter()
    entries = [[sum(symengine.sympify(coef) * x ** d for d, coef in enumerate(m[r][c])) for c in range(6)]
               for r in range(5)]
    coefficients = []
    for i in range(6):
        cols = [c for c in range(6) if c != i]
        # Leibniz formula: no divisions, so the expansion stays polynomial.
        det = 0
        for perm in itertools.permutations(range(5)):
            sign = -1 if sum(perm[a] > perm[b] for a in range(5) for b in range(a + 1, 5)) % 2 else 1
            term = sign
            for r in range(5):
                term = term * entries[r][cols[perm[r]]]
            det += term
        det = symengine.expand(det)
        coefficients += [sympy.sympify((-1) ** i * det.coeff(x, d))
                         for d in range(beta_n4.NULL_VECTOR_DEGREES[i] + 1)]
    t_expand = time.perf_counter() - start
    terms = sum(len(sympy.Add.make_args(c)) for c in coefficients)
    k = Kernel(name="expanded", doc="")
    k.output("u", coefficients, "")
    program, t_cse = timed(lambda: build_program(k))
    return terms, program_op_count(program), t_expand, t_cse


def expanded_in_v_term_count():
    """Terms of the leading 2x2 and 3x3 minors of the constant block of the 5x6 matrix, expanded
    in v's 48 entries (the full 5x5 minors do not fit in memory when expanded this way)."""
    k = Kernel(name="v", doc="")
    vs = [k.input(f"v{j}", 12, "") for j in range(4)]
    M = beta_n4.matrix_coefficients(*vs)
    counts = []
    start = time.perf_counter()
    for n in (2, 3):
        mat = symengine.Matrix(n, n, [symengine.sympify(M[r][c][0]) for r in range(n) for c in range(n)])
        counts.append(len(symengine.expand(mat.det()).args))
    return counts, time.perf_counter() - start


def numeric_interpolation(v):
    """u by LU determinants at 5 Chebyshev nodes of b3 in [-2, 2], then interpolation."""
    vs = v.reshape(4, 12)

    def bilinear(a, b):
        d = lambda i, j: a[3 * i:3 * i + 3] @ b[3 * j:3 * j + 3]
        return np.array([0.5 * (d(0, 1) + d(1, 0)), 0.5 * (d(1, 2) + d(2, 1)), 0.5 * (d(2, 0) + d(0, 2)),
                         d(0, 0) - d(1, 1), d(1, 1) - d(2, 2)])

    nodes = 2 * np.cos((2 * np.arange(5) + 1) * np.pi / 10)
    values = np.zeros((6, 5))
    for k, b3 in enumerate(nodes):
        w = b3 * vs[2] + vs[3]
        A = np.column_stack([bilinear(vs[0], vs[0]), bilinear(vs[1], vs[1]), 2 * bilinear(vs[0], vs[1]),
                             2 * bilinear(vs[0], w), 2 * bilinear(vs[1], w), bilinear(w, w)])
        for i in range(6):
            values[i, k] = (-1) ** i * np.linalg.det(np.delete(A, i, axis=1))
    V = np.vander(nodes, 5, increasing=True)
    coefficients = np.linalg.solve(V, values.T).T  # 6 x 5, ascending
    return np.concatenate([coefficients[i, :d + 1] for i, d in enumerate(beta_n4.NULL_VECTOR_DEGREES)])


def accuracy(program, trials=200):
    mpmath.mp.dps = 50
    run_double = compile_program(program)
    run_exact = compile_program(program, sqrt=mpmath.sqrt)
    rng = np.random.default_rng(7)
    err_staged, err_numeric = [], []
    for _ in range(trials):
        q = np.linalg.qr(rng.normal(size=(12, 4)))[0]  # Orthonormal kernel vectors.
        v = q.T.ravel()
        ref = np.array([float(x) for x in run_exact(v=[mpmath.mpf(float(e)) for e in v])["u"]])
        got = np.array(run_double(v=[float(e) for e in v])["u"], dtype=float)
        err_staged.append(np.abs(got - ref).max() / np.abs(ref).max())
        err_numeric.append(np.abs(numeric_interpolation(v) - ref).max() / np.abs(ref).max())
    return np.median(err_staged), np.max(err_staged), np.median(err_numeric), np.max(err_numeric)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--skip-expanded", action="store_true")
    args = parser.parse_args()

    kernel, program, t = staged()
    print(f"staged:   {program_op_count(program)}  generation {t:.2f} s")
    e = accuracy(program)
    print(f"accuracy (max |du| / max |u|, 200 random orthonormal v): staged median {e[0]:.1e} max {e[1]:.1e}; "
          f"numeric interpolation median {e[2]:.1e} max {e[3]:.1e}")
    (t2, t3), t = expanded_in_v_term_count()
    print(f"in v:     a 2x2 minor expands to {t2} terms, a 3x3 minor to {t3} terms ({t:.1f} s)")
    if not args.skip_expanded:
        terms, ops, t_expand, t_cse = expanded_in_matrix_coefficients()
        print(f"expanded: {terms} terms; after CSE {ops}; expansion {t_expand:.1f} s, CSE {t_cse:.1f} s")


if __name__ == "__main__":
    main()
