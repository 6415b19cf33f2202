#!/usr/bin/env python3
"""Numeric prototype of the stereo-rig pose solver: the specification of the C++ solver.

A calibrated stereo rig sees points and line segments at two times. Views: 1 = left camera at
time A, [I|0]; 2 = right camera at time A, the rig [R12|t12] (known); 3 = left camera at time B,
[R|t] (unknown); 4 = right camera at time B, [R12 R | R12 t + t12]. Every feature is seen in views
1 and 2 and in view 3, view 4 or both. The solver:

1. Rows (generated kernels, run here through their Python evaluation): a line gets the two points
   qa, qb of its 3D line from views 1-2 (lineNullSpace); in view 3 they give lineRows (b = 0), in
   view 4 rigLineRows (b != 0). A point gives pointRows in view 3 and rigPointRows in view 4, each
   view Hartley-normalized over the points it sees. Every block of rows (one feature in one view)
   is scaled to Frobenius norm sqrt(2) (two unit rows, like a line's), b with it.
2. The kernel dimension d of A for exact data comes from the feature counts (kernel_dimension):
   a line seen in both time-B views is 4 constraints, a point seen in both only 3 (views 3 and 4
   triangulate it; its fourth equation is their epipolar constraint), a feature seen in one of
   them 2, with overlaps when points seen in both views pin the relaxed map down (e.g. 1P+2L seen
   in both views: 10, not 11). With no feature in view 4 (or none in view 3) the system is the
   homogeneous three-view one and d >= 1. d >= 7 (fewer than six constraints) is not solvable.
3. v = v0 + sum_k c_k e_k: v0 the minimum-norm solution over the leading 12 - d singular
   directions, e_k the last d right singular vectors.
     d = 0       v = v0 (least squares when over-determined);
     d = 1..5    linearization: C m(c) = 0 with the twenty quadrics of SO(3)
                 (affineConstraintsD<d>), solved by least squares for the non-constant monomials,
                 c read off the linear ones;
     d = 6       (six constraints: up to 8 poses, 4 with a line seen in both views) an
                 eigenproblem on the null space of the degree-3 Macaulay matrix of the twenty
                 quadrics (solve_minimal).
4. Each candidate: R = the rotation nearest to [r1 r2 r3] (SVD, det +1), then t re-estimated by
   least squares from A_t t = b - A_r vec(R); candidates ordered by |A v - b|.

    .venv/bin/python test/evaluation/codegen/stereo_rig.py [--scenes 1000] [--seed 0]

prints, per feature mix, the kernel dimension d, how many poses fit exact data (solution_count),
how often the true pose is recovered from noise-free data (the first candidate where one pose
fits, any candidate where several do) and the largest errors of the successes.

    .venv/bin/python test/evaluation/codegen/stereo_rig.py --check-counts 6

checks kernel_dimension and solution_count against numeric ranks for every mix of up to six
features.
"""

import argparse
import functools
import itertools
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import List, Tuple

# The matrices are small: BLAS threads would only contend with each other (and, on a shared
# machine, make an SVD of a 140x84 matrix take 50 ms instead of 1).
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "codegen"))

from tripose_codegen.evaluate import numeric_kernel  # noqa: E402

# Camera used to place features in the images (all four views share it); the solver works in
# calibrated coordinates and never sees it.
FOCAL, WIDTH, HEIGHT = 800.0, 640.0, 480.0

# A success: rotation within 1e-6 rad and translation within 1e-6 of its length.
TOLERANCE = 1e-6

# Scene ranges (metres, degrees): rig baseline, depth of the features in view 1, motion of the
# rig between times A and B, its rotation.
BASELINE = (0.1, 0.5)
DEPTH = (5.0, 30.0)
MOTION = (0.3, 3.0)
TURN = 20.0


@functools.lru_cache(maxsize=None)
def family(module: str):
    import importlib

    return importlib.import_module(f"tripose_codegen.specs.{module}").family()


@functools.lru_cache(maxsize=None)
def kernel(module: str, name: str):
    """A generated kernel, run through its Python evaluation (the same straight-line program
    the C++ file holds)."""
    for k in family(module).kernels:
        if k.name == name:
            return numeric_kernel(k)
    raise KeyError(name)


# ---------------------------------------------------------------------------------------------
# Scenes


def rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def rotation_angle(R):
    """Angle of a rotation, from |R - I|_F = 2 sqrt(2) sin(angle / 2): accurate near 0, where the
    arccos of the trace loses half the digits."""
    return 2 * np.arcsin(min(1.0, np.linalg.norm(R - np.eye(3)) / (2 * np.sqrt(2))))


@dataclass
class Rig:
    """The rig (R12, t12) and the motion (R, t) of the left camera from time A to time B."""

    R12: np.ndarray
    t12: np.ndarray
    R: np.ndarray
    t: np.ndarray

    def cameras(self):
        """(R, t) of views 1-4."""
        return [(np.eye(3), np.zeros(3)), (self.R12, self.t12), (self.R, self.t),
                (self.R12 @ self.R, self.R12 @ self.t + self.t12)]


def random_rig(rng) -> Rig:
    """Baseline in BASELINE roughly along x, cameras within 3 deg of parallel; the rig moves by a
    distance in MOTION and turns up to TURN degrees about a random axis."""
    baseline = rng.uniform(*BASELINE)
    centre2 = baseline * np.array([1.0, *rng.normal(scale=0.05, size=2)])
    R12 = rotation(rng.normal(size=3), np.radians(rng.uniform(0, 3)))
    t12 = -R12 @ centre2
    direction = rng.normal(size=3)
    centre3 = rng.uniform(*MOTION) * direction / np.linalg.norm(direction)
    R = rotation(rng.normal(size=3), np.radians(rng.uniform(0, TURN)))
    return Rig(R12, t12, R, -R @ centre3)


def visible(rig: Rig, X) -> bool:
    for R, t in rig.cameras():
        x = R @ X + t
        if x[2] < 1.0:
            return False
        u, v = FOCAL * x[0] / x[2] + WIDTH / 2, FOCAL * x[1] / x[2] + HEIGHT / 2
        if not (0 <= u < WIDTH and 0 <= v < HEIGHT):
            return False
    return True


def random_visible_point(rng, rig: Rig):
    """A point at a depth in DEPTH in front of view 1 that all four views see."""
    for _ in range(100000):
        u, v = rng.uniform(0, WIDTH), rng.uniform(0, HEIGHT)
        X = rng.uniform(*DEPTH) * np.array([(u - WIDTH / 2) / FOCAL, (v - HEIGHT / 2) / FOCAL, 1.0])
        if visible(rig, X):
            return X
    raise ValueError("the four views share no field of view at these depths")


@dataclass
class Feature:
    """A point (X) or a line segment (A, B) and the time-B views that see it."""

    kind: str  # "point" or "line"
    ends: Tuple[np.ndarray, ...]
    in3: bool = True
    in4: bool = True


def random_feature(rng, rig: Rig, kind: str, in3=True, in4=True) -> Feature:
    if kind == "point":
        return Feature(kind, (random_visible_point(rng, rig),), in3, in4)
    while True:
        A, B = random_visible_point(rng, rig), random_visible_point(rng, rig)
        if np.linalg.norm(A - B) > 0.5:
            return Feature(kind, (A, B), in3, in4)


def project_point(R, t, X):
    x = R @ X + t
    return x[:2] / x[2]


def observe(rig: Rig, f: Feature, noise=0.0, rng=None):
    """Calibrated observations in views 1-4 (None where not seen); noise in pixels, on the point
    and on both segment end points."""
    def jitter(x):
        return x if noise == 0 else x + rng.normal(scale=noise / FOCAL, size=2)

    seen = [True, True, f.in3, f.in4]
    out = []
    for (R, t), s in zip(rig.cameras(), seen):
        if not s:
            out.append(None)
        elif f.kind == "point":
            out.append(jitter(project_point(R, t, f.ends[0])))
        else:
            a = np.append(jitter(project_point(R, t, f.ends[0])), 1.0)
            b = np.append(jitter(project_point(R, t, f.ends[1])), 1.0)
            l = np.cross(a, b)
            out.append(l / np.linalg.norm(l[:2]))
    return out


# ---------------------------------------------------------------------------------------------
# The linear system A v = b


