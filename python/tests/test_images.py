"""tripose.images, the image front end: read_image's conversions and errors, extract_features's
arrays (shapes, dtypes, positions in the image's pixels, undistortion, segment orientation) and
open_frames over a folder, a list file and a video, lost frames included."""
import importlib.util
import struct
import sys
import types
from pathlib import Path

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

REPO = Path(__file__).resolve().parents[2]
MERTON = REPO / "test" / "data" / "vgg" / "Merton-College-I"


def _load_images_module():
    """tripose.images of the installed package; while the installed package predates it, the source
    file itself (it needs no compiled code)."""
    try:
        from tripose import images
        return images
    except ImportError:
        spec = importlib.util.spec_from_file_location("tripose_images_source", REPO / "python" / "tripose" / "images.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module  # dataclasses look their module up while the file runs
        spec.loader.exec_module(module)
        return module


images = _load_images_module()


def merton_K():
    fs = cv2.FileStorage(str(REPO / "test" / "data" / "images" / "merton_college_i_calib.yml"), cv2.FILE_STORAGE_READ)
    K = fs.getNode("K1").mat()
    fs.release()
    return K


@pytest.fixture(scope="module")
def merton():
    return images.read_image(MERTON / "001.jpg")


@pytest.fixture(scope="module")
def merton_features(merton):
    return images.extract_features(merton, merton_K())


def check_arrays(features, points=None, segments=None):
    assert set(features) == {"points", "point_descriptors", "segments", "line_descriptors"}
    p, pd, s, ld = (features[k] for k in ("points", "point_descriptors", "segments", "line_descriptors"))
    assert p.dtype == np.float64 and p.ndim == 2 and p.shape[1] == 2
    assert pd.dtype == np.float32 and pd.shape == (len(p), 128)
    assert s.dtype == np.float64 and s.ndim == 2 and s.shape[1] == 4
    assert ld.dtype == np.uint8 and ld.shape == (len(s), 32)
    if points is not None:
        assert (len(p) > 0) == points
    if segments is not None:
        assert (len(s) > 0) == segments


# --- extract_features ------------------------------------------------------------------------------

def test_features_of_a_real_image_have_the_documented_arrays(merton, merton_features):
    check_arrays(merton_features, points=True, segments=True)
    p, s = merton_features["points"], merton_features["segments"]
    h, w = merton.shape
    assert 1000 < len(p) <= 4000 + 10 and len(s) > 100  # SIFT keeps key points tied with the last
    assert np.all((p >= -0.5) & (p <= [w - 0.5, h - 0.5]))
    assert np.all((s >= -1) & (s <= [w, h, w, h]))
    # Segments shorter than min_segment_length are dropped (the fit moves ends by a fraction of a px).
    assert np.min(np.hypot(s[:, 2] - s[:, 0], s[:, 3] - s[:, 1])) >= 19.0


def test_kinds_leave_the_other_kind_empty(merton):
    crop = merton[:300, :400]
    points = images.extract_features(crop, merton_K(), options=images.FeatureOptions(kinds="points", max_points=300))
    check_arrays(points, points=True, segments=False)
    assert len(points["points"]) <= 310
    lines = images.extract_features(crop, merton_K(), options=images.FeatureOptions(kinds="lines"))
    check_arrays(lines, points=False, segments=True)


def test_default_options_are_the_cpp_front_ends():
    options = images.FeatureOptions()
    assert (options.kinds, options.max_points, options.min_segment_length, options.max_image_size) == \
        ("all", 4000, 20.0, 1600)


@pytest.mark.parametrize("options, word", [(dict(kinds="edges"), "kinds"), (dict(max_points=-1), "max_points"),
                                           (dict(max_image_size=1.5), "max_image_size"),
                                           (dict(min_segment_length=float("nan")), "min_segment_length")])
def test_bad_options_are_named(merton, options, word):
    with pytest.raises(ValueError, match=word):
        images.extract_features(merton[:50, :50], merton_K(), options=images.FeatureOptions(**options))


def test_bad_image_and_calibration_are_named(merton):
    with pytest.raises(ValueError, match="image"):
        images.extract_features(merton.astype(np.float32), merton_K())
    with pytest.raises(ValueError, match="K"):
        images.extract_features(merton[:50, :50], np.eye(2))
    with pytest.raises(ValueError, match="dist"):
        images.extract_features(merton[:50, :50], merton_K(), dist=[0.1, 0.2, 0.3])


def test_a_larger_image_is_detected_reduced_with_positions_in_its_pixels(merton):
    image = merton[:400, :600]
    options = images.FeatureOptions(max_image_size=300)
    assert images.detection_scale(image.shape, 300) == 2.0
    reduced = images.extract_features(image, merton_K(), options=options)
    check_arrays(reduced, points=True, segments=True)
    # Positions span the whole image, not the 300 x 200 detection image.
    assert reduced["points"][:, 0].max() > 450 and reduced["segments"][:, [0, 2]].max() > 450
    # Features of the image reduced by hand (area averaging), mapped to the image's pixel centres.
    by_hand = images.extract_features(cv2.resize(image, (300, 200), interpolation=cv2.INTER_AREA), merton_K(),
                                      options=images.FeatureOptions(max_image_size=0))
    np.testing.assert_allclose(reduced["points"], (by_hand["points"] + 0.5) * 2 - 0.5, atol=1e-9)
    np.testing.assert_allclose(reduced["segments"], (by_hand["segments"] + 0.5) * 2 - 0.5, atol=1e-4)


def test_positions_are_undistorted_with_dist(merton):
    crop = merton[:300, :400]
    K = merton_K()
    dist = np.array([-0.2, 0.05, 0.001, -0.001, 0.0])
    plain = images.extract_features(crop, K)
    moved = images.extract_features(crop, K, dist=dist)
    for key, rows in (("points", 2), ("segments", 4)):
        expected = cv2.undistortPoints(plain[key].reshape(-1, 1, 2), K, dist, P=K).reshape(-1, rows)
        np.testing.assert_allclose(moved[key], expected, atol=1e-9)
    assert np.array_equal(moved["line_descriptors"], plain["line_descriptors"])


def test_segments_run_with_the_brighter_side_on_their_right():
    image = np.full((200, 240), 40, np.uint8)
    cv2.fillPoly(image, [np.array([[60, 50], [190, 40], [170, 160], [70, 150]], np.int32)], 200)
    image = cv2.GaussianBlur(image, (0, 0), 1.0)
    segments = images.extract_features(image, np.diag([300.0, 300.0, 1.0]),
                                       options=images.FeatureOptions(kinds="lines"))["segments"]
    assert len(segments) >= 4
    for x0, y0, x1, y1 in segments:
        d = np.array([x1 - x0, y1 - y0]) / np.hypot(x1 - x0, y1 - y0)
        right = np.array([-d[1], d[0]])  # x right, y down: the right-hand side as drawn
        mid = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        a, b = np.rint(mid + 4 * right).astype(int), np.rint(mid - 4 * right).astype(int)
        assert image[a[1], a[0]] > image[b[1], b[0]]


def test_missing_opencv_contrib_is_an_import_error_naming_the_extra(monkeypatch):
    message = "tripose.images needs OpenCV's contrib modules: pip install tripose\\[images\\]"
    monkeypatch.setitem(sys.modules, "cv2", types.ModuleType("cv2"))  # OpenCV without contrib
    with pytest.raises(ImportError, match=message):
        images.extract_features(np.zeros((10, 10), np.uint8), np.eye(3))
    monkeypatch.setitem(sys.modules, "cv2", None)  # no OpenCV
    with pytest.raises(ImportError, match=message):
        images.read_image(MERTON / "001.jpg")


# --- read_image ------------------------------------------------------------------------------------

def test_read_image_gives_eight_bit_grey(merton):
    assert merton.dtype == np.uint8 and merton.shape == (768, 1024)
    colour = cv2.imread(str(MERTON / "001.jpg"), cv2.IMREAD_COLOR)
    assert np.array_equal(merton, cv2.cvtColor(colour, cv2.COLOR_BGR2GRAY))


def test_deeper_images_are_stretched_to_eight_bits(tmp_path):
    ramp = (1000 + 4 * np.arange(64, dtype=np.uint16))[None, :].repeat(8, axis=0)  # 12 bits in 16
    cv2.imwrite(str(tmp_path / "deep.png"), ramp)
    grey = images.read_image(tmp_path / "deep.png")
    assert grey.dtype == np.uint8 and grey.min() == 0 and grey.max() == 255
    np.testing.assert_allclose(grey[0], (ramp[0] - 1000) * 255.0 / 252, atol=0.5)
    cv2.imwrite(str(tmp_path / "float.tiff"), ramp.astype(np.float32) / 4096)
    assert np.array_equal(images.read_image(tmp_path / "float.tiff"), grey)


def test_exif_orientation_is_applied(tmp_path):
    image = np.zeros((20, 40, 3), np.uint8)
    image[:, :10] = 255  # bright on the left: on the top after turning a quarter clockwise
    data = cv2.imencode(".jpg", image)[1].tobytes()
    entry = struct.pack("<HHII", 0x0112, 3, 1, 6)  # Orientation 6: turn 90 degrees clockwise to view
    tiff = b"II*\x00" + struct.pack("<I", 8) + struct.pack("<H", 1) + entry + struct.pack("<I", 0)
    app1 = b"\xff\xe1" + struct.pack(">H", 2 + 6 + len(tiff)) + b"Exif\x00\x00" + tiff
    path = tmp_path / "portrait.jpg"
    path.write_bytes(data[:2] + app1 + data[2:])
    grey = images.read_image(path)
    assert grey.shape == (40, 20)
    assert grey[:8].mean() > 200 and grey[-20:].mean() < 50


@pytest.mark.parametrize("make, reason", [
    (lambda p: None, "no such file"),
    (lambda p: p.write_bytes((MERTON / "001.jpg").read_bytes()[:60000]), "cut short"),
    (lambda p: p.write_bytes((MERTON / "001.jpg").read_bytes()[:200]), "cannot be decoded"),
    (lambda p: p.write_text("not an image"), "cannot be decoded"),
    (lambda p: p.write_bytes(cv2.imencode(".png", np.full((8, 8), 7, np.uint8))[1].tobytes()), "blank"),
])
def test_unreadable_images_raise_value_error_naming_the_file(tmp_path, make, reason):
    path = tmp_path / "broken image.jpg"
    make(path)
    with pytest.raises(ValueError, match=reason) as error:
        images.read_image(path)
    assert str(path) in str(error.value)


# --- open_frames -----------------------------------------------------------------------------------

def frame(level, size=(48, 64)):
    """A distinct 8-bit test frame: a grey level and a bright square whose place follows it."""
    image = np.full(size, level, np.uint8)
    x = 4 + level % 40
    image[10:30, x:x + 16] = 255
    return image


def test_open_frames_over_a_folder_in_natural_order(tmp_path):
    levels = {"f1.png": 10, "f2.png": 20, "f10.png": 30, "F11.jpg": 40}
    for name, level in levels.items():
        cv2.imwrite(str(tmp_path / name), frame(level))
    (tmp_path / "f3.png").write_bytes(b"\x89PNG\r\n\x1a\n broken")  # cannot be decoded: lost
    (tmp_path / "notes.txt").write_text("not a frame")
    (tmp_path / "sub.png").mkdir()
    got = list(images.open_frames(tmp_path))
    assert [name for _, name, _ in got] == ["f1.png", "f2.png", "f3.png", "f10.png", "F11.jpg"]
    assert [t for t, _, _ in got] == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert got[2][2] is None
    assert np.array_equal(got[0][2], frame(10)) and np.array_equal(got[3][2], frame(30))
    assert got[4][2].dtype == np.uint8 and got[4][2].shape == (48, 64)


def test_open_frames_over_a_list_file(tmp_path):
    (tmp_path / "images").mkdir()
    for level in (10, 20, 30):
        cv2.imwrite(str(tmp_path / "images" / f"{level}.png"), frame(level))
    lines = ["# timestamp path", "100.5 images/30.png", "", "101.0 images/missing.png",
             f"101.25 {tmp_path / 'images' / '10.png'}", "102 images/20.png"]
    listing = tmp_path / "frames.txt"
    listing.write_text("\n".join(lines) + "\n")
    got = list(images.open_frames(listing))
    assert [(t, name) for t, name, _ in got] == [(100.5, "images/30.png"), (101.0, "images/missing.png"),
                                                 (101.25, str(tmp_path / "images" / "10.png")),
                                                 (102.0, "images/20.png")]
    assert got[1][2] is None
    for (_, _, image), level in zip([got[0], got[2], got[3]], (30, 10, 20)):
        assert np.array_equal(image, frame(level))
    # Without timestamps, frames are numbered; with them on some lines only, the list is refused.
    plain = tmp_path / "plain.lst"
    plain.write_text("images/20.png\nimages/10.png\n")
    assert [(t, name) for t, name, _ in images.open_frames(plain)] == [(0.0, "images/20.png"), (1.0, "images/10.png")]
    mixed = tmp_path / "mixed.txt"
    mixed.write_text("1.0 images/20.png\nimages/10.png\n")
    with pytest.raises(ValueError, match="mixed.txt:2"):
        images.open_frames(mixed)


def write_video(path, levels, fps=10.0):
    writer = cv2.VideoWriter(str(path), cv2.VideoWriter_fourcc(*"MJPG"), fps, (64, 48))
    assert writer.isOpened()
    for level in levels:
        writer.write(cv2.cvtColor(frame(level), cv2.COLOR_GRAY2BGR))
    writer.release()


def test_open_frames_over_a_video(tmp_path):
    levels = [20, 60, 100, 140, 180]
    video = tmp_path / "clip.avi"
    write_video(video, levels)
    got = list(images.open_frames(video))
    assert [name for _, name, _ in got] == [f"clip.avi:{i}" for i in range(5)]
    np.testing.assert_allclose([t for t, _, _ in got], [0.0, 0.1, 0.2, 0.3, 0.4], atol=1e-6)
    for (_, _, image), level in zip(got, levels):
        assert image.dtype == np.uint8 and image.shape == (48, 64)
        assert np.abs(image.astype(int) - frame(level)).mean() < 4  # JPEG compressed


def test_a_corrupt_video_frame_is_lost_and_the_video_goes_on(tmp_path):
    levels = [20, 60, 100, 140, 180]
    video = tmp_path / "clip.avi"
    write_video(video, levels)
    data = bytearray(video.read_bytes())
    starts = [i for i in range(len(data) - 2) if data[i:i + 3] == b"\xff\xd8\xff"]  # each frame's JPEG
    assert len(starts) == len(levels)
    # Frame 2's JPEG zeroed up to the next frame's chunk header ("00dc", size): nothing to decode (a
    # JPEG with only its headers damaged is concealed by the decoder, which returns a picture).
    end = starts[3] - 8
    assert bytes(data[end:end + 4]) == b"00dc"
    data[starts[2]:end] = bytes(end - starts[2])
    video.write_bytes(bytes(data))
    got = list(images.open_frames(video))
    assert [name for _, name, _ in got] == [f"clip.avi:{i}" for i in range(5)]
    assert got[2][2] is None
    np.testing.assert_allclose([t for t, _, _ in got], [0.0, 0.1, 0.2, 0.3, 0.4], atol=1e-6)
    for k in (0, 1, 3, 4):
        assert np.abs(got[k][2].astype(int) - frame(levels[k])).mean() < 4


def test_sources_that_cannot_be_opened_raise_value_error_naming_them(tmp_path):
    missing = tmp_path / "nothing here"
    empty = tmp_path / "empty"
    empty.mkdir()
    not_video = tmp_path / "noise.avi"
    not_video.write_bytes(bytes(range(256)) * 8)
    empty_list = tmp_path / "empty.txt"
    empty_list.write_text("# no frames\n")
    for source in (missing, empty, not_video, empty_list):
        with pytest.raises(ValueError) as error:
            images.open_frames(source)
        assert str(source) in str(error.value)
