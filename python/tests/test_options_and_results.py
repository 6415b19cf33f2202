"""The option classes reach every field of the core's options, the robust and refining functions
return one PoseResult, and the keyword arguments of earlier releases give what the options give."""
import warnings

import numpy as np
import pytest

import tripose
from scenes import add_outliers, multiview_scene, perturb_pose, rotation_error, stereo_scene, three_view_scene


def noisy_scene(seed, sigma=0.5):
    scene = three_view_scene(seed, 40, 20)
    rng = np.random.default_rng(seed)
    scene.points = [p + rng.normal(0, sigma, p.shape) for p in scene.points]
    scene.lines = [l + rng.normal(0, sigma, l.shape) for l in scene.lines]
    rng_out = np.random.default_rng(seed + 100)
    scene.points[2], scene.lines[2], _, _ = add_outliers(rng_out, scene.points[2], scene.lines[2], 0.2)
    return scene


def legacy(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return function(*args, **kwargs)


def test_ransac_options_reach_every_field_of_the_core():
    options = tripose.RansacOptions()
    for name, value in (("threshold", 2.0), ("confidence", 0.999), ("max_iterations", 10000),
                        ("local_optimization", True), ("refine", True), ("seed", 0), ("min_inliers", 15)):
        assert getattr(options, name) == value, name
    refine = options.refine_options
    assert (refine.max_iterations, refine.loss, refine.loss_scale, refine.tolerance) == (30, "squared", 1.0, 1e-10)
    options.refine_options.loss = "cauchy"  # a field of the nested options, set in place
    assert options.refine_options.loss == "cauchy" and "loss='cauchy'" in repr(options)
    with pytest.raises(ValueError, match="loss"):
        options.refine_options.loss = "l1"


def test_options_give_what_the_keyword_arguments_gave():
    scene = noisy_scene(1)
    old = legacy(tripose.estimate_pose_line_point_ransac, *scene.args(), threshold=3.0, seed=7, min_inliers=10)
    options = tripose.RansacOptions()
    options.threshold, options.seed, options.min_inliers = 3.0, 7, 10
    new = tripose.estimate_pose_line_point_ransac(*scene.args(), options=options)
    np.testing.assert_array_equal(new.R, old["R"])
    np.testing.assert_array_equal(new.point_inliers, old["point_inliers"])
    refine = tripose.RefineOptions()
    refine.loss, refine.loss_scale = "huber", 0.7
    R0, t0 = perturb_pose(np.random.default_rng(0), scene.R, scene.t)
    old = legacy(tripose.refine_pose_line_point, *scene.args(), R0, t0, loss="huber", loss_scale=0.7)
    new = tripose.refine_pose_line_point(*scene.args(), R0, t0, options=refine)
    np.testing.assert_array_equal(new.R, old["R"])
    assert new.rms == old["rms"]


def test_the_refinement_loss_of_the_robust_estimate_is_reachable():
    # RANSAC under refine_options' Cauchy loss ends where refining its inliers under that loss ends.
    scene = noisy_scene(2)
    options = tripose.RansacOptions()
    options.refine_options.loss, options.refine_options.loss_scale = "cauchy", 0.5
    robust = tripose.estimate_pose_line_point_ransac(*scene.args(), options=options)
    squared = tripose.estimate_pose_line_point_ransac(*scene.args())
    changed = rotation_error(robust.R, squared.R)  # measured 3.7e-4 rad
    p, l = robust.point_inliers, robust.line_inliers
    refine = tripose.RefineOptions()
    refine.loss, refine.loss_scale = "cauchy", 0.5
    again = tripose.refine_pose_line_point(*[a[p] for a in scene.points], *[a[l] for a in scene.lines], scene.K,
                                           scene.R12, scene.t12, robust.R, robust.t, options=refine)
    # Measured 6.9e-6 rad: the two refinements stop at the default 30 steps.
    assert rotation_error(again.R, robust.R) < 0.05 * changed, (rotation_error(again.R, robust.R), changed)


def test_local_optimization_and_refine_can_be_turned_off():
    scene = noisy_scene(3)
    options = tripose.RansacOptions()
    options.local_optimization, options.refine = False, False
    result = tripose.estimate_pose_line_point_ransac(*scene.args(), options=options, covariance=True)
    assert result.R is not None and result.covariance is None and result.candidates == []
    assert rotation_error(result.R, scene.R) < np.radians(2)


def test_options_and_keyword_arguments_together_are_an_error_naming_them():
    scene = noisy_scene(4)
    with pytest.raises(ValueError, match="options and the keyword arguments threshold, seed"):
        tripose.estimate_pose_line_point_ransac(*scene.args(), options=tripose.RansacOptions(), threshold=3.0,
                                                seed=1)
    with pytest.raises(ValueError, match="loss"):
        tripose.refine_pose_line_point(*scene.args(), scene.R, scene.t, options=tripose.RefineOptions(),
                                       loss="cauchy")
    with pytest.raises(TypeError, match="RansacOptions"):
        tripose.estimate_pose_line_point_ransac(*scene.args(), options=tripose.RefineOptions())


def test_keyword_arguments_warn_with_the_new_call():
    scene = noisy_scene(5)
    with pytest.warns(DeprecationWarning, match=r"options=tripose\.RansacOptions\(threshold=\.\.\.\)"):
        tripose.estimate_pose_line_point_ransac(*scene.args(), threshold=3.0)


def test_bad_option_fields_are_named_as_options_fields():
    scene = noisy_scene(6)
    options = tripose.RansacOptions()
    options.threshold = 0.0
    with pytest.raises(ValueError, match=r"options\.threshold"):
        tripose.estimate_pose_line_point_ransac(*scene.args(), options=options)
    options = tripose.RansacOptions()
    options.refine_options.loss_scale = -1.0
    with pytest.raises(ValueError, match=r"options\.refine_options\.loss_scale"):
        tripose.estimate_pose_line_point_ransac(*scene.args(), options=options)
    refine = tripose.RefineOptions()
    refine.max_iterations = 0
    with pytest.raises(ValueError, match=r"options\.max_iterations"):
        tripose.refine_pose_line_point(*scene.args(), scene.R, scene.t, options=refine)


def test_every_robust_and_refining_function_returns_a_pose_result():
    three = noisy_scene(7)
    stereo = stereo_scene(8, 30, 15)
    multi = multiview_scene(9, 30, 15)
    results = [
        tripose.estimate_pose_line_point_ransac(*three.args(), covariance=True),
        tripose.refine_pose_line_point(*three.args(), three.R, three.t),
        tripose.estimate_pose_line_point_stereo_ransac(*stereo.args()),
        tripose.refine_pose_line_point_stereo(*stereo.args(), stereo.R, stereo.t),
        tripose.estimate_pose_multiview_ransac(multi.points, multi.lines, multi.K, multi.Rs, multi.ts),
        tripose.refine_pose_multiview(multi.points, multi.lines, multi.K, multi.Rs, multi.ts, multi.R, multi.t),
    ]
    for result in results:
        assert isinstance(result, tripose.PoseResult)
        assert result.R.shape == (3, 3) and result.t.shape == (3,) and result.rms >= 0
        assert result["R"] is result.R and result.get("no such field", 5) == 5 and "noise_variance" in result
        with pytest.raises(KeyError):
            result["no such field"]
        assert repr(result).startswith("PoseResult(rotation=")
    robust, refined = results[0], results[1]
    assert robust.num_inliers == robust.point_inliers.sum() + robust.line_inliers.sum()
    assert robust.covariance.shape == (6, 6) and robust.candidates[0][0].shape == (3, 3)
    assert robust.points3d is None and refined.num_inliers is None and refined.points3d.shape == (40, 3)
    assert f"num_inliers={robust.num_inliers}" in repr(robust) and "points3d=(40, 3)" in repr(refined)
    adjusted = tripose.adjust_poses_multiview(multi.points, multi.lines, multi.K, [True] * 3 + [False],
                                              multi.Rs + [multi.R], multi.ts + [multi.t])
    assert isinstance(adjusted, tripose.PoseResult) and adjusted.R is None and len(adjusted["Rs"]) == 4
    assert repr(adjusted).startswith("PoseResult(Rs, ts: 4 poses")


def test_no_pose_is_a_pose_result_without_one():
    scene = noisy_scene(10)
    rng = np.random.default_rng(0)
    wrong = [rng.uniform(0, 640, p.shape) for p in (scene.points[2], scene.lines[2])]
    result = tripose.estimate_pose_line_point_ransac(*scene.points[:2], wrong[0], *scene.lines[:2], wrong[1],
                                                     scene.K, scene.R12, scene.t12)
    assert result.R is None and result.num_inliers == 0 and np.isnan(result.rms)
    assert repr(result) == "PoseResult(no pose, num_inliers=0 of 40 points and 20 lines)"
