"""The tracker on the real benchmark sequences (doc/studies/front_end_and_tracker.md): each sequence
tracked from its images by `tripose_track` (C++) and, with --python, by `tripose-track` (the
package), frames 0-1 given from the ground truth; per sequence the frames registered, the last
frame's rotation and position error (degrees, % of the path), the largest over the frames, and the
time per frame by stage.

    python test/evaluation/track_real_sequences.py [--python] [--sequences fountain_p11 temple_ring ...]
                                                   [--trajectories DIR] [-- extra tripose_track options]

--trajectories keeps each program's TUM output as DIR/<sequence>-<cpp or python>.txt (frames stamped by
index, in frame 0's camera frame; plot_trajectories.py draws them).
"""
import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "test" / "python"))
import real_sequences as rs  # noqa: E402

SEQUENCES = ["fountain_p11", "herz_jesus_p8", "temple_ring", "kitti_06_forward"]


def run(program, sequence, folder, extra, keep=None):
    seq = rs.relative_to_first(getattr(rs, sequence)())
    calib, listing, out = folder / "calib.yml", folder / "frames.txt", folder / "trajectory.txt"
    rs.write_calibration_yaml(calib, seq.K[0], R12=seq.R[1], t12=seq.t[1])
    listing.write_text("".join(f"{k} {p}\n" for k, p in enumerate(seq.image_paths)))
    proc = subprocess.run([*program, "--images", str(listing), "--calib", str(calib), "--output", str(out), *extra],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(program)} failed on {sequence}: {proc.stderr}")
    if keep is not None:
        keep.parent.mkdir(parents=True, exist_ok=True)
        keep.write_text(out.read_text())
    stamps, Rs, ts = rs.read_tum(out)
    path = rs.path_length(seq.R, seq.t)
    frames = [int(round(s)) for s in stamps]
    rotation = [rs.rotation_error_deg(R, seq.R[k]) for R, k in zip(Rs, frames)]
    position = [100 * rs.position_error(R, t, seq.R[k], seq.t[k]) / path for R, t, k in zip(Rs, ts, frames)]
    last = frames[-1] == len(seq.R) - 1
    times = re.search(r"points \(SIFT\) (\d+), segments \(EDLines, LBD\) (\d+), tracking (\d+)", proc.stdout)
    return (f"| {sequence} | {seq.width}x{seq.height} | {len(frames)}/{len(seq.R)} | "
            + (f"{rotation[-1]:.3f} / {position[-1]:.3f}" if last else "lost") + f" | {max(rotation):.3f} / "
            f"{max(position):.3f} | " + (" / ".join(times.groups()) if times else "-") + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--python", action="store_true", help="also the package's tripose-track")
    parser.add_argument("--sequences", nargs="+", default=SEQUENCES, choices=SEQUENCES)
    parser.add_argument("--trajectories", type=Path, help="folder to keep the TUM trajectories in")
    parser.add_argument("extra", nargs="*", help="options passed to both programs")
    args = parser.parse_args()
    programs = [("C++", [str(REPO / "build" / "samples" / "tripose_track")])]
    if args.python:
        programs.append(("Python", [sys.executable, "-m", "tripose.track_cli"]))
    for label, program in programs:
        print(f"\n{label}: sequence | image size | frames with a pose | last frame deg / % path | "
              "largest deg / % | ms per frame: points / segments / tracking")
        print("|---|---|---|---|---|---|")
        for sequence in args.sequences:
            with tempfile.TemporaryDirectory() as folder:
                keep = (args.trajectories / f"{sequence}-{label.lower().replace('+', 'p')}.txt"
                        if args.trajectories else None)
                print(run(program, sequence, Path(folder), args.extra, keep), flush=True)


if __name__ == "__main__":
    main()
