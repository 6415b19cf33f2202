# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""The accuracy floor of tracking a VGG sequence from its first two cameras, computed independently
of the module (numpy only, points only): the maximum-likelihood estimate of every camera from 2 on
and of the points, with cameras 0 and 1 fixed at the sequence's poses (Levenberg-Marquardt on the
reprojection error, Jacobians by finite differences), and the standard deviation of the last
camera's centre that the estimate's covariance gives (sigma^2 (J^T J)^-1, sigma from the residuals).

    .venv/bin/python test/evaluation/sequence_ml_floor.py test/data/vgg/Corridor     # about a minute

Prints the RMS error at the sequence's poses (points re-fitted) and at the estimate, and the last
camera's distance from the sequence's in % of the path, beside its standard deviation. doc/studies/tracking.md
quotes it for Corridor.
"""

import argparse
from pathlib import Path

import numpy as np


def rq(M):
    """M = K R with K upper triangular, positive diagonal, R orthonormal."""
    Q, R = np.linalg.qr(np.flipud(M).T)
    K = np.fliplr(np.flipud(R.T))
    Rot = np.flipud(Q.T)
    S = np.diag(np.sign(np.diag(K)))
    return K @ S, S @ Rot


def load(folder):
    folder = Path(folder)
    cameras = sorted(folder.glob("*.P"))
    Ks, Rs, ts = [], [], []
    for path in cameras:
        P = np.loadtxt(path)
        K, R = rq(P[:, :3])
        t = np.linalg.solve(K, P[:, 3])
        if np.linalg.det(R) < 0:
            R, t = -R, -t
        Ks.append(K / K[2, 2])
        Rs.append(R)
        ts.append(t)
    corners = [np.loadtxt(p.with_suffix(".corners")) for p in cameras]
    table = [line.split() for line in next(folder.glob("*nview-corners")).read_text().splitlines() if line.strip()]
    obs = [(i, k, corners[k][int(row[k])]) for i, row in enumerate(table) for k in range(len(cameras))
           if row[k] != "*"]
    return Ks, Rs, ts, obs, len(table)


def rotation(w):
    angle = np.linalg.norm(w)
    if angle < 1e-15:
        return np.eye(3)
    k = w / angle
    S = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * S + (1 - np.cos(angle)) * S @ S


def centre(R, t):
    return -R.T @ t


class Problem:
    def __init__(self, folder):
        self.Ks, self.Rs, self.ts, obs, self.n = load(folder)
        self.point = np.array([o[0] for o in obs])
        self.frame = np.array([o[1] for o in obs])
        self.pixel = np.array([o[2] for o in obs])
        self.free = list(range(2, len(self.Ks)))

    def residuals(self, Rs, ts, X):
        r = np.zeros_like(self.pixel)
        for k in range(len(self.Ks)):
            m = self.frame == k
            y = (X[self.point[m]] @ Rs[k].T + ts[k]) @ self.Ks[k].T
            r[m] = y[:, :2] / y[:, 2:] - self.pixel[m]
        return r.ravel()

    def moved(self, Rs, ts, X, step):
        Rs, ts = list(Rs), list(ts)
        for a, k in enumerate(self.free):
            w, dt = step[6 * a:6 * a + 3], step[6 * a + 3:6 * a + 6]
            Rs[k] = rotation(w) @ Rs[k]
            ts[k] = rotation(w) @ ts[k] + dt
        return Rs, ts, X + step[6 * len(self.free):].reshape(-1, 3)

    def jacobian(self, Rs, ts, X, free_poses=True, eps=1e-6):
        r = self.residuals(Rs, ts, X)
        poses = 6 * len(self.free) if free_poses else 0
        J = np.zeros((len(r), poses + 3 * self.n))
        for c in range(poses):
            step = np.zeros(6 * len(self.free) + 3 * self.n)
            step[c] = eps
            J[:, c] = (self.residuals(*self.moved(Rs, ts, X, step)) - r) / eps
        rows = np.arange(len(self.point))
        for j in range(3):
            Y = X.copy()
            Y[:, j] += eps
            d = ((self.residuals(Rs, ts, Y) - r) / eps).reshape(-1, 2)
            J[2 * rows, poses + 3 * self.point + j] = d[:, 0]
            J[2 * rows + 1, poses + 3 * self.point + j] = d[:, 1]
        return r, J

    def solve(self, Rs, ts, X, free_poses=True, iterations=30):
        lam = 1e-3
        for _ in range(iterations):
            r, J = self.jacobian(Rs, ts, X, free_poses)
            H, g = J.T @ J, J.T @ r
            while lam < 1e10:
                d = -np.linalg.solve(H + lam * np.diag(np.diag(H)), g)
                step = d if free_poses else np.concatenate([np.zeros(6 * len(self.free)), d])
                trial = self.moved(Rs, ts, X, step)
                if self.residuals(*trial) @ self.residuals(*trial) < r @ r:
                    Rs, ts, X = trial
                    lam /= 3
                    break
                lam *= 5
            if np.linalg.norm(d) < 1e-10 or lam >= 1e10:
                break
        return Rs, ts, X


def triangulate(p):
    X = np.zeros((p.n, 3))
    for i in range(p.n):
        rows = []
        for k, x in zip(p.frame[p.point == i], p.pixel[p.point == i]):
            P = p.Ks[k] @ np.hstack([p.Rs[k], p.ts[k][:, None]])
            rows += [x[0] * P[2] - P[0], x[1] * P[2] - P[1]]
        X[i] = (lambda v: v[:3] / v[3])(np.linalg.svd(np.array(rows))[2][-1])
    return X


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sequence")
    args = parser.parse_args()
    p = Problem(args.sequence)
    F = len(p.Ks)
    path = sum(np.linalg.norm(centre(p.Rs[k], p.ts[k]) - centre(p.Rs[k - 1], p.ts[k - 1])) for k in range(1, F))
    rms = lambda Rs, ts, X: np.sqrt(np.mean(p.residuals(Rs, ts, X) ** 2) * 2)
    X0 = triangulate(p)
    _, _, Xref = p.solve(p.Rs, p.ts, X0, free_poses=False)
    print(f"{F} cameras, {p.n} points, {len(p.point)} observations, path {path:.4g}")
    print(f"RMS at the sequence's poses (points re-fitted): {rms(p.Rs, p.ts, Xref):.4f} px")
    Rs, ts, X = p.solve(p.Rs, p.ts, Xref)
    r, J = p.jacobian(Rs, ts, X)
    sigma2 = (r @ r) / (len(r) - J.shape[1])
    a = len(p.free) - 1
    pose_cov = sigma2 * np.linalg.inv(J.T @ J)[6 * a:6 * a + 6, 6 * a:6 * a + 6]
    dcentre = np.hstack([np.zeros((3, 3)), -Rs[F - 1].T])  # c = -R^T t under R <- Exp(w) R, t <- Exp(w) t + dt
    std = np.sqrt(np.trace(dcentre @ pose_cov @ dcentre.T))
    distance = np.linalg.norm(centre(Rs[F - 1], ts[F - 1]) - centre(p.Rs[F - 1], p.ts[F - 1]))
    print(f"RMS at the maximum-likelihood estimate (cameras 0 and 1 fixed): {rms(Rs, ts, X):.4f} px")
    print(f"last camera: {100 * distance / path:.3f} % of the path from the sequence's, "
          f"standard deviation {100 * std / path:.3f} % of the path")


if __name__ == "__main__":
    main()
