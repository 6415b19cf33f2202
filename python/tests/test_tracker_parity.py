"""Fed the same observations, the C++ API (cv::tripose::Tracker::addObservations, through the
evaluation's tripose_track_vgg) and the Python API (tripose.Tracker.track_observations) give the
same poses: they run the same core. VGG Model House, the track checks off so that the tracks the C++
program writes back (--observations) are the ones it was given."""
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tripose

cv2 = pytest.importorskip("cv2")

REPO = Path(__file__).resolve().parents[2]
PROGRAM = REPO / "build" / "test" / "evaluation" / "tripose_track_vgg"


def test_cpp_and_python_trackers_agree_to_1e9(tmp_path):
    # A missing program is an error, never a skip: the test command builds it before these tests. The
    # program runs with the local adjustment, as the library does by default (the program does not).
    assert PROGRAM.exists(), f"{PROGRAM} is not built; run scripts/test.sh"
    out, observations = tmp_path / "track.yml", tmp_path / "observations.yml"
    proc = subprocess.run([str(PROGRAM), "--data", str(REPO / "test" / "data" / "vgg" / "Model-House"),
                           "--check-tracks", "0", "--local-refine", "1", "--observations", str(observations),
                           "--output", str(out)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    fs = cv2.FileStorage(str(out), cv2.FILE_STORAGE_READ)
    poses, status = fs.getNode("poses").mat(), fs.getNode("status").mat().ravel()
    tracks = cv2.FileStorage(str(observations), cv2.FILE_STORAGE_READ)
    options = tripose.TrackerOptions()
    options.check_tracks = False
    tracker = tripose.Tracker(tracks.getNode("K0").mat(), options=options)
    for k in range(len(status)):
        points, lines = tracks.getNode(f"points{k}").mat(), tracks.getNode(f"lines{k}").mat()
        point_ids, line_ids = np.flatnonzero(~np.isnan(points[:, 0])), np.flatnonzero(~np.isnan(lines[:, 0]))
        given = dict(R=poses[k, :9].reshape(3, 3), t=poses[k, 9:]) if k < 2 else {}
        result = tracker.track_observations(points[point_ids], point_ids, lines[line_ids], line_ids,
                                            K=tracks.getNode(f"K{k}").mat(), **given)
        assert result.status.value == int(status[k]), k
    assert list(status[2:]) == [1] * (len(status) - 2)
    for k in range(2, len(status)):
        R, t = tracker.pose(k)
        np.testing.assert_allclose(R, poses[k, :9].reshape(3, 3), rtol=0, atol=1e-9)
        np.testing.assert_allclose(t, poses[k, 9:], rtol=0, atol=1e-9)
