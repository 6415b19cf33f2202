"""The bad-input catalogue through the package (the C++ one is
modules/tripose/test/test_estimate_pose_bad_input.cpp): each case breaks one thing in a valid call
and must raise ValueError (TypeError for a wrong type) whose message names the argument as a whole
word. And the accepted variety: float32 and any memory layout give the float64 C-order result.
"""
import re

import numpy as np
import pytest

import tripose
from scenes import multiview_scene, stereo_scene, three_view_scene

NAN, INF = float("nan"), float("inf")

SCENE = three_view_scene(1, 4, 3)
STEREO = stereo_scene(1, 4, 3, missing=0.0)
MULTI = multiview_scene(1, 6, 4, num_known=3)


def names(message, argument):
    """argument appears in message as a whole name: not inside a longer one ("R" is not named by
    "R12 ..." nor by "Rodrigues"); "K[1]" is one name."""
    return re.search(r"(?<![\w.\[])" + re.escape(argument) + r"(?![\w\[])", message) is not None


def test_names_matcher_can_fail():
    assert names("R is not a rotation", "R")
    assert names("K[1] must have positive focal lengths", "K[1]")
    assert names("fixed_views: at least two", "fixed_views")
    assert not names("R12 is not a rotation", "R")
    assert not names("Rodrigues vector", "R")
    assert not names("K[1] must be 3x3", "K")
    assert not names("at least 4 features", "t")


def three_view_args(**changes):
    a = dict(points1=SCENE.points[0], points2=SCENE.points[1], points3=SCENE.points[2], lines1=SCENE.lines[0],
             lines2=SCENE.lines[1], lines3=SCENE.lines[2], K=SCENE.K, R12=SCENE.R12, t12=SCENE.t12)
    a = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in a.items()}
    a.update(changes)
    return a


def linear(**a):
    return tripose.estimate_pose_line_point(**a)


def ransac(**a):
    # The scenes hold 7 features, all right: no floor on the inliers above them.
    a.setdefault("min_inliers", 0)
    return tripose.estimate_pose_line_point_ransac(**a)


def refine(**a):
    a.setdefault("R", SCENE.R)
    a.setdefault("t", SCENE.t)
    return tripose.refine_pose_line_point(**a)


ENTRY_POINTS = [linear, ransac, refine]


def expect_rejected(call, argument, error=ValueError, **kwargs):
    with pytest.raises(error) as info:
        call(**kwargs)
    message = str(info.value)
    assert type(info.value) is error, (type(info.value), message)
    assert names(message, argument), f"the message does not name {argument!r}: {message!r}"


def edited(array, index, value):
    out = np.array(array, dtype=np.float64, copy=True)
    out[index] = value
    return out


@pytest.mark.parametrize("call", ENTRY_POINTS)
def test_valid_call_succeeds(call):
    result = call(**three_view_args())
    assert result is not None and (len(result) > 0 if isinstance(result, list) else result["R"] is not None)


