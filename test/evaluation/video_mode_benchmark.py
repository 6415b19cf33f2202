"""The video mode (tripose.video.VideoTracker: points followed by optical flow, detected afresh after
keyframes) against the full mode (tripose.images.extract_features with tracking_feature_options() and
tripose.Tracker.track in every frame, as tripose-track), side by side in one process on the same frames (read into memory first; reading is not
timed): per sequence and mode, the median and the 90th percentile of the time per frame (ms and
frames per second), the median processor time per frame (the process's, which other programs on
the machine do not inflate), keyframes, frames with a pose, and the last frame's rotation and position
errors (degrees, % of the ground-truth path), as a markdown table (doc/studies/front_end_and_tracker.md,
"Video mode").

Sequences: the rendered courtyard (render_sequence.py; --folder holds one, or it is rendered into a
temporary folder with --frames) and, with --temple-ring, Middlebury's templeRing in ring order (47
views around an object, not a video: the flow between its views is large). With --stereo the
rendered rig: tripose.video.StereoVideoTracker against tripose.StereoTracker, no pose given.

    python test/evaluation/video_mode_benchmark.py [--folder DIR | --frames 300] [--stereo] [--temple-ring]
        [--modes video,full] [--segments] [--parallax DEG] [--no-local-adjustment]
"""
import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

import cv2
import numpy as np

import render_sequence as render

rs = render.rs

import tripose  # noqa: E402
from tripose import images  # noqa: E402
from tripose.video import StereoVideoTracker, VideoOptions, VideoTracker  # noqa: E402


def read_frames(folder, side):
    """The frames as the programs read them (tripose.images.read_image: a colour PNG converted to grey
    by OpenCV's conversion, which differs from the PNG decoder's own by a grey level here and there)."""
    names = [line.split()[1] for line in (folder / f"{side}.txt").read_text().splitlines() if line.strip()]
    return [images.read_image(folder / n) for n in names]


def rendered(folder, stereo=False):
    """(name, K per frame, frames, ground truth [(R, t)]) of a rendered sequence; with @p stereo the
    frames are (left, right) pairs."""
    fs = cv2.FileStorage(str(folder / "calib.yml"), cv2.FILE_STORAGE_READ)
    K = fs.getNode("K").mat()
    fs.release()
    frames = read_frames(folder, "left")
    if stereo:
        frames = list(zip(frames, read_frames(folder, "right")))
    _, Rs, ts = rs.read_tum(folder / "groundtruth.txt")
    truth = list(zip(Rs, ts))[:len(frames)]
    kind = "rendered courtyard, stereo" if stereo else "rendered courtyard"
    return f"{kind}, {len(frames)} frames", [K] * len(frames), frames, truth


def temple_ring():
    seq = rs.relative_to_first(rs.temple_ring())
    frames = [images.read_image(p) for p in seq.image_paths]
    return f"templeRing (ring order), {len(frames)} views", seq.K, frames, list(zip(seq.R, seq.t))


def run(mode, Ks, frames, truth, segments, parallax, local_adjustment):
    """Per frame wall and processor times (ms), keyframes and the trajectory of one mode."""
    given = truth[:2]
    times, cpu, keyframes = [], [], 0
    stages = []
    stereo = isinstance(frames[0], tuple)
    if stereo:
        # No pose given: the rig's baseline fixes the scale, frame 0's left camera the world.
        R12, t12 = render.rig()
        if mode == "video":
            tracker = StereoVideoTracker(Ks[0], Ks[0], R12, t12, options=VideoOptions(segments=segments))
        else:
            tracker = tripose.StereoTracker(Ks[0], Ks[0], R12, t12)
            options = images.tracking_feature_options()
        for k, (left, right) in enumerate(frames):
            start, start_cpu = time.perf_counter(), time.process_time()
            if mode == "video":
                frame = tracker.track(left, right)
                result = frame.result
                stages.append(dict(frame.milliseconds, detected=frame.detected))
            else:
                result = tracker.track(images.extract_features(left, Ks[k], options=options),
                                       images.extract_features(right, Ks[k], options=options))
            times.append(1e3 * (time.perf_counter() - start))
            cpu.append(1e3 * (time.process_time() - start_cpu))
            keyframes += bool(result.keyframe)
    elif mode == "video":
        options = VideoOptions(segments=segments)
        if parallax is not None:
            options.tracker.keyframe_parallax_deg = parallax
        options.tracker.local_adjustment = local_adjustment
        tracker = VideoTracker(Ks[0], options=options)
        for k, image in enumerate(frames):
            start = time.process_time()
            frame = tracker.track(image, *(given[k] if k < 2 else (None, None)))
            cpu.append(1e3 * (time.process_time() - start))
            times.append(frame.milliseconds["total"])
            stages.append(dict(frame.milliseconds, detected=frame.detected))
            keyframes += bool(frame.result.keyframe)
    if not stereo and mode != "video":
        tracker = tripose.Tracker(Ks[0])
        options = images.tracking_feature_options()
        for k, image in enumerate(frames):
            start, start_cpu = time.perf_counter(), time.process_time()
            features = images.extract_features(image, Ks[k], options=options)
            result = tracker.track(features, *(given[k] if k < 2 else (None, None)), K=Ks[k])
            times.append(1e3 * (time.perf_counter() - start))
            cpu.append(1e3 * (time.process_time() - start_cpu))
            keyframes += bool(result.keyframe)
    if stages:
        detections = sum(m["detected"] for m in stages)
        stereo_stage = f", stereo {np.mean([m['stereo'] for m in stages]):.1f}" if "stereo" in stages[0] else ""
        print(f"video stages, mean ms per frame: flow {np.mean([m['flow'] for m in stages]):.1f}, detection "
              f"{np.mean([m['detection'] for m in stages]):.1f} (in {detections} frames, median "
              f"{np.median([m['detection'] for m in stages if m['detected']]):.1f}){stereo_stage}, registration "
              f"{np.mean([m['registration'] for m in stages]):.1f} (median {np.median([m['registration'] for m in stages]):.1f})",
              file=sys.stderr)
    return times, cpu, keyframes, tracker.trajectory()


