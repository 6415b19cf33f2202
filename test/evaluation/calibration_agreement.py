# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.

"""How the front ends tell a calibration that contradicts images 1 and 2 (doc/studies/real_images.md,
"A calibration that contradicts the images"): for every consecutive pair of a VGG sequence with
images, the share of the descriptor matches found without the calibration (tripose.match_triplets'
pair_agreement: up to 300 points of the first image against all of the second) that lie within 2 px
of the epipolar lines of the sequence's cameras, and of the usual mistakes: view 2's pose inverted,
the two images swapped, the first image given twice. The front ends warn under 30 % (of 20 matches
or more).

    python test/evaluation/calibration_agreement.py --data <VGG folder with images> [--data ...]

Needs the tripose package with its images extra (pip install ".[images]").
"""

import argparse
import sys
from pathlib import Path

import numpy as np
import tripose
import tripose.images as images

root = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(root / "samples" / "python"))
import vgg  # noqa: E402


def contradicts(matches, agreeing):
    """The front ends' warning: under 30 % of 20 or more matches agree."""
    return matches >= 20 and agreeing < 0.3 * matches


def share(a, b, K, R12, t12):
    """pair_agreement of features a and b as views 1 and 2 at [R12 | t12] (view 3 is not used by it;
    b stands in for it)."""
    matches, agreeing = tripose.match_triplets(a, b, b, K, R12, t12)["pair_agreement"]
    return f"{agreeing}/{matches} ({100 * agreeing / max(matches, 1):.0f} %)" + (
        " warned" if contradicts(matches, agreeing) else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True, action="append")
    a = ap.parse_args()
    print("| pair | the sequence's cameras | view 2's pose inverted | images swapped | first image twice |")
    print("| --- | --- | --- | --- | --- |")
    for folder in a.data:
        files = sorted(p for p in Path(folder).iterdir() if p.suffix.lower() in (".pgm", ".png", ".jpg", ".ppm"))
        points = images.FeatureOptions(kinds="points")
        features = [images.extract_features(images.read_image(p), np.eye(3), None, points) for p in files]
        for first in range(len(files) - 1):
            third = first + 2 if first + 2 < len(files) else first - 1  # any other view: only 1-2 are used
            t = vgg.load_triplet(folder, (first, first + 1, third))
            K = list(t.K)
            given = (K, t.R12, t.t12)
            inverted = (K, t.R12.T, -t.R12.T @ t.t12)
            a1, a2 = features[first], features[first + 1]
            print(f"| {Path(folder).name} {first}-{first + 1} | {share(a1, a2, *given)} | {share(a1, a2, *inverted)} | "
                  f"{share(a2, a1, *given)} | {share(a1, a1, *given)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
