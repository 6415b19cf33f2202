"""tripose.video.VideoTracker and StereoVideoTracker, the video mode (points followed by optical flow,
detected afresh after keyframes), on the first 40 frames of the rendered courtyard
(test/evaluation/render_sequence.py), mono and stereo: every frame registered and the last one within
the bound measured on them; the same frames give the same poses; tripose-track --mode video writes
the API's poses; bad options and images raise errors naming them."""
import sys
from pathlib import Path

import numpy as np
import pytest

import tripose
from tripose.video import StereoVideoTracker, VideoFrame, VideoOptions, VideoTracker

REPO = Path(__file__).resolve().parents[2]
sys.path.append(str(REPO / "test" / "evaluation"))  # render_sequence.py (and real_sequences.py)
import render_sequence as render  # noqa: E402

rs = render.rs
FRAMES = 40
REGISTERED, GIVEN = tripose.FrameStatus.REGISTERED, tripose.FrameStatus.GIVEN


@pytest.fixture(scope="module")
def walk(tmp_path_factory):
    """(grey frames, ground-truth poses relative to frame 0) of the rendered walk's first frames."""
    from tripose import images

    folder = tmp_path_factory.mktemp("courtyard")
    render.write_sequence(folder, FRAMES)
    names = [line.split()[1] for line in (folder / "left.txt").read_text().splitlines() if line.strip()]
    frames = [images.read_image(folder / n) for n in names]  # as tripose-track reads them
    _, Rs, ts = rs.read_tum(folder / "groundtruth.txt")
    return frames, list(zip(Rs, ts)), folder


def last_frame_errors(trajectory, truth):
    """The last frame's rotation error (deg) and position error (% of the true path)."""
    Rs, ts = zip(*truth)
    R, t = trajectory[-1]
    return (rs.rotation_error_deg(R, Rs[-1]),
            100 * rs.position_error(R, t, Rs[-1], ts[-1]) / rs.path_length(Rs, ts))


def assert_same_trajectory(trajectory, again):
    for (R, t), (R2, t2) in zip(trajectory, again):
        np.testing.assert_array_equal(R, R2)
        np.testing.assert_array_equal(t, t2)


def assert_program_wrote(output, trajectory):
    """The program's TUM file holds every frame's pose of @p trajectory (camera to world, printed to
    17 digits)."""
    _, Rs, ts = rs.read_tum(output)
    assert len(Rs) == FRAMES
    for (R, t), R2, t2 in zip(trajectory, Rs, ts):
        np.testing.assert_allclose(R2, R, atol=1e-9)
        np.testing.assert_allclose(t2, t, atol=1e-9)


def track(frames, truth, options=None):
    tracker = VideoTracker(render.K, options=options)
    results = [tracker.track(image, *(truth[k] if k < 2 else (None, None))) for k, image in enumerate(frames)]
    return results, tracker.trajectory()


def test_every_frame_registered_within_the_measured_bound(walk):
    # Measured on these 40 frames: the last at 0.450 deg and 2.170 % of the path (the full mode, SIFT
    # and EDLines matched in every frame, 0.607 deg and 8.196 %); bounds at 1.5 times the measured.
    frames, truth, _ = walk
    results, trajectory = track(frames, truth)
    assert all(isinstance(f, VideoFrame) for f in results)
    assert [f.result.status for f in results] == [GIVEN, GIVEN] + [REGISTERED] * (FRAMES - 2)
    assert all(f.points >= VideoOptions().min_points for f in results)
    assert results[0].detected and results[1].detected == bool(results[0].result.keyframe)
    assert all(set(f.milliseconds) == {"flow", "detection", "registration", "total"} for f in results)
    rotation, position = last_frame_errors(trajectory, truth)
    assert rotation < 0.675 and position < 3.25, (rotation, position)
    assert_same_trajectory(trajectory, track(frames, truth)[1])


def test_segments_followed_too(walk):
    frames, truth, _ = walk
    results, _ = track(frames[:12], truth, VideoOptions(segments=True))
    assert [f.result.status for f in results] == [GIVEN, GIVEN] + [REGISTERED] * 10
    assert all(f.segments > 0 for f in results)


def test_an_unreadable_frame_is_lost_and_the_next_registered(walk):
    frames, truth, _ = walk
    tracker = VideoTracker(render.K)
    statuses = [tracker.track(frames[k], *truth[k]).result.status for k in range(2)]
    lost = tracker.track(None)
    assert lost.result.status == tripose.FrameStatus.LOST and lost.points == 0
    # The points followed before it are followed on from frame 1 into frame 3.
    after = tracker.track(frames[3])
    assert after.result.status == REGISTERED and after.points > 0, after.result.reason
    assert statuses == [GIVEN, GIVEN]


def test_program_video_mode_gives_the_api_poses(walk, tmp_path, capsys):
    from tripose import track_cli

    frames, truth, folder = walk
    _, trajectory = track(frames, truth)
    output = tmp_path / "trajectory.txt"
    arguments = ["--images", str(folder / "left.txt"), "--calib", str(folder / "calib.yml"), "--output", str(output)]
    assert track_cli.main(arguments + ["--mode", "video"]) == 0
    assert "flow / detection / registration" in capsys.readouterr().out
    assert_program_wrote(output, trajectory)
    for extra, named in ((["--max-image-size", "800"], "--max-image-size"),
                         (["--contrast-threshold", "0.01"], "--contrast-threshold"),
                         (["--max-points", "500"], "--max-points"), (["--loop-closure"], "--loop-closure")):
        assert track_cli.main(arguments + ["--mode", "video"] + extra) == 1
        assert named in capsys.readouterr().err


