"""Kernel dimension of the three-view constraint system on coplanar structure, and the closed-form
pose from it.

On exact data each point adds the two independent rows of [x3]x P3 X and each line the two rows
l3^T P3 Y (Y two points of the 3D line), with P3 = [R | t] = reshape(v) and v = [r1; r2; r3; t]
(the row space of the solver's trilinear rows on exact data). When every X and Y lies on the plane
n^T X + d = 0, P3 + a [n^T d] maps the structure as P3 does for any a in R^3: the kernel holds this
3-dimensional family besides v, so it has dimension at least 4 whatever the number of features.

The script prints the measured kernel dimension per feature mix (singular values of the stacked
rows, relative threshold 1e-9) and checks the closed form: a kernel vector w whose family part is
removed has its rotation block equal to s R on the plane's directions (s = +-|.|), which gives R
(up to the rotation by pi about n, which puts the structure behind view 3); with 2P+2L two such
vectors, combined first (planar_rotations).

    .venv/bin/python test/evaluation/codegen/planar_kernel.py
"""
import numpy as np


def rotation(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def skew(x):
    return np.array([[0, -x[2], x[1]], [x[2], 0, -x[0]], [-x[1], x[0], 0]])


def scene(rng, points, lines, planar):
    R = rotation(rng)
    t = rng.normal(size=3) + np.array([0, 0, 20.0])
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    d = -n @ np.array([0, 0, 20.0])

    def structure_point():
        X = rng.uniform(-5, 5, size=3) + np.array([0, 0, 20.0])
        if planar:
            X -= (n @ X + d) * n
        return np.append(X, 1.0)

    rows = []
    for _ in range(points):
        X = structure_point()
        x3 = np.hstack([R, t[:, None]]) @ X
        rows += list(np.kron(X, skew(x3))[:2])
    for _ in range(lines):
        Y1, Y2 = structure_point(), structure_point()
        P = np.hstack([R, t[:, None]])
        l3 = np.cross(P @ Y1, P @ Y2)
        rows += [np.kron(Y1, l3), np.kron(Y2, l3)]
    return np.array(rows), R, t, np.append(n, d)


def kernel(A, tol=1e-9):
    _, s, vt = np.linalg.svd(A)
    s = np.concatenate([s, np.zeros(12 - len(s))])
    k = int(np.sum(s < tol * s[0]))
    return vt[12 - k:].T, k


def planar_rotations(K, plane):
    """Rotations from a kernel K containing the family a [n^T d]: a quotient of dimension 1 (four
    features or more, except 2P+2L) gives M directly; of dimension 2 (2P+2L), M = b1 M1 + b2 M2 with
    |M e1| = |M e2| and M e1 . M e2 = 0, two quadrics in [b1^2, b1 b2, b2^2] whose common root is
    the cross product of their coefficient rows."""
    n = plane[:3] / np.linalg.norm(plane[:3])
    # Family basis: vec(e_i plane^T), i = 1..3 (column-major, v = [r1; r2; r3; t]).
    F = np.stack([np.kron(plane, e) for e in np.eye(3)], axis=1)
    Qf, _ = np.linalg.qr(F)
    W = K - Qf @ (Qf.T @ K)                    # quotient representatives
    u, s, _ = np.linalg.svd(W)
    e1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    if K.shape[1] == 4:
        M = u[:, 0][:9].reshape(3, 3, order="F")   # rotation block, columns r1 r2 r3
    else:
        M1, M2 = (u[:, k][:9].reshape(3, 3, order="F") for k in (0, 1))
        a1, b1, a2, b2 = M1 @ e1, M1 @ e2, M2 @ e1, M2 @ e2
        q1 = [a1 @ a1 - b1 @ b1, 2 * (a1 @ a2 - b1 @ b2), a2 @ a2 - b2 @ b2]
        q2 = [a1 @ b1, a1 @ b2 + a2 @ b1, a2 @ b2]
        m = np.cross(q1, q2)
        beta = m[:2] if abs(m[0]) >= abs(m[2]) else m[1:]
        M = beta[0] * M1 + beta[1] * M2
    out = []
    for sign in (1, -1):
        a, b = sign * M @ e1, sign * M @ e2
        scale = np.sqrt((a @ a + b @ b) / 2)
        a, b = a / scale, b / scale
        E = np.stack([e1, e2, n], axis=1)
        out.append(np.stack([a, b, np.cross(a, b)], axis=1) @ E.T)
    return out


def main():
    rng = np.random.default_rng(0)
    mixes = [(4, 0), (0, 4), (2, 2), (3, 1), (1, 3), (3, 2), (2, 3), (5, 0), (0, 5), (3, 3), (6, 0),
             (0, 6), (4, 4), (10, 10)]
    print("mix       general  planar  planar closed form (max rotation error, rad)")
    for p, l in mixes:
        dims = {False: set(), True: set()}
        worst = 0.0
        for trial in range(200):
            for planar in (False, True):
                A, R, t, plane = scene(rng, p, l, planar)
                K, k = kernel(A)
                dims[planar].add(k)
                if planar:
                    errs = [np.linalg.norm(Rc - R) for Rc in planar_rotations(K, plane)]
                    worst = max(worst, min(errs))
        print(f"{p}P+{l}L".ljust(10), str(sorted(dims[False])).ljust(8), str(sorted(dims[True])).ljust(7),
              f"{worst:.1e}" if worst else "-")


if __name__ == "__main__":
    main()