# Each case: (argument named, error, changes to the valid three-view call). Every one of them runs
# through the linear solver, RANSAC and the refinement.
SHARED_CASES = {
    # Types.
    "points_int": ("points1", TypeError, dict(points1=SCENE.points[0].astype(np.int32))),
    "points_complex": ("points2", TypeError, dict(points2=SCENE.points[1].astype(complex))),
    "points_float16": ("points3", TypeError, dict(points3=SCENE.points[2].astype(np.float16))),
    "points_string": ("points1", TypeError, dict(points1="points")),
    "lines_int": ("lines2", TypeError, dict(lines2=SCENE.lines[1].astype(np.int64))),
    "K_int": ("K", TypeError, dict(K=np.eye(3, dtype=np.int32))),
    "R12_int": ("R12", TypeError, dict(R12=np.eye(3, dtype=np.int64))),
    "R12_string": ("R12", TypeError, dict(R12="identity")),
    "t12_int": ("t12", TypeError, dict(t12=np.array([1, 0, 0]))),
    "dist_int": ("dist", TypeError, dict(dist=np.zeros(5, dtype=np.int32))),
    # Shapes.
    "points_wrong_width": ("points2", ValueError, dict(points2=np.zeros((4, 3)))),
    "points_flat": ("points3", ValueError, dict(points3=SCENE.points[2].ravel())),
    "points_3d_array": ("points3", ValueError, dict(points3=SCENE.points[2][None])),
    "lines_wrong_width": ("lines1", ValueError, dict(lines1=np.zeros((3, 5)))),
    "homogeneous_beside_segments": ("lines3", ValueError, dict(lines3=np.ones((3, 3)))),
    "K_wrong_shape": ("K", ValueError, dict(K=np.eye(4))),
    "K_flat": ("K", ValueError, dict(K=SCENE.K.ravel())),
    "R12_wrong_shape": ("R12", ValueError, dict(R12=np.eye(2))),
    "t12_wrong_size": ("t12", ValueError, dict(t12=np.ones(4))),
    "dist_as_matrix": ("dist", ValueError, dict(dist=np.zeros((2, 4)))),
    # Counts.
    "point_counts_differ": ("points3", ValueError, dict(points3=SCENE.points[2][:2])),
    "points_missing_in_one_view": ("points2", ValueError, dict(points2=None)),
    "line_counts_differ": ("lines2", ValueError, dict(lines2=SCENE.lines[1][:1])),
    # Values of the observations.
    "nan_in_points": ("points2", ValueError, dict(points2=edited(SCENE.points[1], (1, 0), NAN))),
    "inf_in_lines": ("lines3", ValueError, dict(lines3=edited(SCENE.lines[2], (0, 3), INF))),
    "zero_length_segment": ("lines2", ValueError, dict(lines2=edited(SCENE.lines[1], (2, slice(2, 4)),
                                                                       SCENE.lines[1][2, :2]))),
    "homogeneous_line_zero_normal": ("lines1", ValueError, dict(
        lines1=np.array([[0.0, 0.0, 1.0]] * 3), lines2=np.ones((3, 3)), lines3=np.ones((3, 3)))),
    # Intrinsics.
    "K_negative_focal": ("K", ValueError, dict(K=edited(SCENE.K, (0, 0), -800.0))),
    "K_zero_focal": ("K", ValueError, dict(K=edited(SCENE.K, (1, 1), 0.0))),
    "K_singular": ("K", ValueError, dict(K=edited(SCENE.K, (2, 2), 0.0))),
    "K_not_upper_triangular": ("K", ValueError, dict(K=edited(SCENE.K, (1, 0), 5.0))),
    "K_nan": ("K", ValueError, dict(K=edited(SCENE.K, (0, 2), NAN))),
    "two_camera_matrices": ("K", ValueError, dict(K=[SCENE.K, SCENE.K])),
    "one_of_three_camera_matrices_bad": ("K[1]", ValueError, dict(K=[SCENE.K, edited(SCENE.K, (0, 0), -1.0),
                                                                      SCENE.K])),
    # Distortion.
    "dist_wrong_count": ("dist", ValueError, dict(dist=np.array([0.1, 0, 0, 0, 0, 0]))),
    "dist_nan": ("dist", ValueError, dict(dist=np.array([0.1, NAN, 0, 0, 0]))),
    "two_distortion_vectors": ("dist", ValueError, dict(dist=[np.zeros(5), np.zeros(5)])),
    "homogeneous_lines_with_distortion": ("lines1", ValueError, dict(
        lines1=np.cross(np.c_[SCENE.lines[0][:, :2], np.ones(3)], np.c_[SCENE.lines[0][:, 2:], np.ones(3)]),
        lines2=np.cross(np.c_[SCENE.lines[1][:, :2], np.ones(3)], np.c_[SCENE.lines[1][:, 2:], np.ones(3)]),
        lines3=np.cross(np.c_[SCENE.lines[2][:, :2], np.ones(3)], np.c_[SCENE.lines[2][:, 2:], np.ones(3)]),
        dist=np.array([0.1, 0.0, 0.0, 0.0]))),
    # The known pose of view 2.
    "R12_not_a_rotation": ("R12", ValueError, dict(R12=SCENE.R12 * 1.1)),
    "R12_reflection": ("R12", ValueError, dict(R12=-SCENE.R12)),
    "R12_off_by_1e-3": ("R12", ValueError, dict(R12=edited(SCENE.R12, (0, 1), SCENE.R12[0, 1] + 1e-3))),
    "R12_nan": ("R12", ValueError, dict(R12=edited(SCENE.R12, (0, 1), NAN))),
    "t12_zero": ("t12", ValueError, dict(t12=np.zeros(3))),
    "t12_inf": ("t12", ValueError, dict(t12=edited(SCENE.t12, 2, -INF))),
}


