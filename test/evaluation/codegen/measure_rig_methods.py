#!/usr/bin/env python3
"""Measurements behind the choice of method per kernel dimension d of the stereo-rig system
(reported in doc/studies/accuracy.md, "The stereo rig's method per kernel dimension").

1. Reach (exact data, random d-dimensional affine kernels through a pose): the dimension of the
   solution space of C m = 0, each monomial of c an unknown, with the six column constraints
   and with the twenty quadrics of SO(3); for the six alone, the smallest degree at which the
   Macaulay matrix (the six times all monomials of degree <= D - 2) has a one-dimensional null
   space, and its size.
2. Accuracy with noise on representative feature mixes, per method:
     six       the six column constraints, linearized (d <= 2);
     six-XL    the six, Macaulay matrix of the degree from part 1, null vector (d = 3, 4);
     twenty    the twenty quadrics, linearized (stereo_rig.solve_linearized);
     twenty-W1 the twenty, null space of C of its structural dimension compressed to the
               degree <= 1 rows (for the mixes whose C has null vectors on quadratic monomials);
     minimal   the twenty, degree-3 Macaulay eigenproblem (d = 6).
   Errors: rotation (deg) and translation relative to its length of the selected candidate, or
   of the best one where several poses fit exact data.

    .venv/bin/python test/evaluation/codegen/measure_rig_methods.py [--scenes 500] [--noise 0.5 1]
"""

import argparse
import itertools
import os
import sys
from pathlib import Path

# Small matrices: BLAS threads would only contend (see stereo_rig.py).
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))

import stereo_rig as rig  # noqa: E402


def exponents_up_to(d: int, degree: int):
    return [e for k in range(degree + 1) for e in itertools.product(range(k + 1), repeat=d)
            if sum(e) == k]


def macaulay(C: np.ndarray, d: int, degree: int):
    """The quadrics of C times every monomial of degree <= degree - 2."""
    quad = rig.monomials(d)
    shifts = exponents_up_to(d, degree - 2)
    columns = sorted({tuple(a + b for a, b in zip(m, s)) for m in quad for s in shifts},
                     key=lambda e: (-sum(e), e))
    index = {e: i for i, e in enumerate(columns)}
    M = np.zeros((len(shifts) * len(C), len(columns)))
    for i, (s, q) in enumerate(itertools.product(shifts, C)):
        for coef, m in zip(q, quad):
            M[i, index[tuple(a + b for a, b in zip(m, s))]] += coef
    return M, index


def null_dimension(M):
    return M.shape[1] - rig.numeric_rank(M)


# Degree of the six-constraint Macaulay matrix with a one-dimensional null space (part 1).
SIX_XL_DEGREE = {3: 3, 4: 4}


def reach(rng, trials=3):
    from_tests = Path(__file__).resolve().parents[3] / "codegen" / "tests"
    sys.path.insert(0, str(from_tests))
    from conftest import pose_vector, random_rotation

    print("Part 1: null space of the linearization, exact data, random affine kernels")
    print(f"{'d':>2} {'monomials':>9} {'six':>4} {'twenty':>6}   six, Macaulay by degree (size: null space)")
    for d in range(1, 7):
        found = set()
        for _ in range(trials):
            v = pose_vector(random_rotation(rng), rng.normal(size=3))
            E = np.linalg.qr(rng.normal(size=(12, d)))[0].T
            v0 = v - E.T @ (E @ v)
            C = rig.constraint_matrix(v0, E, d)
            xl = []
            if 3 <= d <= 5:
                for degree in range(3, 6):
                    M, _ = macaulay(C[:6], d, degree)
                    xl.append(f"D{degree} {M.shape[0]}x{M.shape[1]}: {null_dimension(M)}")
            found.add((null_dimension(C[:6]), null_dimension(C), ", ".join(xl)))
        for six, twenty, xl in sorted(found):
            print(f"{d:>2} {d * (d + 3) // 2:>9} {six:>4} {twenty:>6}   {xl}")


def solve_six(system, rng):
    d = system.d
    v0, E = rig.affine_kernel(system, d)
    C = rig.constraint_matrix(v0, E, d)[:6]
    if d <= 2:
        m = np.linalg.lstsq(C[:, :-1], -C[:, -1], rcond=None)[0]
        return [v0 + m[-d:] @ E]
    M, index = macaulay(C, d, SIX_XL_DEGREE[d])
    m = np.linalg.svd(M)[2][-1]
    one = m[index[(0,) * d]]
    if not abs(one) > 1e-12 * np.abs(m).max():
        return []
    c = np.array([m[index[rig.unit(d, k)]] for k in range(d)]) / one
    return [v0 + c @ E]


def solve_twenty_w1(system, rng, nullity=5):
    """The null space of C (its structural dimension) compressed to its degree <= 1 rows."""
    d = system.d
    v0, E = rig.affine_kernel(system, d)
    C = rig.constraint_matrix(v0, E, d)
    W = np.linalg.svd(C)[2][-nullity:].T
    low = [i for i, e in enumerate(rig.monomials(d)) if sum(e) <= 1]
    m = W @ np.linalg.svd(W[low])[2][0]
    return [v0 + (m[-d - 1:-1] / m[-1]) @ E]


