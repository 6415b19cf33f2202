"""The pose covariance of the refiners and the robust functions, through the installed package.

The covariance is that of the maximum-likelihood pose for 1 px noise (doc/conventions.md, "Pose
covariance"); the C++ tests check it against finite differences and a Monte-Carlo study per regime
(doc/studies/accuracy.md). Here: what the package returns, where, in which order, and the conversion to the
camera centre that doc/conventions.md derives.
"""
import numpy as np
import pytest

import tripose
from scenes import rodrigues, three_view_scene

CHI2_6_95 = 12.591587243743977


def skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def rotation_log(R):
    """The rotation vector w with R = expm([w]x) (angles below pi)."""
    angle = np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0))
    w = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2.0
    return w if angle < 1e-12 else w * angle / np.sin(angle)


def noisy(scene, rng, sigma=1.0):
    return ([p + rng.normal(scale=sigma, size=p.shape) for p in scene.points],
            [l + rng.normal(scale=sigma, size=l.shape) for l in scene.lines])


def refine(scene, points, lines, R, t):
    return tripose.refine_pose_line_point(*points, *lines, scene.K, scene.R12, scene.t12, R, t)


def test_refine_returns_a_symmetric_positive_definite_covariance():
    scene = three_view_scene(11, 8, 8)
    rng = np.random.default_rng(1)
    points, lines = noisy(scene, rng)
    result = refine(scene, points, lines, scene.R, scene.t)
    cov = result["covariance"]
    assert cov.shape == (6, 6) and cov.dtype == np.float64
    np.testing.assert_allclose(cov, cov.T, rtol=0, atol=1e-12 * np.abs(cov).max())
    assert np.linalg.eigvalsh(cov).min() > 0
    # 1 px noise: the estimate of its variance is near 1 (66 residuals beyond the parameters here).
    assert 0.5 < result["noise_variance"] < 1.6


def test_noise_variance_scales_with_the_noise():
    scene = three_view_scene(12, 10, 10)
    rng = np.random.default_rng(2)
    points, lines = noisy(scene, rng, sigma=3.0)
    result = refine(scene, points, lines, scene.R, scene.t)
    assert 9.0 * 0.6 < result["noise_variance"] < 9.0 * 1.5


def test_errors_are_consistent_with_the_covariance():
    # 200 draws on one scene: the mean NEES of a right covariance is 6 with a standard error of
    # sqrt(12 / 200) = 0.24; +-0.8 is more than three of them, and a covariance off by a factor of
    # two (NEES 3 or 12), or with its rotation and translation exchanged, is far outside.
    scene = three_view_scene(13, 10, 10)
    rng = np.random.default_rng(3)
    nees = []
    for _ in range(200):
        points, lines = noisy(scene, rng)
        result = refine(scene, points, lines, scene.R, scene.t)
        e = np.concatenate([rotation_log(result["R"] @ scene.R.T), result["t"] - scene.t])
        nees.append(e @ np.linalg.solve(result["covariance"], e))
    nees = np.array(nees)
    assert abs(nees.mean() - 6.0) < 0.8
    assert 0.90 < np.mean(nees <= CHI2_6_95) < 0.99


def test_ransac_returns_the_refinement_covariance_when_asked_and_none_without_refinement():
    scene = three_view_scene(14, 8, 8)
    rng = np.random.default_rng(4)
    points, lines = noisy(scene, rng)
    reference = refine(scene, points, lines, scene.R, scene.t)
    result = tripose.estimate_pose_line_point_ransac(*points, *lines, scene.K, scene.R12, scene.t12, threshold=4.0,
                                                     covariance=True)
    assert result["num_inliers"] == 16
    np.testing.assert_allclose(result["covariance"], reference["covariance"], rtol=1e-5,
                               atol=1e-6 * np.abs(reference["covariance"]).max())
    assert result["noise_variance"] == pytest.approx(reference["noise_variance"], rel=1e-5)
    unrefined = tripose.estimate_pose_line_point_ransac(*points, *lines, scene.K, scene.R12, scene.t12,
                                                        threshold=4.0, refine=False, covariance=True)
    assert unrefined["covariance"] is None and unrefined["noise_variance"] is None
    # Not asked for (it costs one more refinement): not computed.
    unasked = tripose.estimate_pose_line_point_ransac(*points, *lines, scene.K, scene.R12, scene.t12, threshold=4.0)
    assert unasked["covariance"] is None and unasked["noise_variance"] is None
    np.testing.assert_array_equal(unasked["R"], result["R"])


def test_undetermined_pose_gives_none():
    # Every point behind view 3 (half a turn about its y axis): no feature enters the cost.
    scene = three_view_scene(15, 6, 0)
    half_turn = np.diag([-1.0, 1.0, -1.0])
    result = tripose.refine_pose_line_point(*scene.points, None, None, None, scene.K, scene.R12, scene.t12,
                                            half_turn @ scene.R, half_turn @ scene.t)
    assert np.isinf(result["rms"])
    assert result["covariance"] is None and result["noise_variance"] is None


def test_camera_centre_conversion_of_the_conventions():
    # doc/conventions.md: with R_est = expm([d]x) R, t_est = t + dt and C = -R^T t,
    # dC = [C]x R^T d - R^T dt to first order, and the world orientation R^T has the left error -R^T d.
    rng = np.random.default_rng(5)
    R = rodrigues(rng.normal(size=3))
    t = rng.normal(size=3) * 5
    C = -R.T @ t
    J = np.hstack([skew(C) @ R.T, -R.T])
    M = np.block([[-R.T, np.zeros((3, 3))], [skew(C) @ R.T, -R.T]])
    h = 1e-6
    for i in range(6):
        columns = []
        for sign in (1.0, -1.0):
            e = np.zeros(6)
            e[i] = sign * h
            Re, te = rodrigues(e[:3]) @ R, t + e[3:]
            columns.append(np.concatenate([rotation_log(Re.T @ R), -Re.T @ te]))
        derivative = (columns[0] - columns[1]) / (2 * h)
        np.testing.assert_allclose(derivative[3:], J[:, i], atol=1e-6)
        np.testing.assert_allclose(derivative, M[:, i], atol=1e-6)
