# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Why the image front end's matches give larger pose errors than a sequence's own correspondences.

    .venv/bin/python test/evaluation/image_error_gap.py --data <VGG folder with images> [--build build]
        [--threshold 2] [--estimate-options --loss squared]

For every run of three consecutive frames: tripose_images (the front end and the robust estimate)
on the frames, calibrated by tripose_images_report --calib-output from the sequence's cameras;
tripose_estimate again on the matched problem (with tripose_images' refinement) for the pose
covariance. Per triplet it prints:

- the estimate's rotation error against the sequence's camera, and how many standard deviations
  that is by the estimate's own first-order covariance (Mahalanobis distance over the six pose
  parameters, noise variance from the residuals): a distance of a few means the matches say what
  they can, a large one that they are biased (or the sequence's camera is off);
- the point tracks' reprojection residuals, each track triangulated from its three views, at the
  sequence's cameras and at the estimate (median, and the share above 1 px), for the tracks the
  estimate kept as inliers;
- the same residuals of the sequence's own corner tracks at the sequence's cameras: how well those
  cameras explain the corners they were computed from;
- the inlier segment triplets' residuals at the sequence's cameras (end points' distances to the
  projection of the 3D line fitted to the three views' planes).
"""

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import cv2
import numpy as np


def run(cmd):
    proc = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed ({proc.returncode}): {proc.stderr}")
    return proc.stdout


def read(path, keys):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    if not fs.isOpened():
        raise RuntimeError(f"cannot read {path}")
    out = {}
    for k in keys:
        node = fs.getNode(k)
        if node.empty():
            out[k] = None
        elif node.isString():
            out[k] = node.string()
        elif node.isReal() or node.isInt():
            out[k] = node.real()
        else:
            out[k] = node.mat()
    fs.release()
    return out


def rotation_vector(R):
    return cv2.Rodrigues(np.asarray(R, np.float64))[0].ravel()


def triangulate(Ps, xs):
    """Each row of xs[v] (N x 2) triangulated from all views (DLT on pixels), N x 3."""
    n = len(xs[0])
    X = np.zeros((n, 3))
    for i in range(n):
        A = []
        for P, x in zip(Ps, xs):
            A.append(x[i, 0] * P[2] - P[0])
            A.append(x[i, 1] * P[2] - P[1])
        A = np.array(A)
        A /= np.linalg.norm(A, axis=1, keepdims=True)
        h = np.linalg.svd(A)[2][-1]
        X[i] = h[:3] / h[3]
    return X


def refine_points(Ps, xs, X, iterations=5):
    """Gauss-Newton on each point's reprojection error over all views (the optimal triangulation)."""
    X = X.copy()
    for _ in range(iterations):
        JtJ = np.zeros((len(X), 3, 3))
        Jtr = np.zeros((len(X), 3))
        for P, x in zip(Ps, xs):
            h = X @ P[:, :3].T + P[:, 3]
            u, v, w = h[:, 0], h[:, 1], h[:, 2]
            r = np.stack([u / w - x[:, 0], v / w - x[:, 1]], axis=1)
            J = np.stack([(P[0, :3][None] * w[:, None] - P[2, :3][None] * u[:, None]) / (w * w)[:, None],
                          (P[1, :3][None] * w[:, None] - P[2, :3][None] * v[:, None]) / (w * w)[:, None]], axis=1)
            JtJ += np.einsum("nki,nkj->nij", J, J)
            Jtr += np.einsum("nki,nk->ni", J, r)
        X -= np.linalg.solve(JtJ + 1e-12 * np.eye(3), Jtr[..., None])[..., 0]
    return X


def track_residuals(Ps, xs):
    """Per track, the RMS over its views of the optimally triangulated point's reprojection error (px)."""
    X = refine_points(Ps, xs, triangulate(Ps, xs))
    sq = np.zeros(len(X))
    for P, x in zip(Ps, xs):
        h = X @ P[:, :3].T + P[:, 3]
        sq += np.sum((h[:, :2] / h[:, 2:3] - x) ** 2, axis=1)
    return np.sqrt(sq / len(Ps))


def segment_residuals(Ps, segments):
    """Per segment triplet, the RMS over its views of its end points' distances to the projection of
    the 3D line that best fits the three views' planes (px)."""
    def line_through(s):
        l = np.cross([s[0], s[1], 1.0], [s[2], s[3], 1.0])
        return l / np.hypot(l[0], l[1])

    out = []
    for i in range(len(segments[0])):
        planes = np.array([P.T @ line_through(seg[i]) for P, seg in zip(Ps, segments)])
        planes /= np.linalg.norm(planes[:, :3], axis=1, keepdims=True)
        A, B = np.linalg.svd(planes)[2][-2:]  # two points spanning the line
        d = []
        for P, seg in zip(Ps, segments):
            line = np.cross(P @ A, P @ B)
            line /= np.hypot(line[0], line[1])
            d += [line @ [seg[i][0], seg[i][1], 1.0], line @ [seg[i][2], seg[i][3], 1.0]]
        out.append(np.sqrt(np.mean(np.square(d))))
    return np.array(out)


def projections(calib, R3, t3):
    K = [calib[f"K{v}"] for v in (1, 2, 3)]
    return [K[0] @ np.hstack([np.eye(3), np.zeros((3, 1))]),
            K[1] @ np.hstack([calib["R12"], calib["t12"].reshape(3, 1)]),
            K[2] @ np.hstack([R3, np.asarray(t3).reshape(3, 1)])]


def own_tracks(folder, views):
    """The sequence's own corner tracks seen in all of `views` (pixels per view)."""
    corners = sorted(Path(folder).glob("*.corners"))
    table = [line.split() for line in (next(Path(folder).glob("*.nview-corners"))).read_text().splitlines() if line.strip()]
    xy = [np.loadtxt(corners[v]) for v in views]
    rows = [r for r in table if all(r[v] != "*" for v in views)]
    return [np.array([xy[k][int(r[v])] for r in rows]) for k, v in enumerate(views)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, help="VGG sequence folder with its images")
    ap.add_argument("--build", default="build")
    ap.add_argument("--threshold", type=float, default=2.0)
    ap.add_argument("--frames", type=int, default=0, help="first frames of the sequence only (0: all)")
    ap.add_argument("--estimate-options", nargs="*", default=["--loss", "cauchy", "--loss-scale", "0.5"],
                    help="tripose_estimate's refinement, as tripose_images refines (default: Cauchy, 0.5 px)")
    a = ap.parse_args()
    samples = Path(a.build) / "samples"
    images = sorted(p for p in Path(a.data).iterdir() if p.suffix.lower() in (".pgm", ".png", ".jpg", ".ppm"))
    count = len(images) if a.frames == 0 else min(a.frames, len(images))

    print("| views | tracks | inliers | rot err (deg) | Mahalanobis (6 dof) | sigma (px) | "
          "inlier residual at truth: median (px) | > 1 px | at estimate: median (px) | > 1 px | "
          "own corners at truth: median (px) | > 1 px | inlier segments | at truth: median (px) | > 1 px |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for k in range(count - 2):
            views = (k, k + 1, k + 2)
            calib_path, result_path, again_path = tmp / "calib.yml", tmp / "result.yml", tmp / "again.yml"
            run([Path(a.build) / "test" / "evaluation" / "tripose_images_report", "--data", a.data, "--calib-output", calib_path,
                 "--views", *views])
            run([samples / "tripose_images", "--calib", calib_path, "--images", *[images[v] for v in views],
                 "--output", result_path, "--threshold", a.threshold])
            run([samples / "tripose_estimate", "--input", result_path, "--output", again_path, "--method", "ransac",
                 "--threshold", a.threshold, "--allow-unknown-keys", *a.estimate_options])
            calib = read(calib_path, ["K1", "K2", "K3", "R12", "t12", "R_gt", "t_gt"])
            res = read(result_path, ["points1", "points2", "points3", "point_inliers", "lines1", "lines2", "lines3",
                                     "line_inliers"])
            est = read(again_path, ["R", "t", "covariance", "noise_variance"])
            R, t = est["R"], est["t"].ravel()
            R_gt, t_gt = calib["R_gt"], calib["t_gt"].ravel()
            # The conventions' left rotation error: R_est = exp([d]x) R_true.
            d = rotation_vector(R @ R_gt.T)
            e = np.concatenate([d, t - t_gt])
            C = est["covariance"] * est["noise_variance"]
            mahalanobis = float(np.sqrt(e @ np.linalg.solve(C, e)))
            xs = [res[f"points{v}"] for v in (1, 2, 3)]
            inl = res["point_inliers"].ravel().astype(bool)
            xs_in = [x[inl] for x in xs]
            at_truth = track_residuals(projections(calib, R_gt, t_gt), xs_in)
            at_estimate = track_residuals(projections(calib, R, t), xs_in)
            own = track_residuals(projections(calib, R_gt, t_gt), own_tracks(a.data, views))
            segments = [res[f"lines{v}"] for v in (1, 2, 3)]
            seg = np.zeros(0)
            if segments[0] is not None and len(segments[0]):
                keep = res["line_inliers"].ravel().astype(bool)
                seg = segment_residuals(projections(calib, R_gt, t_gt), [x[keep] for x in segments])
            print(f"| {views[0]}-{views[1]}-{views[2]} | {len(xs[0])} | {int(inl.sum())} | "
                  f"{np.degrees(np.linalg.norm(d)):.3f} | {mahalanobis:.1f} | {np.sqrt(est['noise_variance']):.2f} | "
                  f"{np.median(at_truth):.2f} | {100 * np.mean(at_truth > 1):.0f} % | "
                  f"{np.median(at_estimate):.2f} | {100 * np.mean(at_estimate > 1):.0f} % | "
                  f"{np.median(own):.2f} | {100 * np.mean(own > 1):.0f} % | {len(seg)} | "
                  f"{np.median(seg) if len(seg) else np.nan:.2f} | {100 * np.mean(seg > 1) if len(seg) else np.nan:.0f} % |",
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
