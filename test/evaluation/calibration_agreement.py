# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How the front ends tell a calibration that contradicts images 1 and 2 (doc/studies/real_images.md,
"A calibration that contradicts the images"): for every consecutive pair of a VGG sequence with
images, the share of the Python sample's descriptor matches found without the calibration
(epipolar_agreement(): up to 300 points of the first image against all of the second) that lie
within 2 px of the epipolar lines of the sequence's cameras, and of the usual mistakes: view 2's pose
inverted, the two images swapped, the first image given twice. The front ends warn under 30 %.

    .venv/bin/python test/evaluation/calibration_agreement.py --data <VGG folder with images> [--data ...]
"""

import argparse
import sys
from pathlib import Path

import cv2

root = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "samples" / "python"))
import pose_from_images as front  # noqa: E402
import vgg  # noqa: E402


def share(a, b, F):
    matches, agreeing = front.epipolar_agreement(a, b, F)
    return f"{agreeing}/{matches} ({100 * agreeing / max(matches, 1):.0f} %)" + (
        " warned" if front.contradicts(matches, agreeing) else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, action="append")
    a = ap.parse_args()
    print("| pair | the sequence's cameras | view 2's pose inverted | images swapped | first image twice |")
    print("| --- | --- | --- | --- | --- |")
    for folder in a.data:
        images = sorted(p for p in Path(folder).iterdir() if p.suffix.lower() in (".pgm", ".png", ".jpg", ".ppm"))
        features = [front.extract(cv2.imread(str(p), cv2.IMREAD_GRAYSCALE), None, None, "points") for p in images]
        for first in range(len(images) - 1):
            third = first + 2 if first + 2 < len(images) else first - 1  # any other view: only 1-2 are used
            t = vgg.load_triplet(folder, (first, first + 1, third))
            F = front.fundamental(t.K[0], t.K[1], t.R12, t.t12)
            inverted = front.fundamental(t.K[0], t.K[1], t.R12.T, -t.R12.T @ t.t12)
            a1, a2 = features[first], features[first + 1]
            print(f"| {Path(folder).name} {first}-{first + 1} | {share(a1, a2, F)} | {share(a1, a2, inverted)} | "
                  f"{share(a2, a1, F)} | {share(a1, a1, F)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