def kernel_dimension(features: List[Feature]) -> int:
    """Dimension of the kernel of A for exact data in general position.

    A v = b relaxes R to any 3x3 matrix M: it asks for an affine map f(X) = M X + t (12 unknowns)
    that sends each feature of time A onto its observations at time B. A point seen in both
    time-B views is triangulated there, f(X) = Y: 3 constraints (its fourth row, the epipolar
    constraint of views 3-4, holds by itself); a line seen in both maps onto a line: 4; a point
    or line seen in one view only: 2 (onto a ray, into a plane). When all time-B observations are
    in one view the system is the homogeneous three-view one and the true v is in its kernel.
    Points seen in both views fix f at those points, and the kernel is what remains of M on the
    other directions; the constraints then overlap (verified against numeric ranks for every
    mix of up to six features, check_counts):
      1 such point X:   two lines seen in both lie in planes through X that share a direction w,
                        and M w = 0 is counted once too often: one constraint less;
      2 points X1, X2:  M = w1 b1^T + w2 b2^T (b_i spanning the normal plane of X2 - X1), w1, w2
                        in a common subspace S of dimension s = 3 - (lines seen once) - 2 (lines
                        seen in both); each point seen once then removes min(s, 2) of the 2 s;
      3 points:         M = w n^T (n normal to their plane), w in R^3; a point seen once removes
                        2, a line seen once 1, a line seen in both 2, a fourth such point 3;
      4 or more:        M is fixed: d = 0.
    """
    pb = sum(f.kind == "point" and f.in3 and f.in4 for f in features)
    lb = sum(f.kind == "line" and f.in3 and f.in4 for f in features)
    ps = sum(f.kind == "point" and f.in3 != f.in4 for f in features)
    ls = sum(f.kind == "line" and f.in3 != f.in4 for f in features)
    if not any(f.in4 for f in features) or not any(f.in3 for f in features):
        return max(1, 12 - 2 * (ps + ls))
    if pb == 0:
        return max(0, 12 - 2 * ps - 4 * lb - 2 * ls)
    if pb == 1:
        return max(0, 9 - 2 * ps - 4 * lb - 2 * ls + (1 if lb >= 2 else 0))
    if pb == 2:
        s = max(0, 3 - ls - 2 * lb)
        return max(0, 2 * s - ps * min(s, 2))
    if pb == 3:
        return max(0, 3 - 2 * ps - ls - 2 * lb)
    return 0


def check_counts(max_features: int, seeds: int = 3) -> List[str]:
    """Every mix of up to @p max_features features (point/line x both/view 3/view 4) where, with
    exact data in `seeds` random scenes, kernel_dimension disagrees with the numeric rank of A
    or solution_count with the number of solutions: the rank of the degree <= 1 rows of the null
    space of C for d <= 5 (for two points seen in both views and a line seen in one, or a point
    seen in both, a point and a line seen in one, C has four more null vectors, but only on
    quadratic monomials), of the degree <= 2 rows of the degree-3 Macaulay null space for d = 6."""
    kinds = [(k, a, b) for k in ("point", "line") for a, b in ((True, True), (True, False), (False, True))]
    bad = []
    for n in range(1, max_features + 1):
        for combo in itertools.combinations_with_replacement(kinds, n):
            for seed in range(seeds):
                rng = np.random.default_rng([seed, n])
                rig = random_rig(rng)
                features = [random_feature(rng, rig, *c) for c in combo]
                system = build_system(rig, features, [observe(rig, f) for f in features])
                rank = numeric_rank(system.A)
                if rank != 12 - system.d:
                    bad.append(f"{combo}: rank {rank}, kernel_dimension {system.d}")
                elif 1 <= system.d <= 6 and system.solutions > 0:
                    v0, E = affine_kernel(system, system.d)
                    C = constraint_matrix(v0, E, system.d)
                    if system.d <= 5:
                        M, columns, degree = C, monomials(system.d), 1
                    else:
                        (M, columns), degree = macaulay_degree3(C, system.d), 2
                    W = np.linalg.svd(M)[2][numeric_rank(M):].T
                    low = [i for i, e in enumerate(columns) if sum(e) <= degree]
                    found = numeric_rank(W[low], 1e-8)
                    if found != system.solutions:
                        bad.append(f"{combo}: {found} solutions, solution_count {system.solutions}")
    return bad


def numeric_rank(M, tolerance=1e-10):
    s = np.linalg.svd(M, compute_uv=False)
    return int(np.sum(s > tolerance * s[0]))


def normalizing_similarity(points: List[np.ndarray]) -> np.ndarray:
    """Hartley normalization (s, cx, cy): centroid at the origin, mean distance sqrt(2)."""
    P = np.array(points)
    c = P.mean(axis=0)
    mean = np.linalg.norm(P - c, axis=1).mean()
    return np.array([np.sqrt(2) / mean if mean > 1e-12 else 1.0, c[0], c[1]])


