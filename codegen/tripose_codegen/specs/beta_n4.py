"""N = 4 (paper Sec. III-D, eqs. 22-26): relinearization with beta3 hidden.

Derivation. With beta4 = 1, v = b1 v1 + b2 v2 + b3 v3 + v4. Each of the five homogeneous
constraints (r1.r2, r2.r3, r3.r1, |r1|^2 - |r2|^2, |r2|^2 - |r3|^2) is a quadratic form
w^T Q w in w = (b1, b2, b3, 1); grouping by [b1^2, b2^2, b1 b2, b1, b2, 1] gives the 5x6 matrix of
eq. (24) whose last three columns are polynomials in b3 of degrees 1, 1, 2:
    [Q11, Q22, 2 Q12, 2 (Q14 + Q13 b3), 2 (Q24 + Q23 b3), Q44 + 2 Q34 b3 + Q33 b3^2].
Its null vector (eq. 25) is u_i = (-1)^(i-1) det(matrix without column i), polynomials in b3 of
degrees 4, 4, 4, 3, 3, 2. The consistency relations (eq. 26) give three degree-6 polynomials
    f1 = u4 u5 - u3 u6,  f2 = u4^2 - u1 u6,  f3 = u5^2 - u2 u6,
and the stationary points of sum f_i^2 are the roots of the degree-11 polynomial sum f_i f_i'.

What is expanded where (measured, see codegen/README.md): the 50 coefficients of the 5x6
matrix are expanded symbolically in v; the minors are NOT expanded: they are a memoized
cofactor expansion over the matrix coefficients with exact polynomial arithmetic in b3 (each
shared sub-minor is one staged intermediate); f_i and sum f_i f_i' are polynomial products of the
u coefficients.
"""

import itertools
from typing import Dict, List, Sequence, Tuple

import sympy

from ..spec import Family, Kernel, join_doc
from .common import coefficients, homogeneous_constraints, pose_columns

SPEC_PATH = "codegen/tripose_codegen/specs/beta_n4.py"

# Degrees in beta3 of the columns [b1^2, b2^2, b1 b2, b1, b2, 1] and of u1..u6.
COLUMN_DEGREES = (0, 0, 0, 1, 1, 2)
NULL_VECTOR_DEGREES = (4, 4, 4, 3, 3, 2)
# Order in which the cofactor expansion takes the columns: the first listed column is expanded
# at the top level, the last ones form the smallest (shared) sub-minors. Constant columns last
# keep the deep sub-minors scalar; chosen by op count among all orders (codegen/README.md).
EXPANSION_ORDER = (5, 3, 4, 0, 1, 2)

Poly = List[sympy.Expr]  # Ascending coefficients in beta3.


def poly_add(a: Poly, b: Poly) -> Poly:
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]


def poly_mul(a: Poly, b: Poly) -> Poly:
    out = [sympy.S.Zero] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def poly_derivative(a: Poly) -> Poly:
    return [i * a[i] for i in range(1, len(a))]


def matrix_coefficients(v1, v2, v3, v4) -> List[List[Poly]]:
    """The 5x6 matrix of eq. (24): entry [row][col] as a polynomial in beta3."""
    b1, b2, b3 = sympy.symbols("beta1 beta2 beta3")
    w = [b1 * v1[i] + b2 * v2[i] + b3 * v3[i] + v4[i] for i in range(12)]
    r1, r2, r3, _ = pose_columns(w)
    rows = []
    for q in homogeneous_constraints(r1, r2, r3):
        c = coefficients(q, [b1 ** 2, b2 ** 2, b1 * b2, b1, b1 * b3, b2, b2 * b3, 1, b3, b3 ** 2],
                         [b1, b2, b3])
        rows.append([[c[0]], [c[1]], [c[2]], [c[3], c[4]], [c[5], c[6]], [c[7], c[8], c[9]]])
    return rows


