"""Estimates the pose of the third view of an Oxford VGG sequence (default: Merton College I,
views 0, 1, 2) from the points and lines seen in all three views, with tripose's RANSAC and
refinement, and prints its error against the sequence's own camera.

    python samples/python/estimate_pose.py [--data <sequence folder>] [--views 0 1 2]
"""
import argparse
import time
from pathlib import Path

import numpy as np

import tripose
from vgg import load_triplet

DEFAULT_DATA = Path(__file__).resolve().parents[2] / "test" / "data" / "vgg" / "Merton-College-I"


def rotation_error_deg(A, B):
    """Angle of A B^T in degrees, accurate near zero."""
    d = np.linalg.norm(A - B) / (2.0 * np.sqrt(2.0))
    return np.degrees(2.0 * np.arcsin(min(1.0, d)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, default=DEFAULT_DATA, help="VGG sequence folder")
    parser.add_argument("--views", type=int, nargs=3, default=[0, 1, 2], help="three views; the third is estimated")
    parser.add_argument("--threshold", type=float, default=2.0, help="RANSAC inlier threshold (px)")
    args = parser.parse_args()

    triplet = load_triplet(args.data, tuple(args.views))
    print(f"Sequence {args.data}, views {args.views}: {len(triplet.points[0])} point and "
          f"{len(triplet.lines[0])} line triplets")
    options = tripose.RansacOptions()
    options.threshold = args.threshold
    start = time.perf_counter()
    result = tripose.estimate_pose_line_point_ransac(*triplet.points, *triplet.lines, triplet.K, triplet.R12,
                                                     triplet.t12, options=options)
    elapsed = time.perf_counter() - start
    if result.R is None:
        raise SystemExit("no pose found")
    R, t = result.R, result.t
    np.set_printoptions(precision=6, suppress=True)
    print(f"Solved in {1e3 * elapsed:.3f} ms: {result.num_inliers} inliers of "
          f"{len(triplet.points[0]) + len(triplet.lines[0])}, RMS {result.rms:.3f} px")
    print(f"Estimated R =\n{R}\nGround truth R =\n{triplet.R}")
    print(f"Estimated t = {t}\nGround truth t = {triplet.t}")
    direction = np.degrees(np.arccos(np.clip(t @ triplet.t / (np.linalg.norm(t) * np.linalg.norm(triplet.t)), -1, 1)))
    print(f"Rotation error: {rotation_error_deg(R, triplet.R):.4f} deg")
    print(f"Translation error: {100 * np.linalg.norm(t - triplet.t) / np.linalg.norm(triplet.t):.2f} % of |t| "
          f"(direction {direction:.4f} deg)")
    # The linear estimate on every triplet, without RANSAC or refinement: what the C++ demo
    # tripose_demo_vgg prints for the same views.
    linear = tripose.estimate_pose_line_point(*triplet.points, *triplet.lines, triplet.K, triplet.R12, triplet.t12)
    if linear.R is not None:
        print(f"Linear estimate on all triplets: rotation error {rotation_error_deg(linear.R, triplet.R):.4f} deg")


if __name__ == "__main__":
    main()