def apply_similarity(n, x):
    return n[0] * (x - n[1:])


@dataclass
class System:
    A: np.ndarray
    b: np.ndarray
    d: int  # dimension of the kernel of A for exact, generic data (kernel_dimension)
    solutions: int  # poses that exact data admits (solution_count)


def build_system(rig: Rig, features: List[Feature], observations) -> System:
    R12, t12 = rig.R12.ravel(), rig.t12
    rows, rhs = [], []

    def add(block_rows, block_b):
        # Two unit rows' worth of weight per block, whatever the normalizing scales.
        s = np.sqrt(2) / np.linalg.norm(block_rows)
        rows.append(block_rows * s)
        rhs.append(block_b * s)

    points = [i for i, f in enumerate(features) if f.kind == "point"]
    if points:
        n = [None] * 4
        for view in range(4):
            seen = [observations[i][view] for i in points if observations[i][view] is not None]
            if seen:
                n[view] = normalizing_similarity(seen)
        for i in points:
            o = observations[i]
            x1, x2 = apply_similarity(n[0], o[0]), apply_similarity(n[1], o[1])
            if o[2] is not None:
                r = kernel("point_rows", "pointRows")(
                    x1=x1, x2=x2, x3=apply_similarity(n[2], o[2]), n1=n[0], n2=n[1], n3=n[2],
                    R12=R12, t12=t12)["rows"].reshape(4, 12)
                add(r, np.zeros(4))
            if o[3] is not None:
                out = kernel("rig_rows", "rigPointRows")(
                    x1=x1, x2=x2, x4=apply_similarity(n[3], o[3]), n1=n[0], n2=n[1], n4=n[3],
                    R12=R12, t12=t12)
                add(out["rows"].reshape(4, 12), out["b"])
    for i, f in enumerate(features):
        if f.kind != "line":
            continue
        o = observations[i]
        q = kernel("line_rows", "lineNullSpace")(l1=o[0], l2=o[1], R12=R12, t12=t12)
        if o[2] is not None:
            r = kernel("line_rows", "lineRows")(qa=q["qa"], qb=q["qb"], l3=o[2])["rows"]
            add(r.reshape(2, 12), np.zeros(2))
        if o[3] is not None:
            out = kernel("rig_rows", "rigLineRows")(qa=q["qa"], qb=q["qb"], l4=o[3],
                                                    R12=R12, t12=t12)
            add(out["rows"].reshape(2, 12), out["b"])
    d = kernel_dimension(features)
    return System(np.vstack(rows), np.concatenate(rhs), d, solution_count(features, d))


# ---------------------------------------------------------------------------------------------
# Solving




def solution_count(features: List[Feature], d: int) -> int:
    """How many poses exact data in general position admits (0: not determined).

    d >= 7 leaves fewer than six constraints. Two points seen in both time-B views fix the
    rotation only up to a turn about the line through them. Two features seen in both views,
    two lines or a point and a line, admit a second rigid motion that maps them onto themselves:
    the half turn about their common perpendicular (through the point, for a point and a line),
    so two poses fit exactly. d = 6 is a minimal problem; its counts are those of the null space
    of the degree-3 Macaulay matrix restricted to degree <= 2 (check_counts): 8 for three
    features seen in one time-B view each, 4 when these are two points and a line (as for the
    absolute pose from two points and a line) or when a line is seen in both views."""
    if d >= 7:
        return 0
    both = [f for f in features if f.in3 and f.in4]
    if len(features) == 2 and len(both) == 2:
        return 0 if all(f.kind == "point" for f in both) else 2
    if d == 6:
        points = sum(f.kind == "point" for f in features)
        return 4 if both or (len(features) == 3 and points == 2) else 8
    return 1


def affine_kernel(system: System, d: int):
    """v0 (minimum norm over the leading 12 - d singular directions) and the kernel basis."""
    U, s, Vt = np.linalg.svd(system.A)
    k = 12 - d
    v0 = Vt[:k].T @ ((U[:, :k].T @ system.b) / s[:k])
    return v0, Vt[k:]


