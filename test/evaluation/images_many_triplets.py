# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""The image front end on more triplets than the consecutive ones (doc/studies/real_images.md, "Segments:
EDLines fitted to their edges"): points and lines against points only, by tripose_images.

    .venv/bin/python test/evaluation/images_many_triplets.py --model-house <Model House folder with its images> \
        [--merton test/data/vgg/Merton-College-I] [--build build]

Triplets (views 1, 2, 3): Model House's (i, i+1, i+2), (i, i+1, i+3), (i, i+2, i+3) and
(i+2, i+1, i), and Merton College I's six orders of its three views: 36 in all. Each is calibrated
from the sequence's cameras (tripose_images_report --calib-output) and run through tripose_images
with --features all and --features points; prints each triplet's rotation errors against the
sequence's camera (deg) and a summary: medians, means, largest, and in how many triplets points and
lines are below points alone. --build points at the build whose samples to run, so that two front
ends can be compared on the same triplets.
"""

import argparse
import itertools
import subprocess
import sys
import tempfile
from pathlib import Path

import cv2
import numpy as np


def read(path, key):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    value = fs.getNode(key).mat()
    fs.release()
    return value


def rotation_deg(R, truth):
    return float(np.degrees(np.arccos(np.clip((np.trace(R.T @ truth) - 1) / 2, -1, 1))))


def main():
    root = Path(__file__).resolve().parents[2]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--model-house", required=True, help="Model House folder with its images")
    ap.add_argument("--merton", default=str(root / "test" / "data" / "vgg" / "Merton-College-I"))
    ap.add_argument("--build", default=str(root / "build"))
    a = ap.parse_args()
    samples = Path(a.build) / "samples"
    triplets = [(a.model_house, (i, i + 1, i + 2)) for i in range(8)]
    triplets += [(a.model_house, (i, i + 1, i + 3)) for i in range(7)]
    triplets += [(a.model_house, (i, i + 2, i + 3)) for i in range(7)]
    triplets += [(a.model_house, (i + 2, i + 1, i)) for i in range(8)]
    triplets += [(a.merton, v) for v in itertools.permutations((0, 1, 2))]
    print("| sequence | views | points+lines (deg) | points only (deg) |\n| --- | --- | --- | --- |")
    errors = []
    with tempfile.TemporaryDirectory() as tmp:
        for folder, views in triplets:
            images = sorted(p for p in Path(folder).iterdir() if p.suffix in (".pgm", ".jpg", ".png"))
            calib = Path(tmp) / "calib.yml"
            subprocess.run([str(Path(a.build) / "test" / "evaluation" / "tripose_images_report"), "--data", folder, "--calib-output", str(calib),
                            "--views", *map(str, views)], check=True, capture_output=True)
            truth = read(calib, "R_gt")
            row = []
            for kinds in ("all", "points"):
                out = Path(tmp) / "result.yml"
                proc = subprocess.run([str(samples / "tripose_images"), "--calib", str(calib), "--images",
                                       *[str(images[v]) for v in views], "--output", str(out), "--features", kinds],
                                      capture_output=True, text=True)
                row.append(rotation_deg(read(out, "R"), truth) if proc.returncode == 0 else np.inf)
            errors.append(row)
            print(f"| {Path(folder).name} | {'-'.join(map(str, views))} | {row[0]:.3f} | {row[1]:.3f} |", flush=True)
    e = np.array(errors)
    print(f"\nmedian {np.median(e[:, 0]):.4f} / {np.median(e[:, 1]):.4f} deg, mean {e[:, 0].mean():.4f} / "
          f"{e[:, 1].mean():.4f}, largest {e[:, 0].max():.3f} / {e[:, 1].max():.3f} (points+lines / points only); "
          f"points+lines below points only in {int(np.sum(e[:, 0] < e[:, 1]))} of {len(e)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