@pytest.mark.parametrize("name, value, error", [
    ("max_points", 0, ValueError), ("max_points", 2.5, TypeError), ("min_points", -1, ValueError),
    ("min_points", 10_000, ValueError), ("window_size", 14, ValueError), ("pyramid_levels", -1, ValueError),
    ("min_distance", 0.0, ValueError), ("quality_level", 1.5, ValueError), ("max_flow_error", float("nan"), ValueError),
    ("max_length_change", "0.2", TypeError), ("segments", 1, TypeError), ("tracker", object(), TypeError),
])
def test_bad_options_raise_naming_the_option(name, value, error):
    options = VideoOptions(**{name: value})
    with pytest.raises(error, match=name):
        VideoTracker(render.K, options=options)


def test_bad_arguments_raise_naming_them():
    with pytest.raises(TypeError, match="options"):
        VideoTracker(render.K, options=tripose.TrackerOptions())
    with pytest.raises(ValueError, match="K"):
        VideoTracker(np.eye(2))
    tracker = VideoTracker(render.K)
    with pytest.raises(TypeError, match="image"):
        tracker.track(np.zeros((48, 64), np.float32))
    with pytest.raises(ValueError, match="image"):
        tracker.track(np.zeros((48, 64, 2), np.uint8))
    tracker.track(np.zeros((48, 64), np.uint8), np.eye(3), np.zeros(3))
    with pytest.raises(ValueError, match="image"):
        tracker.track(np.zeros((40, 64), np.uint8))
    with pytest.raises(ValueError, match="R and t"):
        tracker.track(np.zeros((48, 64), np.uint8), np.eye(3))


# --- a stereo rig --------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def stereo_walk(tmp_path_factory):
    """(left frames, right frames, ground-truth poses relative to frame 0, folder) of the rendered
    rig's first frames."""
    from tripose import images

    folder = tmp_path_factory.mktemp("courtyard-stereo")
    render.write_sequence(folder, FRAMES, stereo=True)
    frames = []
    for side in ("left", "right"):
        names = [line.split()[1] for line in (folder / f"{side}.txt").read_text().splitlines() if line.strip()]
        frames.append([images.read_image(folder / n) for n in names])
    _, Rs, ts = rs.read_tum(folder / "groundtruth.txt")
    return frames[0], frames[1], list(zip(Rs, ts)), folder


def track_stereo(left, right):
    R12, t12 = render.rig()
    tracker = StereoVideoTracker(render.K, render.K, R12, t12)
    results = [tracker.track(a, b) for a, b in zip(left, right)]
    return results, tracker.trajectory()


def test_stereo_every_frame_registered_within_the_measured_bound(stereo_walk):
    # Measured on these 40 frames: the last at 0.078 deg and 0.384 % of the path on one machine, 0.102
    # and 0.516 on another (their floating point differs, and the robust estimator's choices with it);
    # bounds at 1.5 times the larger. No pose is given: the rig's baseline gives the scale.
    left, right, truth, _ = stereo_walk
    results, trajectory = track_stereo(left, right)
    assert [f.result.status for f in results] == [GIVEN] + [REGISTERED] * (FRAMES - 1)
    assert all(set(f.milliseconds) == {"flow", "detection", "stereo", "registration", "total"} for f in results)
    rotation, position = last_frame_errors(trajectory, truth)
    assert rotation < 0.153 and position < 0.774, (rotation, position)
    assert_same_trajectory(trajectory, track_stereo(left, right)[1])


def test_stereo_bad_images_raise_naming_the_camera(stereo_walk):
    left, right, _, _ = stereo_walk
    R12, t12 = render.rig()
    tracker = StereoVideoTracker(render.K, render.K, R12, t12)
    with pytest.raises(ValueError, match="right"):
        tracker.track(left[0], right[0][:100])
    with pytest.raises(TypeError, match="left"):
        tracker.track(left[0].astype(np.float32), right[0])
    with pytest.raises(ValueError, match="t"):
        StereoVideoTracker(render.K, render.K, R12, np.zeros(3))
    # Without its right image a frame is registered from the left camera's points; without its
    # left image it is lost, and the next frame is registered from the points followed on.
    assert tracker.track(left[0], right[0]).result.status == GIVEN
    assert tracker.track(left[1], None).result.status == REGISTERED
    assert tracker.track(None, right[2]).result.status == tripose.FrameStatus.LOST
    assert tracker.track(left[3], right[3]).result.status == REGISTERED


def test_program_stereo_video_mode_gives_the_api_poses(stereo_walk, tmp_path, capsys):
    from tripose import track_cli

    left, right, _, folder = stereo_walk
    _, trajectory = track_stereo(left, right)
    output = tmp_path / "trajectory.txt"
    assert track_cli.main(["--images", str(folder / "left.txt"), "--right", str(folder / "right.txt"), "--calib",
                           str(folder / "calib.yml"), "--output", str(output), "--mode", "video"]) == 0
    assert "flow / detection / stereo / registration" in capsys.readouterr().out
    assert_program_wrote(output, trajectory)
