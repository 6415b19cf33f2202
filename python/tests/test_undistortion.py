"""dist=...: the package undistorts the observations as cv2.undistortPoints does (iterated to
convergence: cv2.undistortPointsIter, the criteria form of
cv2.undistortPoints), for OpenCV's 4, 5, 8, 12 and 14 coefficient models.

A noisy scene is seen through a distorting camera (cv2.projectPoints with the coefficients). The
package is called once with the distorted pixels and dist, once with the pixels undistorted by
cv2.undistortPoints(..., P=K) and no dist; both results must agree:
* the refinement (maximum likelihood, run to convergence from the true pose): its pose to 1e-9
  (rad, and relative for t), and its structure, reprojected into the three views without
  distortion, to 1e-9 px. The structure is triangulated from the undistorted pixels, so that its
  reprojections move with them (by at most about as much): this compares the two undistortions
  in pixels;
* the linear estimate to 1e-8 only: on noisy input its result moves by up to ~1e-9 (relative t)
  when the pixels move by 1e-12 px, even without distortion (doc/studies/accuracy.md), so that a 1e-9
  bound on it would test the linear solver's own precision, not the undistortion.
The observations carry 0.5 px of noise so that the estimates depend on every pixel (on noise-free
data any good undistortion gives the true pose).
"""
import cv2
import numpy as np
import pytest

import tripose
from scenes import project, rotation_error, three_view_scene, translation_error

CRITERIA = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 100, 1e-15)
PIXEL_TOL = 1e-9
POSE_TOL = 1e-9
LINEAR_POSE_TOL = 1e-8


def random_dist(rng, count):
    """Moderate coefficients (a monotonic, invertible model over the image)."""
    k = [rng.uniform(-0.15, 0.15), rng.uniform(-0.05, 0.05), rng.uniform(-2e-3, 2e-3), rng.uniform(-2e-3, 2e-3)]
    if count >= 5:
        k.append(rng.uniform(-0.01, 0.01))
    if count >= 8:
        k += [rng.uniform(-0.05, 0.05), rng.uniform(-0.02, 0.02), rng.uniform(-0.01, 0.01)]
    if count >= 12:
        k += list(rng.uniform(-2e-3, 2e-3, size=4))
    if count >= 14:
        k += list(rng.uniform(-0.01, 0.01, size=2))
    return np.array(k)


def distorted_scene(seed, dists):
    """A 10P+10L scene with 0.5 px noise; the observations of view v as seen through dists[v]."""
    s = three_view_scene(seed, 10, 10)
    rng = np.random.default_rng(seed + 500)
    points = [p + rng.normal(scale=0.5, size=p.shape) for p in s.points]
    lines = [l + rng.normal(scale=0.5, size=l.shape) for l in s.lines]

    def distort(pixels, dist):
        normalised = np.c_[(pixels - s.K[:2, 2]) / np.diag(s.K)[:2], np.ones(len(pixels))]
        out, _ = cv2.projectPoints(normalised, np.zeros(3), np.zeros(3), s.K, dist)
        return out.reshape(-1, 2)

    distorted_points = [distort(points[v], dists[v]) for v in range(3)]
    distorted_lines = [distort(lines[v].reshape(-1, 2), dists[v]).reshape(-1, 4) for v in range(3)]
    return s, distorted_points, distorted_lines


def cv2_undistort(pixels, K, dist):
    # cv2.undistortPoints with a termination criteria is undistortPointsIter in Python.
    out = cv2.undistortPointsIter(pixels.reshape(-1, 1, 2), K, dist, None, K, CRITERIA)
    return out.reshape(pixels.shape)


def reprojections(s, result):
    poses = [(np.eye(3), np.zeros(3)), (s.R12, s.t12), (result["R"], result["t"])]
    ends = result["lines3d"].reshape(-1, 3)
    return np.concatenate([np.concatenate([project(s.K, R, t, result["points3d"]).ravel(),
                                           project(s.K, R, t, ends).ravel()]) for R, t in poses])


def compare(s, points, lines, dists, dist_argument):
    undistorted_points = [cv2_undistort(points[v], s.K, dists[v]) for v in range(3)]
    undistorted_lines = [cv2_undistort(lines[v], s.K, dists[v]) for v in range(3)]
    # The distortion matters: undistortion moves some pixels by more than half a pixel.
    assert max(np.abs(points[v] - undistorted_points[v]).max() for v in range(3)) > 0.5

    with_dist = tripose.estimate_pose_line_point(*points, *lines, s.K, s.R12, s.t12, dist=dist_argument)
    without = tripose.estimate_pose_line_point(*undistorted_points, *undistorted_lines, s.K, s.R12, s.t12)
    assert len(with_dist.candidates) == len(without.candidates) > 0
    for (Ra, ta), (Rb, tb) in zip(with_dist.candidates, without.candidates):
        assert rotation_error(Ra, Rb) < LINEAR_POSE_TOL
        assert translation_error(ta, tb) < LINEAR_POSE_TOL
    # Both are close to the truth (0.5 px noise): the undistortion is right, not only the same.
    assert rotation_error(with_dist.R, s.R) < np.deg2rad(1.0)

    refined_with = tripose.refine_pose_line_point(*points, *lines, s.K, s.R12, s.t12, s.R, s.t, dist=dist_argument,
                                                  max_iterations=300)
    refined_without = tripose.refine_pose_line_point(*undistorted_points, *undistorted_lines, s.K, s.R12, s.t12,
                                                     s.R, s.t, max_iterations=300)
    assert rotation_error(refined_with["R"], refined_without["R"]) < POSE_TOL
    assert translation_error(refined_with["t"], refined_without["t"]) < POSE_TOL
    difference = np.abs(reprojections(s, refined_with) - reprojections(s, refined_without)).max()
    assert difference < PIXEL_TOL, difference


@pytest.mark.parametrize("count", [4, 5, 8, 12, 14])
def test_shared_distortion_equals_cv2_undistort(count):
    for seed in range(5):
        dist = random_dist(np.random.default_rng(100 * count + seed), count)
        s, points, lines = distorted_scene(seed, [dist] * 3)
        compare(s, points, lines, [dist] * 3, dist)


def test_one_distortion_per_view_equals_cv2_undistort():
    rng = np.random.default_rng(7)
    dists = [random_dist(rng, 5), random_dist(rng, 8), random_dist(rng, 14)]
    s, points, lines = distorted_scene(3, dists)
    compare(s, points, lines, dists, dists)


@pytest.mark.parametrize("shape", [(5,), (1, 5), (5, 1)])
def test_distortion_vector_layouts(shape):
    dist = random_dist(np.random.default_rng(1), 5)
    s, points, lines = distorted_scene(1, [dist] * 3)
    reference = tripose.estimate_pose_line_point(*points, *lines, s.K, s.R12, s.t12, dist=dist)
    other = tripose.estimate_pose_line_point(*points, *lines, s.K, s.R12, s.t12, dist=dist.reshape(shape))
    np.testing.assert_array_equal(reference.R, other.R)
    np.testing.assert_array_equal(reference.t, other.t)


def test_zero_distortion_is_no_distortion():
    s = three_view_scene(2, 6, 6)
    none = tripose.estimate_pose_line_point(*s.points, *s.lines, s.K, s.R12, s.t12)
    zeros = tripose.estimate_pose_line_point(*s.points, *s.lines, s.K, s.R12, s.t12, dist=np.zeros(5))
    assert rotation_error(none.R, zeros.R) < 1e-12