@pytest.mark.parametrize("call", ENTRY_POINTS)
@pytest.mark.parametrize("case", list(SHARED_CASES))
def test_shared_catalogue(call, case):
    argument, error, changes = SHARED_CASES[case]
    expect_rejected(call, argument, error, **three_view_args(**changes))


def few(num_points, num_lines):
    return dict(points1=SCENE.points[0][:num_points], points2=SCENE.points[1][:num_points],
                points3=SCENE.points[2][:num_points], lines1=SCENE.lines[0][:num_lines],
                lines2=SCENE.lines[1][:num_lines], lines3=SCENE.lines[2][:num_lines])


@pytest.mark.parametrize("call,num_points,num_lines", [(linear, 2, 1), (ransac, 1, 2), (refine, 1, 1)])
def test_too_few_features(call, num_points, num_lines):
    # The message names what is missing: features, i.e. points and lines.
    with pytest.raises(ValueError) as info:
        call(**three_view_args(**few(num_points, num_lines)))
    assert names(str(info.value), "points") and names(str(info.value), "lines"), str(info.value)


def test_three_features_are_enough_to_refine():
    refine(**three_view_args(**few(2, 1)))


def test_nothing_at_all():
    nothing = dict(points1=None, points2=None, points3=None, lines1=None, lines2=None, lines3=None)
    for call in ENTRY_POINTS:
        with pytest.raises(ValueError):
            call(**three_view_args(**nothing))


RANSAC_CASES = [("threshold", dict(threshold=0.0)), ("threshold", dict(threshold=-1.0)),
                ("threshold", dict(threshold=INF)), ("threshold", dict(threshold=NAN)),
                ("confidence", dict(confidence=0.0)), ("confidence", dict(confidence=1.0)),
                ("confidence", dict(confidence=NAN)), ("max_iterations", dict(max_iterations=0)),
                ("max_iterations", dict(max_iterations=-5)),
                ("min_inliers", dict(min_inliers=-1))]


@pytest.mark.parametrize("argument,changes", RANSAC_CASES)
def test_ransac_options(argument, changes):
    expect_rejected(ransac, argument, **three_view_args(**changes))
    stereo_changes = dict(stereo_args(), **changes)
    expect_rejected(tripose.estimate_pose_line_point_stereo_ransac, argument, **stereo_changes)
    expect_rejected(tripose.estimate_pose_multiview_ransac, argument, **dict(multiview_args(), **changes))


REFINE_CASES = [("max_iterations", dict(max_iterations=-1)), ("max_iterations", dict(max_iterations=0)),
                ("loss", dict(loss="l1")), ("loss", dict(loss="")), ("loss_scale", dict(loss_scale=0.0)),
                ("loss_scale", dict(loss_scale=INF)), ("tolerance", dict(tolerance=-1e-3)),
                ("tolerance", dict(tolerance=NAN)),
                ("R", dict(R=2.0 * SCENE.R)), ("R", dict(R=edited(SCENE.R, (2, 2), NAN))), ("R", dict(R=np.eye(2))),
                ("R", dict(R=edited(SCENE.R, (1, 2), SCENE.R[1, 2] + 1e-3))),
                ("t", dict(t=np.ones(2))), ("t", dict(t=edited(SCENE.t, 0, INF)))]


@pytest.mark.parametrize("argument,changes", REFINE_CASES)
def test_refine_options_and_initial_pose(argument, changes):
    expect_rejected(refine, argument, **three_view_args(**changes))


def test_refine_initial_pose_type():
    expect_rejected(refine, "R", TypeError, **three_view_args(R=np.eye(3, dtype=np.int32)))
    expect_rejected(refine, "t", TypeError, **three_view_args(t="t"))