def permutation_sign(seq: Sequence[int]) -> int:
    inversions = sum(1 for i, j in itertools.combinations(range(len(seq)), 2) if seq[i] > seq[j])
    return -1 if inversions % 2 else 1


class CofactorExpansion:
    """Determinants of square submatrices of a matrix of polynomials, by expansion along the
    first listed column, each distinct (rows, columns) minor computed once and staged."""

    def __init__(self, kernel: Kernel, entries: List[List[Poly]]):
        self.kernel = kernel
        self.entries = entries
        self.memo: Dict[Tuple[Tuple[int, ...], Tuple[int, ...]], Poly] = {}

    def det(self, rows: Tuple[int, ...], cols: Tuple[int, ...]) -> Poly:
        """det of the submatrix with @p rows (ascending) and @p cols in the listed order."""
        if len(cols) == 1:
            return self.entries[rows[0]][cols[0]]
        key = (rows, cols)
        if key not in self.memo:
            total: Poly = [sympy.S.Zero]
            for idx, r in enumerate(rows):
                sub = self.det(rows[:idx] + rows[idx + 1:], cols[1:])
                term = poly_mul(self.entries[r][cols[0]], sub)
                total = poly_add(total, term if idx % 2 == 0 else [-c for c in term])
            self.memo[key] = [self.kernel.let(c) for c in total]
        return self.memo[key]


def null_vector(k: Kernel, entries: List[List[Poly]], order=EXPANSION_ORDER) -> List[Poly]:
    """u_i = (-1)^(i-1) det(entries without column i), i = 1..6 (eq. 25)."""
    expansion = CofactorExpansion(k, entries)
    u = []
    for i in range(6):
        cols = tuple(c for c in order if c != i)
        sign = (-1) ** i * permutation_sign(cols)
        d = expansion.det(tuple(range(5)), cols)
        d = d[:NULL_VECTOR_DEGREES[i] + 1]  # Higher coefficients vanish identically.
        u.append([sign * c for c in d])
    return u


def unpack_null_vector(u: Sequence[sympy.Expr]) -> List[Poly]:
    out, offset = [], 0
    for deg in NULL_VECTOR_DEGREES:
        out.append(list(u[offset:offset + deg + 1]))
        offset += deg + 1
    return out


def consistency_polynomials(u: List[Poly]) -> List[Poly]:
    """Eq. (26): f1 = u4 u5 - u3 u6, f2 = u4^2 - u1 u6, f3 = u5^2 - u2 u6 (degree 6 each)."""
    def minus(a, b):
        return poly_add(a, [-c for c in b])
    return [minus(poly_mul(u[3], u[4]), poly_mul(u[2], u[5])),
            minus(poly_mul(u[3], u[3]), poly_mul(u[0], u[5])),
            minus(poly_mul(u[4], u[4]), poly_mul(u[1], u[5]))]


def stationarity_polynomial(f: List[Poly]) -> Poly:
    """sum_i f_i f_i' (degree 11)."""
    total: Poly = [sympy.S.Zero]
    for fi in f:
        total = poly_add(total, poly_mul(fi, poly_derivative(fi)))
    return total


MATRIX_LAYOUT = """\
    Matrix layout (row-major 5x10, one row per constraint r1.r2, r2.r3, r3.r1,
    |r1|^2 - |r2|^2, |r2|^2 - |r3|^2):
        [b1^2, b2^2, b1 b2, b1: (1, b3), b2: (1, b3), 1: (1, b3, b3^2)],
    i.e. the 5x6 matrix of eq. (24) in [b1^2, b2^2, b1 b2, b1, b2, 1] with its polynomial
    entries in b3 expanded as ascending coefficients."""

U_LAYOUT = """\
    u packing (26 doubles, ascending powers of b3): u1, u2, u3 (degree 4, 5 coefficients each),
    u4, u5 (degree 3, 4 each), u6 (degree 2, 3), at offsets 0, 5, 10, 15, 19, 23."""