def solve_default(system, rng):
    d = system.d
    v0, E = rig.affine_kernel(system, d)
    if d == 0:
        return [v0]
    if d <= 5:
        return rig.solve_linearized(v0, E, d, system.solutions, rng)
    return rig.solve_minimal(v0, E, d, system.solutions, rng)


METHODS = {"six": solve_six, "six-XL": solve_six, "twenty": solve_default,
           "twenty-W1": solve_twenty_w1, "minimal": solve_default}

both, only3, only4 = (True, True), (True, False), (False, True)
P, L = "point", "line"
CASES = [
    ("3L both", [(L, *both)] * 3, ["twenty"]),
    ("5P+5L both", [(P, *both)] * 5 + [(L, *both)] * 5, ["twenty"]),
    ("10P both", [(P, *both)] * 10, ["twenty"]),
    ("10L both", [(L, *both)] * 10, ["twenty"]),
    ("1P+2L both", [(P, *both), (L, *both), (L, *both)], ["six", "twenty"]),
    ("2P+1L both", [(P, *both), (P, *both), (L, *both)], ["six", "twenty"]),
    ("3P both", [(P, *both)] * 3, ["six-XL", "twenty"]),
    ("2P both + 1P only3", [(P, *both), (P, *both), (P, *only3)], ["six-XL", "twenty"]),
    ("2P both + 1L only4", [(P, *both), (P, *both), (L, *only4)], ["twenty", "twenty-W1"]),
    ("1P both + 1P only3 + 1L only4", [(P, *both), (P, *only3), (L, *only4)], ["twenty", "twenty-W1"]),
    ("1P both + 2L single", [(P, *both), (L, *only3), (L, *only4)], ["twenty"]),
    ("2L both (2 fit)", [(L, *both)] * 2, ["twenty"]),
    ("1P+1L both (2 fit)", [(P, *both), (L, *both)], ["twenty"]),
    ("3P single (8 fit)", [(P, *only3), (P, *only3), (P, *only4)], ["minimal"]),
    ("1L both + 1P only3 (4 fit)", [(L, *both), (P, *only3)], ["minimal"]),
]


def accuracy(scenes: int, noises, seed: int):
    print(f"\nPart 2: accuracy with noise, {scenes} scenes per row, depth {rig.DEPTH[0]:g}-{rig.DEPTH[1]:g} m, "
          f"baseline {rig.BASELINE[0]:g}-{rig.BASELINE[1]:g} m (f = 800 px; rotation error in deg, "
          "translation error relative to |t|; median / 90th percentile; gross: rotation error > 5 deg)")
    print(f"{'mix':32} {'d':>2} {'px':>4} {'method':>9} {'rotation':>15} {'translation':>15} {'gross':>6}")
    for name, spec, methods in CASES:
        for noise in noises:
            for method in methods:
                rot, trans = [], []
                for s in range(scenes):
                    rng = np.random.default_rng([seed, s])
                    scene = rig.random_rig(rng)
                    features = [rig.random_feature(rng, scene, *c) for c in spec]
                    observations = [rig.observe(scene, f, noise, rng) for f in features]
                    system = rig.build_system(scene, features, observations)
                    poses = [rig.polish(system, v) for v in METHODS[method](system, rng)]
                    errors = [rig.pose_error(scene, R, t) for R, t in poses] or [(np.pi, np.inf)]
                    if system.solutions == 1:
                        errors = errors[:1]
                    r, t = min(errors)
                    rot.append(np.degrees(r))
                    trans.append(t)
                q = lambda x: f"{np.median(x):6.3f} / {np.percentile(x, 90, method='lower'):6.3f}"  # noqa: E731
                print(f"{name:32} {system.d:>2} {noise:>4} {method:>9} {q(rot):>15} {q(trans):>15} "
                      f"{np.mean(np.array(rot) > 5):6.1%}", flush=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenes", type=int, default=500)
    parser.add_argument("--noise", type=float, nargs="+", default=[0.5, 1.0], help="pixels")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--skip-reach", action="store_true")
    parser.add_argument("--depth", type=float, nargs=2, default=rig.DEPTH, help="metres")
    parser.add_argument("--baseline", type=float, nargs=2, default=rig.BASELINE, help="metres")
    parser.add_argument("--only", help="the mixes whose name contains this text")
    args = parser.parse_args()
    rig.DEPTH, rig.BASELINE = tuple(args.depth), tuple(args.baseline)
    if args.only:
        CASES[:] = [c for c in CASES if args.only in c[0]]
    if not args.skip_reach:
        reach(np.random.default_rng(args.seed))
    accuracy(args.scenes, args.noise, args.seed)
    return 0


if __name__ == "__main__":
    sys.exit(main())