# The stereo rig: points4 and lines4, NaN rows only in views 3 and 4, never in both.
def stereo_args(**changes):
    keys = ["points1", "points2", "points3", "points4", "lines1", "lines2", "lines3", "lines4"]
    a = dict(zip(keys, [x.copy() for x in STEREO.points + STEREO.lines]))
    a.update(K=STEREO.K, R12=STEREO.R12, t12=STEREO.t12)
    a.update(changes)
    return a


def stereo_refine(**a):
    return tripose.refine_pose_line_point_stereo(**a, R=STEREO.R, t=STEREO.t)


STEREO_ENTRY_POINTS = [tripose.estimate_pose_line_point_stereo, tripose.estimate_pose_line_point_stereo_ransac,
                       stereo_refine]


def nan_row(array, row):
    return edited(array, row, NAN)


STEREO_CASES = {
    "points4_another_count": ("points4", dict(points4=STEREO.points[3][:3])),
    "lines4_another_count": ("lines4", dict(lines4=np.zeros((5, 4)))),
    "points3_wrong_width": ("points3", dict(points3=np.zeros((4, 3)))),
    "lines4_homogeneous_beside_segments": ("lines4", dict(lines4=np.ones((3, 3)))),
    "points2_empty": ("points2", dict(points2=None)),
    "partly_nan_point_row": ("points4", dict(points4=edited(STEREO.points[3], (0, 1), NAN))),
    "partly_nan_line_row": ("lines3", dict(lines3=edited(STEREO.lines[2], (1, 2), NAN))),
    "inf_in_points3": ("points3", dict(points3=edited(STEREO.points[2], (0, 0), INF))),
    "inf_row_in_lines4": ("lines4", dict(lines4=edited(STEREO.lines[3], 0, INF))),
    "nan_row_in_time_A_view": ("points1", dict(points1=nan_row(STEREO.points[0], 0))),
    "nan_row_in_lines2": ("lines2", dict(lines2=nan_row(STEREO.lines[1], 1))),
    "R12_not_a_rotation": ("R12", dict(R12=STEREO.R12 * 1.1)),
    "t12_zero": ("t12", dict(t12=np.zeros(3))),
    "three_camera_matrices": ("K", dict(K=[STEREO.K] * 3)),
    "one_of_four_camera_matrices_bad": ("K[3]", dict(K=[STEREO.K] * 3 + [edited(STEREO.K, (1, 0), 1.0)])),
    "three_distortion_vectors": ("dist", dict(dist=[np.zeros(5)] * 3)),
}


@pytest.mark.parametrize("call", STEREO_ENTRY_POINTS)
@pytest.mark.parametrize("case", list(STEREO_CASES))
def test_stereo_catalogue(call, case):
    argument, changes = STEREO_CASES[case]
    expect_rejected(call, argument, **stereo_args(**changes))


@pytest.mark.parametrize("call", STEREO_ENTRY_POINTS)
def test_stereo_feature_missing_in_both_time_B_views(call):
    # The message names both views' arrays: the feature is missing in points3 and in points4.
    with pytest.raises(ValueError) as info:
        call(**stereo_args(points3=nan_row(STEREO.points[2], 1), points4=nan_row(STEREO.points[3], 1)))
    assert names(str(info.value), "points3") and names(str(info.value), "points4"), str(info.value)


# Several known views: lists of one array per view.
def multiview_args(**changes):
    a = dict(points=[p.copy() for p in MULTI.points], lines=[l.copy() for l in MULTI.lines], K=MULTI.K,
             Rs=list(MULTI.Rs), ts=list(MULTI.ts))
    a.update(changes)
    return a


def multiview_refine(**a):
    return tripose.refine_pose_multiview(**a, R=MULTI.R, t=MULTI.t)


MULTIVIEW_ENTRY_POINTS = [tripose.estimate_pose_multiview, tripose.estimate_pose_multiview_ransac, multiview_refine]

