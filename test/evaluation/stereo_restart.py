"""The stereo tracker lost for a long stretch (doc/studies/front_end_and_tracker.md, "Recovery"):
a rendered rig sequence (render_sequence.py --stereo) with a stretch of its frames cut out and
unrelated images put in their place, tracked by tripose-track --right. The rig is lost in the
unrelated images, restarts a map where it comes back (its frames there are placed at the last pose
known), and joins that map to the first when it sees a place of it again. Printed: the frames where
it restarted and joined, each frame's final map, and the errors against the ground truth (degrees,
% of the path) of the last frame before the gap, the restarted frame, the joining frame, the last
frame and the largest after the gap.

    python test/evaluation/stereo_restart.py --folder courtyard-stereo [--keep 0-99,170-299]
        [--unrelated <images>...]
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import cv2
import numpy as np

import render_sequence as render

rs = render.rs
REPO = Path(__file__).resolve().parents[2]
TEMPLE = REPO.parent / "shared" / "data" / "real-images" / "middlebury-templeRing"


def frame_ranges(text):
    frames = []
    for part in text.split(","):
        first, last = (int(v) for v in part.split("-"))
        frames.extend(range(first, last + 1))
    return frames


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--folder", type=Path, required=True, help="a rendered stereo sequence")
    parser.add_argument("--keep", default="0-99,170-299", help="the frames kept, as ranges; the gap between "
                        "the first two ranges gets the unrelated images")
    parser.add_argument("--unrelated", nargs="*", type=Path,
                        help="images put into the gap, the left and the right camera each its own (default: "
                             "templeRing's views 1-6 on the left, 21-26 on the right)")
    args = parser.parse_args()
    unrelated = args.unrelated or [TEMPLE / f"templeR{k:04d}.png" for k in (*range(1, 7), *range(21, 27))]
    half = len(unrelated) // 2
    lefts, rights = unrelated[:half], unrelated[half:2 * half]
    sides = {side: [line.split()[1] for line in (args.folder / f"{side}.txt").read_text().splitlines() if line.strip()]
             for side in ("left", "right")}
    ranges = args.keep.split(",")
    first = frame_ranges(ranges[0])
    rest = frame_ranges(",".join(ranges[1:]))
    plan = first + [None] * half + rest  # the rendered frame of each tracked frame, None in the gap
    _, Rs, ts = rs.read_tum(args.folder / "groundtruth.txt")
    path = rs.path_length(Rs, ts)
    with tempfile.TemporaryDirectory() as temporary:
        temporary = Path(temporary)
        for side, unrelated_side in (("left", lefts), ("right", rights)):
            gap = iter(unrelated_side)
            lines = [f"{i / render.FPS:.9f} {next(gap) if k is None else (args.folder / sides[side][k]).resolve()}"
                     for i, k in enumerate(plan)]
            (temporary / f"{side}.txt").write_text("\n".join(lines) + "\n")
        result = temporary / "result.yml"
        run = subprocess.run([sys.executable, "-m", "tripose.track_cli", "--images", temporary / "left.txt",
                              "--right", temporary / "right.txt", "--calib", args.folder / "calib.yml",
                              "--output", temporary / "trajectory.txt", "--yaml", result],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(run.stderr)
        print(run.stdout.splitlines()[-1])
        fs = cv2.FileStorage(str(result), cv2.FILE_STORAGE_READ)
        node = fs.getNode("frames")
        frames = [node.at(i) for i in range(node.size())]
        rows = []
        for i, f in enumerate(frames):
            k = plan[i]
            status, final_map = int(f.getNode("status").real()), int(f.getNode("map").real())
            recognised = int(f.getNode("recognised_keyframe").real())
            if f.getNode("R").empty() or k is None:
                rows.append((i, k, status, final_map, recognised, None))
                continue
            R, t = f.getNode("R").mat(), f.getNode("t").mat().ravel()
            rows.append((i, k, status, final_map, recognised,
                         (rs.rotation_error_deg(R, Rs[k]), 100 * rs.position_error(R, t, Rs[k], ts[k]) / path)))
        fs.release()
    restarted = [r for r in rows if r[2] == 3]
    joined = [r for r in rows if r[4] >= 0 and rows[r[4]][3] == 0 and r[0] > len(first)]
    print(f"restarted at: {[(r[0], r[1]) for r in restarted]} (tracked, rendered frame); joined at: "
          f"{[(r[0], r[1], r[4]) for r in joined[:1]]} (tracked, rendered, keyframe); final maps: "
          f"{sorted({r[3] for r in rows})}")
    print("| frame | rendered frame | deg | % path | map |")
    print("|---|---|---|---|---|")
    picks = [len(first) - 1] + [r[0] for r in restarted[:1]] + [r[0] for r in joined[:1]] + [len(rows) - 1]
    for i in picks:
        r = rows[i]
        print(f"| {i} | {r[1]} | {r[5][0]:.3f} | {r[5][1]:.3f} | {r[3]} |" if r[5] else f"| {i} | {r[1]} | lost | | |")
    after = [r[5] for r in rows[len(first) + half:] if r[5]]
    print(f"largest after the gap: {max(e[0] for e in after):.3f} deg, {max(e[1] for e in after):.3f} %")


if __name__ == "__main__":
    main()