def row(sequence, mode, times, cpu, keyframes, trajectory, truth):
    Rs, ts = zip(*truth)
    path = rs.path_length(Rs, ts)
    last = trajectory[-1]
    error = "lost" if last is None else \
        f"{rs.rotation_error_deg(last[0], Rs[-1]):.3f} / {100 * rs.position_error(*last, Rs[-1], ts[-1]) / path:.3f}"
    median = statistics.median(times)
    p90 = float(np.percentile(times, 90))
    posed = sum(p is not None for p in trajectory)
    return (f"| {sequence} | {mode} | {median:.1f} ({1e3 / median:.1f}) | {p90:.1f} ({1e3 / p90:.1f}) | "
            f"{statistics.median(cpu):.1f} | {keyframes} | {posed}/{len(trajectory)} | {error} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--folder", type=Path, help="a rendered sequence (render_sequence.py --output)")
    parser.add_argument("--frames", type=int, default=render.LOOP_FRAMES, help="frames rendered without --folder")
    parser.add_argument("--stereo", action="store_true", help="the rendered rig (a folder rendered with --stereo)")
    parser.add_argument("--temple-ring", action="store_true", help="also templeRing in ring order")
    parser.add_argument("--modes", default="video,full", help="comma-separated: video, full")
    parser.add_argument("--segments", action="store_true", help="the video mode follows segments too")
    parser.add_argument("--parallax", type=float, help="the video mode's keyframe parallax (deg; default "
                                                        "tripose.video.VIDEO_KEYFRAME_PARALLAX_DEG)")
    parser.add_argument("--no-local-adjustment", action="store_true", help="the video mode without local adjustment")
    args = parser.parse_args()
    modes = [m for m in args.modes.split(",") if m]
    if not modes or set(modes) - {"video", "full"}:
        parser.error(f"--modes: expected video and/or full, got {args.modes!r}")
    with tempfile.TemporaryDirectory() as temporary:
        folder = args.folder or Path(temporary)
        if not (folder / "groundtruth.txt").is_file():
            seconds = render.write_sequence(folder, args.frames, args.stereo)
            print(f"rendered {args.frames} frames in {seconds:.0f} s", flush=True)
        sequences = [rendered(folder, args.stereo)]
    if args.temple_ring:
        sequences.append(temple_ring())
    print("| sequence | mode | median ms (fps) | 90th percentile ms (fps) | median processor ms | keyframes | "
          "frames with a pose | "
          "last frame deg / % path |")
    print("|---|---|---|---|---|---|---|---|")
    print(f"load average at the start: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores", file=sys.stderr)
    for name, Ks, frames, truth in sequences:
        for mode in modes:
            label = mode
            if mode == "video":
                label += ", segments" if args.segments else ""
                label += f", parallax {args.parallax:g} deg" if args.parallax is not None else ""
                label += ", no local adjustment" if args.no_local_adjustment else ""
            print(row(name, label, *run(mode, Ks, frames, truth, args.segments, args.parallax,
                                        not args.no_local_adjustment), truth), flush=True)


if __name__ == "__main__":
    main()