MULTIVIEW_CASES = {
    "points_list_too_short": ("points", ValueError, dict(points=MULTI.points[:3])),
    "lines_list_too_long": ("lines", ValueError, dict(lines=MULTI.lines + [MULTI.lines[0]])),
    "ts_shorter_than_Rs": ("ts", ValueError, dict(ts=MULTI.ts[:2])),
    "one_known_view": ("Rs", ValueError, dict(Rs=MULTI.Rs[:1], ts=MULTI.ts[:1], points=[MULTI.points[0], MULTI.points[3]],
                                             lines=[MULTI.lines[0], MULTI.lines[3]])),
    "Rs_element_not_a_rotation": ("Rs[0]", ValueError, dict(Rs=[MULTI.Rs[0] * 1.1] + MULTI.Rs[1:])),
    "Rs_element_off_by_1e-3": ("Rs[1]", ValueError, dict(Rs=[MULTI.Rs[0], edited(MULTI.Rs[1], (2, 0), MULTI.Rs[1][2, 0]
                                                                                  + 1e-3), MULTI.Rs[2]])),
    "ts_element_wrong_size": ("ts[2]", ValueError, dict(ts=MULTI.ts[:2] + [np.ones(2)])),
    "ts_element_int": ("ts[1]", TypeError, dict(ts=[MULTI.ts[0], np.array([1, 2, 3]), MULTI.ts[2]])),
    "points_element_wrong_width": ("points[1]", ValueError, dict(points=[MULTI.points[0], np.zeros((6, 3))] +
                                                                 MULTI.points[2:])),
    "new_view_misses_a_point": ("points[3]", ValueError, dict(points=MULTI.points[:3] +
                                                              [nan_row(MULTI.points[3], 5)])),
    "K_list_of_wrong_length": ("K", ValueError, dict(K=[MULTI.K] * 2)),
    # Not a list where a list of arrays is required. These fail with tripose 0.1.0: the Python layer
    # (_view_list in tripose/__init__.py) raises TypeError('a list of arrays, one per view, is
    # required'), which names no argument.
    "points_not_a_list": ("points", TypeError, dict(points=MULTI.points[0])),
    "lines_not_a_list": ("lines", TypeError, dict(lines=np.stack(MULTI.lines))),
    "Rs_as_one_array": ("Rs", TypeError, dict(Rs=np.stack(MULTI.Rs))),
    "ts_as_one_array": ("ts", TypeError, dict(ts=np.stack(MULTI.ts))),
}


@pytest.mark.parametrize("call", MULTIVIEW_ENTRY_POINTS)
@pytest.mark.parametrize("case", list(MULTIVIEW_CASES))
def test_multiview_catalogue(call, case):
    argument, error, changes = MULTIVIEW_CASES[case]
    expect_rejected(call, argument, error, **multiview_args(**changes))


def adjust_poses_args(**changes):
    a = multiview_args(Rs=MULTI.Rs + [MULTI.R], ts=MULTI.ts + [MULTI.t], fixed_views=[True, True, False, False])
    a.update(changes)
    return a


@pytest.mark.parametrize("argument,error,changes", [
    ("fixed_views", ValueError, dict(fixed_views=[True, True, False])),
    ("fixed_views", ValueError, dict(fixed_views=[True, False, False, False])),
    ("points", ValueError, dict(points=MULTI.points[:3])),
    ("Rs[3]", ValueError, dict(Rs=MULTI.Rs + [MULTI.R * 2])),
    ("max_iterations", ValueError, dict(max_iterations=0)),
    ("loss", ValueError, dict(loss="absolute")),
    ("Rs", TypeError, dict(Rs=np.stack(MULTI.Rs + [MULTI.R]))),
])
def test_adjust_poses_multiview_catalogue(argument, error, changes):
    expect_rejected(tripose.adjust_poses_multiview, argument, error, **adjust_poses_args(**changes))


def triangulate_args(**changes):
    a = dict(points=MULTI.points, lines=MULTI.lines, K=MULTI.K, Rs=MULTI.Rs + [MULTI.R], ts=MULTI.ts + [MULTI.t])
    a.update(changes)
    return a


