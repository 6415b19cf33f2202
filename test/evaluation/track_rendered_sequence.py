"""The tracker on the rendered courtyard (render_sequence.py; doc/studies/front_end_and_tracker.md):
the sequence rendered (or read from --folder when it is there), tracked by `tripose_track` (C++)
and, with --python, by `tripose-track` (the package): mono with frames 0-1 given by calib.yml, or
with --stereo the rig. Per program: frames with a pose, the last frame's rotation and position error
(degrees, % of the path), the largest over the frames, the times per frame by stage (SIFT points,
segments, tracking; with `-- --mode video`: flow, detection, the right image's flow, tracking).

    python test/evaluation/track_rendered_sequence.py [--frames 300] [--stereo] [--python] [--folder DIR]
                                                      [-- extra tripose_track options]
"""
import argparse
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import render_sequence as render

rs = render.rs


def errors(folder, trajectory):
    """Per frame of the ground truth: (rotation error in degrees, position error in % of the path), or
    None for a frame the trajectory leaves out. Frames are matched by their timestamps."""
    stamps, Rs, ts = rs.read_tum(folder / "groundtruth.txt")
    path = rs.path_length(Rs, ts)
    tracked = {round(s * render.FPS): (R, t) for s, R, t in zip(*rs.read_tum(trajectory))}
    result = []
    for s, R, t in zip(stamps, Rs, ts):
        pose = tracked.get(round(s * render.FPS))
        result.append(None if pose is None else
                      (rs.rotation_error_deg(pose[0], R), 100 * rs.position_error(*pose, R, t) / path))
    return result


def track(program, folder, stereo, extra):
    """The table row of one program on the sequence in @p folder."""
    out = folder / "trajectory.txt"
    # A stereo sequence's calib.yml holds the rig; its left frames alone are tracked with calib_mono.yml.
    calib = folder / ("calib_mono.yml" if not stereo and (folder / "calib_mono.yml").is_file() else "calib.yml")
    if stereo and not (folder / "right.txt").is_file():
        raise SystemExit(f"--stereo: {folder} holds no right camera (rendered without --stereo)")
    command = [*program, "--images", str(folder / "left.txt"), "--calib", str(calib),
               "--output", str(out), *extra]
    if stereo:
        command += ["--right", str(folder / "right.txt")]
    start = time.perf_counter()
    proc = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(program)} failed: {proc.stderr}")
    per_frame = errors(folder, out)
    found = [e for e in per_frame if e is not None]
    last = per_frame[-1]
    times = (re.search(r"points \(SIFT\) (\d+), segments \(EDLines, LBD\) (\d+), tracking (\d+)", proc.stdout)
             or re.search(r"flow ([\d.]+), detection ([\d.]+)(?:, right image ([\d.]+))?, tracking ([\d.]+)",
                          proc.stdout))
    return (f"| {'stereo' if stereo else 'mono'} | {len(found)}/{len(per_frame)} | "
            + (f"{last[0]:.3f} / {last[1]:.3f}" if last else "lost") + " | "
            + f"{max(e[0] for e in found):.3f} / {max(e[1] for e in found):.3f} | "
            + (" / ".join(g for g in times.groups() if g is not None) if times else "-") + f" | {seconds:.0f} s |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=render.LOOP_FRAMES)
    parser.add_argument("--stereo", action="store_true")
    parser.add_argument("--python", action="store_true", help="also the package's tripose-track")
    parser.add_argument("--folder", type=Path, help="render into (or read from, when it holds a sequence) this folder")
    parser.add_argument("extra", nargs="*", help="options passed to both programs")
    args = parser.parse_args()
    programs = [("C++", [str(render.REPO / "build" / "samples" / "tripose_track")])]
    if args.python:
        programs.append(("Python", [sys.executable, "-m", "tripose.track_cli"]))
    with tempfile.TemporaryDirectory() as temporary:
        folder = args.folder or Path(temporary)
        if not (folder / "groundtruth.txt").is_file():
            seconds = render.write_sequence(folder, args.frames, args.stereo)
            print(f"rendered {args.frames} frames in {seconds:.0f} s")
        print("program | camera | frames with a pose | last frame deg / % path | largest deg / % | "
              "ms per frame by stage | total")
        print("|---|---|---|---|---|---|---|")
        for label, program in programs:
            print(f"| {label} " + track(program, folder, args.stereo, args.extra), flush=True)


if __name__ == "__main__":
    main()