def monomials(d: int):
    """Exponent tuples of m(c) = [c_k^2, c_k c_l (k < l), c_k, 1], the column order of C."""
    out = []
    for k in range(d):
        out.append(tuple(2 if j == k else 0 for j in range(d)))
    for k, l in itertools.combinations(range(d), 2):
        out.append(tuple(1 if j in (k, l) else 0 for j in range(d)))
    for k in range(d):
        out.append(tuple(1 if j == k else 0 for j in range(d)))
    out.append((0,) * d)
    return out


def constraint_matrix(v0, E, d: int) -> np.ndarray:
    """The 20 quadrics of SO(3) in c (generated affineConstraintsD<d>)."""
    C = kernel("affine_constraints", f"affineConstraintsD{d}")(v0=v0, e=E.ravel())["C"]
    return C.reshape(20, -1)


def unit(d: int, k: int):
    return tuple(int(j == k) for j in range(d))


def shifted(e, k: int):
    return tuple(x + int(j == k) for j, x in enumerate(e))


def macaulay_degree3(C: np.ndarray, d: int):
    """Rows: each quadric times 1, c_1..c_d; columns: the monomials of degree <= 3, highest
    degree first. Returns the matrix and the exponent of each column."""
    quad = monomials(d)
    shifts = [(0,) * d] + [unit(d, k) for k in range(d)]
    columns = sorted({tuple(a + b for a, b in zip(m, s)) for m in quad for s in shifts},
                     key=lambda e: (-sum(e), tuple(-x for x in e)))
    index = {e: i for i, e in enumerate(columns)}
    rows = []
    for shift in shifts:
        for q in C:
            row = np.zeros(len(columns))
            for coef, m in zip(q, quad):
                row[index[tuple(a + b for a, b in zip(m, shift))]] += coef
            rows.append(row)
    return np.array(rows), columns


def pivot_rows(M: np.ndarray, count: int) -> List[int]:
    """@p count rows of M chosen greedily, each the one with the largest component orthogonal to
    those already chosen (the pivots of a column-pivoted QR of M^T): a well-conditioned square
    block."""
    M = M.astype(float).copy()
    chosen = []
    for _ in range(count):
        i = int(np.argmax(np.linalg.norm(M, axis=1)))
        chosen.append(i)
        u = M[i] / np.linalg.norm(M[i])
        M -= np.outer(M @ u, u)
    return chosen


def eigen_solutions(W: np.ndarray, exponents, rng) -> List[np.ndarray]:
    """The real solutions c whose monomial vectors span W (rows: the monomials @p exponents,
    columns: r = W.shape[1] basis vectors, one dimension per solution).

    For a basis B of r monomials whose products with every c_k are among the rows, and a random
    linear form l(c) = sum_k w_k c_k, each solution s with m(s) = W a satisfies
    W[l B] a = l(s) W[B] a: the eigenvectors of W[B]^-1 W[l B] are the solutions' a."""
    d = len(exponents[0])
    r = W.shape[1]
    index = {e: i for i, e in enumerate(exponents)}
    closed = [i for i, e in enumerate(exponents) if all(shifted(e, k) in index for k in range(d))]
    basis = [closed[p] for p in pivot_rows(W[closed], r)]
    weights = rng.normal(size=d)
    WlB = sum(weights[k] * W[[index[shifted(exponents[i], k)] for i in basis]] for k in range(d))
    values, vectors = np.linalg.eig(np.linalg.solve(W[basis], WlB))
    one = index[(0,) * d]
    linear = [index[unit(d, k)] for k in range(d)]
    out = []
    for value, a in zip(values, vectors.T):
        if abs(value.imag) > 1e-6 * max(1.0, abs(value)):
            continue
        m = W @ a
        if abs(m[one]) < 1e-12 * np.abs(m).max():
            continue
        out.append((m[linear] / m[one]).real)
    return out


def solve_linearized(v0, E, d: int, count: int, rng) -> List[np.ndarray]:
    """d <= 5: the monomials of c as unknowns of C m = 0. One solution: least squares with the
    constant monomial fixed to 1, c read off the linear monomials. Two (the half-turn pairs of
    solution_count): the null space of C is two-dimensional, and the multiplication by c_k of
    the monomials of degree <= 1 stays within C's columns, so eigen_solutions applies."""
    C = constraint_matrix(v0, E, d)
    if count == 1:
        m = np.linalg.lstsq(C[:, :-1], -C[:, -1], rcond=None)[0]
        return [v0 + m[-d:] @ E]
    W = np.linalg.svd(C)[2][-count:].T
    return [v0 + c @ E for c in eigen_solutions(W, monomials(d), rng)]