def _v_inputs(k: Kernel):
    v = k.input("v", 48, "the kernel vectors v1|v2|v3|v4 concatenated, each [r1; r2; r3; t]")
    return [v[12 * j:12 * j + 12] for j in range(4)]


def matrix_kernel() -> Kernel:
    k = Kernel(
        name="betaN4Matrix",
        doc=join_doc("""
        N = 4, beta4 = 1, beta3 hidden: the 5x6 matrix of eq. (24). With
        v = b1 v1 + b2 v2 + b3 v3 + v4, each homogeneous constraint equals
        row . [b1^2, b2^2, b1 b2, b1, b2, 1] where the last three entries are polynomials in b3.
        """, MATRIX_LAYOUT),
    )
    M = matrix_coefficients(*_v_inputs(k))
    k.output("M", [c for row in M for entry in row for c in entry], "5x10 row-major, see layout")
    return k


def null_vector_kernel() -> Kernel:
    k = Kernel(
        name="betaN4NullVector",
        doc=join_doc("""
        N = 4: the null vector u of the 5x6 matrix of eq. (24) (see betaN4Matrix) as polynomials
        in b3, u_i = (-1)^(i-1) det(matrix without column i) (eq. 25), so that
        matrix(b3) u(b3) = 0 and, for a consistent solution, u ~ [b1^2, b2^2, b1 b2, b1, b2, 1].
        Computed by cofactor expansion over the matrix coefficients with shared sub-minors.
        """, U_LAYOUT),
    )
    M = matrix_coefficients(*_v_inputs(k))
    staged = [[[k.let(c) for c in entry] for entry in row] for row in M]
    u = null_vector(k, staged)
    k.output("u", [c for poly in u for c in poly], "packed null vector, see layout")
    return k


def consistency_kernel() -> Kernel:
    k = Kernel(
        name="betaN4Consistency",
        doc=join_doc("""
        N = 4: the three consistency polynomials of eq. (26), degree 6 in b3:
        f1 = u4 u5 - u3 u6, f2 = u4^2 - u1 u6, f3 = u5^2 - u2 u6.
        Output f: 3x7 row-major, ascending powers.
        """, U_LAYOUT),
    )
    u = unpack_null_vector(k.input("u", 26, "packed null vector from betaN4NullVector"))
    f = consistency_polynomials(u)
    k.output("f", [sympy.expand(c) for poly in f for c in poly], "3x7 row-major, ascending powers")
    return k


def polynomial_kernel() -> Kernel:
    k = Kernel(
        name="betaN4Polynomial",
        doc=join_doc("""
        N = 4: the 12 coefficients (ascending powers of b3) of the degree-11 polynomial
        sum_i f_i f_i' whose real roots are the stationary points of sum_i f_i^2, with
        f1 = u4 u5 - u3 u6, f2 = u4^2 - u1 u6, f3 = u5^2 - u2 u6 (eq. 26).
        """, U_LAYOUT),
    )
    u = unpack_null_vector(k.input("u", 26, "packed null vector from betaN4NullVector"))
    f = [[k.let(sympy.expand(c)) for c in poly] for poly in consistency_polynomials(u)]
    p = stationarity_polynomial(f)
    k.output("p", [sympy.expand(c) for c in p], "12 coefficients, ascending powers")
    return k


def family() -> Family:
    return Family(
        stem="beta_n4",
        title="N = 4: relinearization with beta3 hidden (paper Sec. III-D, eqs. 22-26).",
        doc="""
        v = [r1; r2; r3; t] (r_i: the columns of R); v = b1 v1 + b2 v2 + b3 v3 + v4 (beta4 = 1).
        Typical use: betaN4NullVector(v, u); betaN4Polynomial(u, p); the real roots b3 of p give
        b1 = u4(b3) / u6(b3), b2 = u5(b3) / u6(b3).
        """,
        spec_module=SPEC_PATH,
        kernels=[matrix_kernel(), null_vector_kernel(), consistency_kernel(), polynomial_kernel()],
    )