@pytest.mark.parametrize("argument,error,changes", [
    ("Rs", ValueError, dict(points=MULTI.points[:1], lines=MULTI.lines[:1], Rs=MULTI.Rs[:1], ts=MULTI.ts[:1])),
    ("ts", ValueError, dict(ts=MULTI.ts[:2])),
    ("points", ValueError, dict(points=MULTI.points[:3])),
    ("Rs[3]", ValueError, dict(Rs=MULTI.Rs + [MULTI.R * 2])),
    ("ts[1]", ValueError, dict(ts=[MULTI.ts[0], np.array([0.0, np.nan, 1.0])] + MULTI.ts[2:] + [MULTI.t])),
    ("points", ValueError, dict(points=None, lines=None)),
    ("Rs", TypeError, dict(Rs=np.stack(MULTI.Rs + [MULTI.R]))),
])
def test_triangulate_multiview_catalogue(argument, error, changes):
    expect_rejected(tripose.triangulate_multiview, argument, error, **triangulate_args(**changes))


# Accepted variety: float32, any memory layout, lists.
def float32_exact(a):
    """a rounded to float32 and back: the same values in either precision."""
    return None if a is None else a.astype(np.float32).astype(np.float64)


def noisy_args():
    s = three_view_scene(5, 12, 8)
    rng = np.random.default_rng(3)
    return dict(points1=s.points[0] + rng.normal(size=s.points[0].shape), points2=s.points[1], points3=s.points[2],
                lines1=s.lines[0], lines2=s.lines[1] + rng.normal(size=s.lines[1].shape), lines3=s.lines[2],
                K=s.K, R12=s.R12, t12=s.t12), s


def assert_same_candidates(a, b):
    assert len(a.candidates) == len(b.candidates) > 0
    for (Ra, ta), (Rb, tb) in zip(a.candidates, b.candidates):
        np.testing.assert_array_equal(Ra, Rb)
        np.testing.assert_array_equal(ta, tb)


def test_float32_equals_float64_of_the_same_values():
    args, s = noisy_args()
    # R12 is kept in float64: rounded to float32 it is no longer a rotation, and its nearest
    # rotation differs from the float64 one in the last digits.
    values = {k: (float32_exact(v) if k != "R12" else v) for k, v in args.items()}
    reference = tripose.estimate_pose_line_point(**values)
    single = {k: (v.astype(np.float32) if k != "R12" else v) for k, v in values.items()}
    assert_same_candidates(reference, tripose.estimate_pose_line_point(**single))
    ransac_64 = tripose.estimate_pose_line_point_ransac(**values, seed=2)
    ransac_32 = tripose.estimate_pose_line_point_ransac(**single, seed=2)
    np.testing.assert_array_equal(ransac_64["R"], ransac_32["R"])
    np.testing.assert_array_equal(ransac_64["point_inliers"], ransac_32["point_inliers"])


def test_float32_rotation_within_float32_rounding_is_accepted():
    args, s = noisy_args()
    tripose.estimate_pose_line_point(**dict(args, R12=args["R12"].astype(np.float32)))


def six_digits(R):
    """R with every element rounded to 6 significant digits, as a camera file prints it."""
    R = np.asarray(R, dtype=np.float64)
    return np.array([float(f"{v:.6g}") for v in R.ravel()]).reshape(R.shape)


def rotation_angle(A, B):
    """The angle (radians) of A B^T, from the chord |A - B| = 2 sqrt(2) sin(angle / 2)."""
    return 2.0 * np.arcsin(min(1.0, np.linalg.norm(A - B) / (2.0 * np.sqrt(2.0))))


def test_rotations_rounded_to_six_digits_give_the_pose_of_the_exact_ones():
    # A rotation printed with 6 digits is a rotation: each function reads its nearest one.
    R12 = six_digits(SCENE.R12)
    assert np.linalg.norm(R12.T @ R12 - np.eye(3)) > 1e-6
    exact, rounded = three_view_args(), three_view_args(R12=R12)
    assert rotation_angle(linear(**rounded).R, linear(**exact).R) < 1e-5
    assert rotation_angle(ransac(**rounded)["R"], ransac(**exact)["R"]) < 1e-5
    assert rotation_angle(refine(**rounded, R=six_digits(SCENE.R))["R"], refine(**exact)["R"]) < 1e-5
    stereo = tripose.estimate_pose_line_point_stereo
    assert rotation_angle(stereo(**stereo_args(R12=six_digits(STEREO.R12))).R, stereo(**stereo_args()).R) < 1e-5
    multiview = tripose.estimate_pose_multiview
    assert rotation_angle(multiview(**multiview_args(Rs=[six_digits(R) for R in MULTI.Rs])).R,
                          multiview(**multiview_args()).R) < 1e-5