def solve_minimal(v0, E, d: int, count: int, rng) -> List[np.ndarray]:
    """d = 6 (six constraints, finitely many poses): eigen_solutions on the null space of the
    degree-3 Macaulay matrix of the twenty quadrics.

    Its null space W (dimension 8 here) holds the monomial vectors of the affine solutions, plus,
    when fewer than 8 are affine (count = 4: a line seen in both views), vectors of solutions at
    infinity, which vanish on every monomial of degree <= 2. W' = W Z, Z the leading `count`
    right singular vectors of W[degree <= 2], keeps the affine part; the rows where the solutions
    at infinity vanish (degree <= 2, or all when count = 8) are the ones eigen_solutions may use."""
    M, columns = macaulay_degree3(constraint_matrix(v0, E, d), d)
    W = np.linalg.svd(M)[2][-8:].T
    low = [i for i, e in enumerate(columns) if sum(e) <= 2]
    Z = np.linalg.svd(W[low])[2][:count].T
    rows = low if count < 8 else list(range(len(columns)))
    return [v0 + c @ E for c in eigen_solutions((W @ Z)[rows], [columns[i] for i in rows], rng)]


def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(M)
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))])
    return U @ D @ Vt


def polish(system: System, v) -> Tuple[np.ndarray, np.ndarray]:
    """The rotation nearest to [r1 r2 r3], then t by least squares with R fixed."""
    R = nearest_rotation(np.column_stack([v[0:3], v[3:6], v[6:9]]))
    r = np.concatenate([R[:, 0], R[:, 1], R[:, 2]])
    A_r, A_t = system.A[:, :9], system.A[:, 9:]
    t = np.linalg.lstsq(A_t, system.b - A_r @ r, rcond=None)[0]
    return R, t


def solve(system: System, rng=None) -> List[Tuple[np.ndarray, np.ndarray]]:
    """Candidate poses (R, t), smallest algebraic residual |A v - b| first."""
    rng = rng if rng is not None else np.random.default_rng(0)
    d, count = system.d, system.solutions
    if count == 0:
        return []
    v0, E = affine_kernel(system, d)
    if d == 0:
        vs = [v0]
    elif d <= 5:
        vs = solve_linearized(v0, E, d, count, rng)
    else:
        vs = solve_minimal(v0, E, d, count, rng)
    poses = [polish(system, v) for v in vs]

    def residual(pose):
        R, t = pose
        return np.linalg.norm(system.A @ np.concatenate([R[:, 0], R[:, 1], R[:, 2], t]) - system.b)

    return sorted(poses, key=residual)


def pose_error(rig: Rig, R, t):
    return rotation_angle(R @ rig.R.T), np.linalg.norm(t - rig.t) / np.linalg.norm(rig.t)


# ---------------------------------------------------------------------------------------------
# The noise-free suite


@dataclass
class Mix:
    """A feature mix: (kind, in3, in4) per feature."""

    name: str
    features: List[Tuple[str, bool, bool]]


