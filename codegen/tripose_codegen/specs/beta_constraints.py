"""Quadrics in the kernel coefficients beta (paper Sec. III-D, cases N = 2 and N = 3).

Derivation. Substituting v = sum_k beta_k v_k into the constraints on the columns of R,
orthogonality r1.r2 = r2.r3 = r3.r1 = 0 and equal norms |r1|^2 - |r2|^2 = |r2|^2 - |r3|^2 = 0
(N = 2) or unit norms |r_i|^2 = 1 (N = 3), gives quadratic forms in beta; their coefficients on
the quadratic monomials are read off after expansion.
"""

import sympy

from ..spec import Family, Kernel
from .common import coefficients, homogeneous_constraints, pose_columns, rotation_constraints

SPEC_PATH = "codegen/tripose_codegen/specs/beta_constraints.py"


def combination(vectors, betas):
    return [sum(b * vec[i] for b, vec in zip(betas, vectors)) for i in range(12)]


def beta_n2_kernel() -> Kernel:
    k = Kernel(
        name="betaConstraintsN2",
        doc="""
        N = 2: the five homogeneous constraints on v = b1 v1 + b2 v2 (paper eq. 19) as a 5x3
        matrix C with C [b1^2, b2^2, b1 b2]^T = 0.
        Rows: r1.r2, r2.r3, r3.r1, |r1|^2 - |r2|^2, |r2|^2 - |r3|^2; columns: b1^2, b2^2, b1 b2.
        """,
    )
    v1 = k.input("v1", 12, "first kernel vector [r1; r2; r3; t]")
    v2 = k.input("v2", 12, "second kernel vector [r1; r2; r3; t]")
    b1, b2 = sympy.symbols("beta1 beta2")
    r1, r2, r3, _ = pose_columns(combination([v1, v2], [b1, b2]))
    C = []
    for q in homogeneous_constraints(r1, r2, r3):
        C += coefficients(q, [b1 ** 2, b2 ** 2, b1 * b2], [b1, b2])
    k.output("C", C, "5x3 row-major")
    return k


def beta_n3_kernel() -> Kernel:
    k = Kernel(
        name="betaConstraintsN3",
        doc="""
        N = 3: the orthogonality and unit-norm constraints on v = b1 v1 + b2 v2 + b3 v3 (paper
        eq. 21) as a 6x6 matrix C with C [b1^2, b2^2, b3^2, b1 b2, b1 b3, b2 b3]^T = [0 0 0 1 1 1]^T.
        Rows: r1.r2, r2.r3, r3.r1, |r1|^2, |r2|^2, |r3|^2;
        columns: b1^2, b2^2, b3^2, b1 b2, b1 b3, b2 b3.
        """,
    )
    v1 = k.input("v1", 12, "first kernel vector [r1; r2; r3; t]")
    v2 = k.input("v2", 12, "second kernel vector [r1; r2; r3; t]")
    v3 = k.input("v3", 12, "third kernel vector [r1; r2; r3; t]")
    b1, b2, b3 = sympy.symbols("beta1 beta2 beta3")
    r1, r2, r3, _ = pose_columns(combination([v1, v2, v3], [b1, b2, b3]))
    C = []
    for q in rotation_constraints(r1, r2, r3):
        C += coefficients(q, [b1 ** 2, b2 ** 2, b3 ** 2, b1 * b2, b1 * b3, b2 * b3], [b1, b2, b3])
    k.output("C", C, "6x6 row-major")
    return k


def family() -> Family:
    return Family(
        stem="beta_constraints",
        title="Rotation constraints as quadrics in the kernel coefficients (paper Sec. III-D).",
        doc="""
        v = [r1; r2; r3; t] (r_i: the columns of R), matrices row-major.
        """,
        spec_module=SPEC_PATH,
        kernels=[beta_n2_kernel(), beta_n3_kernel()],
    )