def layouts(a):
    """The same values as a Fortran-order array, a strided slice of a larger array, a transposed
    view and a negatively strided view."""
    big = np.zeros((2 * a.shape[0], a.shape[1] + 3))
    big[::2, 1:1 + a.shape[1]] = a
    transposed = np.ascontiguousarray(a.T).T
    reversed_view = np.ascontiguousarray(a[::-1])[::-1]
    return {"fortran": np.asfortranarray(a), "sliced": big[::2, 1:1 + a.shape[1]], "transposed": transposed,
            "reversed": reversed_view}


@pytest.mark.parametrize("layout", ["fortran", "sliced", "transposed", "reversed"])
def test_memory_layouts_equal_c_order(layout):
    args, s = noisy_args()
    reference = tripose.estimate_pose_line_point(**args, refine=True)
    other = {k: layouts(v)[layout] if v.ndim == 2 else v for k, v in args.items()}
    assert any(not v.flags.c_contiguous for v in other.values())
    assert_same_candidates(reference, tripose.estimate_pose_line_point(**other, refine=True))
    # t12 as a strided 1-D view, and R12 / K too.
    t_strided = np.repeat(args["t12"], 2)[::2]
    assert not t_strided.flags.c_contiguous
    assert_same_candidates(reference, tripose.estimate_pose_line_point(**dict(other, t12=t_strided), refine=True))


def test_float32_non_contiguous():
    args, s = noisy_args()
    values = {k: (float32_exact(v) if k != "R12" else v) for k, v in args.items()}
    reference = tripose.estimate_pose_line_point(**values)
    other = {k: (np.asfortranarray(v.astype(np.float32)) if k != "R12" else v) for k, v in values.items()}
    other["points1"] = layouts(values["points1"].astype(np.float32))["sliced"]
    assert_same_candidates(reference, tripose.estimate_pose_line_point(**other))


def test_lists_equal_arrays():
    args, s = noisy_args()
    reference = tripose.estimate_pose_line_point(**args)
    as_lists = {k: v.tolist() for k, v in args.items()}
    assert_same_candidates(reference, tripose.estimate_pose_line_point(**as_lists))


def test_empty_arrays_equal_none():
    s = three_view_scene(2, 0, 6)
    reference = tripose.estimate_pose_line_point(None, None, None, *s.lines, s.K, s.R12, s.t12)
    empty = [np.zeros((0, 2))] * 3
    assert_same_candidates(reference, tripose.estimate_pose_line_point(*empty, *s.lines, s.K, s.R12, s.t12))


def test_array_kinds_read_alike():
    # A numpy array of numpy's own float dtype is read from its fields; a subclass, a dtype object of
    # its own, a memoryview and an unaligned array take the other paths or offsets, and read the same.
    args, s = noisy_args()
    reference = tripose.estimate_pose_line_point(**args)

    class Subclass(np.ndarray):
        pass

    def unaligned(a):
        raw = np.zeros(a.size * 8 + 1, np.uint8)[1:].view(np.float64).reshape(a.shape)
        raw[...] = a
        assert not raw.flags.aligned
        return raw

    with_metadata = np.dtype(np.float64, metadata={"unit": "px"})
    kinds = {
        "subclass": lambda a: a.view(Subclass),
        "dtype with metadata": lambda a: a.astype(with_metadata),
        "memoryview": lambda a: memoryview(np.ascontiguousarray(a)),
        "unaligned": unaligned,
    }
    for kind, make in kinds.items():
        other = {k: make(v) for k, v in args.items()}
        assert_same_candidates(reference, tripose.estimate_pose_line_point(**other))
    with pytest.raises(TypeError, match="points2"):
        tripose.estimate_pose_line_point(**dict(args, points2=args["points2"].astype(">f8")))