def mixes() -> List[Mix]:
    both, only3, only4 = (True, True), (True, False), (False, True)
    P, L = "point", "line"

    def mix(name, spec):
        return Mix(name, [(kind, *seen) for kind, seen in spec])

    return [
        # Three features, all seen in both time-B views.
        mix("3P both", [(P, both)] * 3),
        mix("2P+1L both", [(P, both)] * 2 + [(L, both)]),
        mix("1P+2L both", [(P, both)] + [(L, both)] * 2),
        mix("3L both", [(L, both)] * 3),
        # Larger sets.
        mix("5P+5L both", [(P, both)] * 5 + [(L, both)] * 5),
        mix("20P+20L both", [(P, both)] * 20 + [(L, both)] * 20),
        mix("10P+10L, half only3/only4", [(P, only3), (P, only4)] * 5 + [(L, only3), (L, only4)] * 5),
        mix("6 view-4 only (3P+3L)", [(P, only4)] * 3 + [(L, only4)] * 3),
        # Three or more features, some missing a time-B view.
        mix("2P both + 1P only3", [(P, both)] * 2 + [(P, only3)]),
        mix("2P both + 1L only4", [(P, both)] * 2 + [(L, only4)]),
        mix("1P+1L both + 1L only4", [(P, both), (L, both), (L, only4)]),
        mix("1P both + 2L single", [(P, both), (L, only3), (L, only4)]),
        mix("2L both + 1P only3", [(L, both)] * 2 + [(P, only3)]),
        mix("4 single (2P only3, 2L only4)", [(P, only3), (P, only3), (L, only4), (L, only4)]),
        mix("5 single (3 only3, 2 only4)", [(P, only3), (L, only3), (P, only3), (L, only4), (P, only4)]),
        # Two features.
        mix("1P+1L both (2 poses fit)", [(P, both), (L, both)]),
        mix("2L both (2 poses fit)", [(L, both)] * 2),
        # Homogeneous (no view 4): the three-view problem through the same linearization.
        mix("6 view-3 only (3P+3L)", [(P, only3)] * 3 + [(L, only3)] * 3),
        mix("4 view-3 only (2P+2L)", [(P, only3)] * 2 + [(L, only3)] * 2),
        # Minimal, d = 6: 8 or 4 poses fit.
        mix("3 single (2P only3, 1P only4)", [(P, only3), (P, only3), (P, only4)]),
        mix("3 single (1P+2L, mixed views)", [(P, only4), (L, only3), (L, only4)]),
        mix("3 single (2P+1L, mixed views)", [(P, only3), (P, only4), (L, only4)]),
        mix("3 single (3L, mixed views)", [(L, only3), (L, only4), (L, only3)]),
        mix("1L both + 1P only3", [(L, both), (P, only3)]),
        mix("1L both + 1L only4", [(L, both), (L, only4)]),
        mix("3 view-3 only (2P+1L)", [(P, only3), (P, only3), (L, only3)]),
        mix("3 view-3 only (3P)", [(P, only3)] * 3),
        mix("3 view-3 only (1P+2L)", [(P, only3), (L, only3), (L, only3)]),
        mix("3 view-4 only (3L)", [(L, only4)] * 3),
        # Not determined: a turn about the line through the points is free.
        mix("2P both", [(P, both)] * 2),
    ]


def run_mix(m: Mix, scenes: int, seed: int):
    ok, errors, counts, failures, dims, fits = 0, [], [], [], set(), set()
    for s in range(scenes):
        rng = np.random.default_rng([seed, s])
        rig = random_rig(rng)
        features = [random_feature(rng, rig, kind, in3, in4) for kind, in3, in4 in m.features]
        observations = [observe(rig, f) for f in features]
        system = build_system(rig, features, observations)
        dims.add(system.d)
        fits.add(system.solutions)
        candidates = solve(system, rng)
        counts.append(len(candidates))
        # Where several poses fit exact data, any candidate may be the true one.
        errs = [pose_error(rig, R, t) for R, t in (candidates if system.solutions > 1 else candidates[:1])]
        good = [e for e in errs if max(e) < TOLERANCE]
        if good:
            ok += 1
            errors.append(min(good, key=max))
        else:
            failures.append(s)
    return ok, errors, counts, failures, dims, fits


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenes", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--only", help="run the mixes whose name contains this text")
    parser.add_argument("--check-counts", type=int, metavar="N",
                        help="only compare kernel_dimension and solution_count with numeric ranks, "
                             "mixes of up to N features")
    args = parser.parse_args()
    if args.check_counts:
        bad = check_counts(args.check_counts)
        print("\n".join(bad) or "kernel_dimension and solution_count agree with the numeric ranks "
              f"for every mix of up to {args.check_counts} features")
        return 1 if bad else 0
    print(f"{'mix':34} {'d':>2} {'fit':>3} {'success':>11} {'max rot err':>12} {'max rel t err':>14} "
          f"{'candidates':>10}")
    for m in mixes():
        if args.only and args.only not in m.name:
            continue
        start = time.perf_counter()
        ok, errors, counts, failures, dims, fits = run_mix(m, args.scenes, args.seed)
        d = ",".join(str(x) for x in sorted(dims))
        fit = ",".join(str(x) for x in sorted(fits))
        if fits == {0}:
            print(f"{m.name:34} {d:>2} {fit:>3}   not determined: no candidate expected", flush=True)
            continue
        worst = np.max(errors, axis=0) if errors else (np.nan, np.nan)
        print(f"{m.name:34} {d:>2} {fit:>3} {ok:>5}/{args.scenes:<5} {worst[0]:12.1e} {worst[1]:14.1e} "
              f"{np.mean(counts):10.2f}   ({time.perf_counter() - start:.0f} s)"
              + (f"  failed seeds: {failures[:5]}" if failures else ""), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
