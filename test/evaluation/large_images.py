# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""Images larger than the front end's --max-image-size (doc/studies/real_images.md, "Large images"): the
bundled Merton College I triplet enlarged to a 12-megapixel camera's size (4096 x 3072, bicubic,
JPEG quality 92, the calibration enlarged with it), then the C++ tripose_images and the Python
sample at several --max-image-size values: the whole process's wall-clock time and peak memory,
the tracks, and the errors against the sequence's camera.

    python test/evaluation/large_images.py [--sizes 1024 1600 2048 0] [--python <python with tripose>]

The C++ tool comes from build/samples; the Python sample runs under --python (default: this
interpreter), which needs the tripose package and opencv-contrib-python. An enlarged image has no
detail finer than the original's: the table shows what reduced detection costs in time and
memory, not the accuracy a real 12-megapixel camera would give. Each row is one run.
"""

import argparse
import sys
import tempfile
import time
from pathlib import Path

import cv2
import numpy as np

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "test" / "python"))
from tripose_tools import MERTON_CALIB as CALIB, enlarged_merton, run_with_peak_memory  # noqa: E402

ENLARGEMENT = 4


def read(path, key):
    fs = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    value = fs.getNode(key).mat()
    fs.release()
    return value


def run_measured(command):
    """Wall-clock seconds and peak resident memory (MiB) of @p command; raises when it fails."""
    start = time.perf_counter()
    status, peak, output = run_with_peak_memory(command)
    seconds = time.perf_counter() - start
    if status != 0:
        raise RuntimeError(f"{command[0]} failed: {output}")
    return seconds, peak


def errors(result):
    """Rotation error (deg) and camera centre error (% of its distance from view 1's) against the
    sequence's camera."""
    R, t = read(result, "R"), read(result, "t")
    R_gt, t_gt = read(CALIB, "R_gt"), read(CALIB, "t_gt")
    angle = np.degrees(np.arccos(np.clip((np.trace(R.T @ R_gt) - 1) / 2, -1, 1)))
    centre, centre_gt = -R.T @ t, -R_gt.T @ t_gt
    return angle, 100 * np.linalg.norm(centre - centre_gt) / np.linalg.norm(centre_gt)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[1024, 1600, 2048, 0])
    parser.add_argument("--python", default=sys.executable, help="Python with the tripose package")
    parser.add_argument("--build", default=str(REPO / "build"))
    args = parser.parse_args()
    tool = Path(args.build) / "samples" / "tripose_images"
    sample = REPO / "samples" / "python" / "pose_from_images.py"
    print("| front end | --max-image-size | time (s) | peak memory (MiB) | point tracks | segment triplets "
          "| rotation (deg) | centre (%) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        calib, images = enlarged_merton(folder, ENLARGEMENT, ".jpg", (cv2.IMWRITE_JPEG_QUALITY, 92))
        for size in args.sizes:
            for name, program in (("C++", [tool]), ("Python", [args.python, sample])):
                out = folder / f"{name}_{size}.yml"
                seconds, peak = run_measured([*program, "--calib", calib, "--images", *images, "--output", out,
                                              "--max-image-size", size])
                rotation, centre = errors(out)
                tracks, triplets = (len(read(out, key)) for key in ("points1", "lines1"))
                print(f"| {name} | {size or 'full'} | {seconds:.1f} | {peak:.0f} | {tracks} | {triplets} "
                      f"| {rotation:.3f} | {centre:.3f} |", flush=True)


if __name__ == "__main__":
    main()
