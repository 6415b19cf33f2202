# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How far the sequence's cameras are from what their own correspondences say, and the image front
end's estimates measured against both (doc/studies/real_images.md, "Where the error came from").

    python test/evaluation/images_vs_own_fit.py --data <VGG folder with images> \
        [--tool build/test/evaluation/tripose_images_report]

Needs the tripose package (pip install .) and the report tool. For every run of three consecutive
frames: the maximum-likelihood fit of view 3 to the sequence's own correspondences of the triplet
(RANSAC, then refinement from its pose; the same refinement from the sequence's camera must agree),
its rotation standard deviation (first-order covariance, noise from the residuals), the sequence's
camera in standard deviations of that fit (Mahalanobis, rotation), and the rotation errors of
tripose on the front end's matches (points and lines, points only; estimate_pose_line_point_ransac
refining under the samples' Cauchy loss, as samples/python/pose_from_images.py) against the camera
and against the fit.
"""

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np
import tripose

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "samples" / "python"))
import vgg  # noqa: E402
from images_vs_poselib import front_end_triplets  # noqa: E402

# The refinement's Cauchy loss scale (px) for detected features, as the samples
# (samples/common/image_estimation.hpp, samples/python/pose_from_images.py).
IMAGE_LOSS_SCALE = 0.5


def rotation_deg(Ra, Rb):
    return float(np.degrees(np.linalg.norm(cv2.Rodrigues(np.asarray(Ra) @ np.asarray(Rb).T)[0])))


def front_end_rotation(points, lines, K, R12, t12, threshold, seed):
    """View 3's rotation by tripose on the front end's matches as the image samples estimate it:
    RANSAC, then the refinement over its inliers under the Cauchy loss; no floor on the inliers."""
    options = tripose.RansacOptions()
    options.threshold = threshold
    options.seed = seed
    options.min_inliers = 0
    options.refine_options.loss = "cauchy"
    options.refine_options.loss_scale = IMAGE_LOSS_SCALE
    return tripose.estimate_pose_line_point_ransac(*points, *lines, K, R12, t12, options=options).R


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, help="VGG sequence folder with its images")
    ap.add_argument("--tool", default=str(ROOT / "build" / "test" / "evaluation" / "tripose_images_report"))
    ap.add_argument("--threshold", type=float, default=2.0)
    a = ap.parse_args()
    triplets = front_end_triplets(a.tool, a.data, a.threshold)

    print("| views | own features | fit vs camera (deg) | fit sd (deg) | camera (sd of fit) | P+L vs camera | "
          "P vs camera | P+L vs fit | P vs fit |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    for tr in triplets:
        own = vgg.load_triplet(a.data, tuple(tr["views"]))
        ransac = tripose.RansacOptions()
        ransac.threshold = a.threshold
        ransac.seed = 0
        robust = tripose.estimate_pose_line_point_ransac(*own.points, *own.lines, own.K, own.R12, own.t12,
                                                         options=ransac)
        refine = tripose.RefineOptions()
        refine.max_iterations = 300
        fit = tripose.refine_pose_line_point(*own.points, *own.lines, own.K, own.R12, own.t12, robust.R, robust.t,
                                             options=refine)
        seeded = tripose.refine_pose_line_point(*own.points, *own.lines, own.K, own.R12, own.t12, own.R, own.t,
                                                options=refine)
        if rotation_deg(fit.R, seeded.R) > 1e-3:
            print(f"{tr['views']}: the fit from the RANSAC and from the camera differ", file=sys.stderr)
        C = np.asarray(fit.covariance)[:3, :3] * fit.noise_variance
        d = cv2.Rodrigues(own.R @ np.asarray(fit.R).T)[0].ravel()
        K = [np.array(k) for k in tr["K"]]
        R12, t12 = np.array(tr["R12"]), np.array(tr["t12"]).ravel()
        points = [np.array(tr[f"points{v}"]).reshape(-1, 2) for v in (1, 2, 3)]
        lines = [np.array(tr[f"lines{v}"]).reshape(-1, 4) for v in (1, 2, 3)]
        both = front_end_rotation(points, lines, K, R12, t12, a.threshold, 0)
        alone = front_end_rotation(points, [l[:0] for l in lines], K, R12, t12, a.threshold, 0)
        row = [rotation_deg(fit.R, own.R), float(np.degrees(np.sqrt(np.trace(C)))), float(np.sqrt(d @ np.linalg.solve(C, d))),
               rotation_deg(both, own.R), rotation_deg(alone, own.R), rotation_deg(both, fit.R), rotation_deg(alone, fit.R)]
        rows.append(row)
        views = "-".join(map(str, tr["views"]))
        print(f"| {views} | {len(own.points[0])} + {len(own.lines[0])} | " + " | ".join(f"{v:.3f}" for v in row) + " |")
    rows = np.array(rows)
    print("| median | - | " + " | ".join(f"{v:.3f}" for v in np.median(rows, axis=0)) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
