"""The candidate estimators (estimate_pose_line_point, estimate_pose_line_point_stereo,
estimate_pose_multiview) return a PoseResult: the best candidate as R, t, rms, every candidate in
candidates and candidate_rms, None for what they do not give; the list they returned before is still
read, with a DeprecationWarning, for one release."""
import warnings

import numpy as np
import pytest

import tripose
from scenes import empty_or, multiview_scene, pose_close, stereo_scene, three_view_scene

TOL = 1e-6


def views(arrays):
    return [empty_or(a) for a in arrays]


def three_view(refine=False):
    s = three_view_scene(3, 5, 4)
    return s, tripose.estimate_pose_line_point(*s.points, *s.lines, s.K, s.R12, s.t12, refine=refine)


def stereo(refine=False):
    s = stereo_scene(4, 4, 3)
    return s, tripose.estimate_pose_line_point_stereo(*views(s.points), *views(s.lines), s.K, s.R12, s.t12,
                                                      refine=refine)


def multiview(refine=False):
    s = multiview_scene(5, 4, 3)
    return s, tripose.estimate_pose_multiview(s.points, s.lines, s.K, s.Rs, s.ts, refine=refine)


PROBLEMS = {"three_view": three_view, "stereo": stereo, "multiview": multiview}


@pytest.mark.parametrize("refine", [False, True])
@pytest.mark.parametrize("name", PROBLEMS)
def test_fields_of_the_candidate_result(name, refine):
    s, result = PROBLEMS[name](refine)
    assert isinstance(result, tripose.PoseResult)
    candidates = result.candidates
    assert isinstance(candidates, list) and len(candidates) > 0
    # The best candidate is the pose, and noise-free data put it at the truth.
    assert result.R is candidates[0][0] and result.t is candidates[0][1]
    assert result.R.shape == (3, 3) and result.t.shape == (3,) and result.R.dtype == np.float64
    assert pose_close(result.R, result.t, s.R, s.t, TOL)
    rms = result.candidate_rms
    assert len(rms) == len(candidates) and rms == sorted(rms)
    assert result.rms == rms[0] < 1e-6
    # What a candidate estimator does not give is None.
    for field in ("num_inliers", "point_inliers", "line_inliers", "covariance", "noise_variance", "ambiguous",
                  "points3d", "lines3d", "Rs", "ts"):
        assert getattr(result, field) is None, field
        assert result[field] is None, field
    text = repr(result)
    assert text.startswith("PoseResult(rotation=") and f"candidates={len(candidates)})" in text
    assert "num_inliers" not in text


def test_no_candidate_is_no_pose():
    # Five observations of one point: the geometry determines no pose.
    s = three_view_scene(3, 5, 0)
    same = [np.repeat(p[:1], 5, axis=0) for p in s.points]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = tripose.estimate_pose_line_point(*same, None, None, None, s.K, s.R12, s.t12)
        assert result.R is None and result.t is None and result.rms is None
        assert result.candidates == [] and result.candidate_rms == []
        assert repr(result) == "PoseResult(no pose, candidates=0)"
    with pytest.warns(DeprecationWarning):
        assert len(result) == 0
    with pytest.warns(DeprecationWarning):
        assert not result


@pytest.mark.parametrize("name", PROBLEMS)
def test_list_use_warns_and_reads_the_candidates(name):
    _, result = PROBLEMS[name]()
    candidates = result.candidates
    with pytest.warns(DeprecationWarning, match="result.candidates"):
        assert len(result) == len(candidates)
    with pytest.warns(DeprecationWarning, match="result.candidates"):
        R, t = result[0]
    assert R is candidates[0][0] and t is candidates[0][1]
    with pytest.warns(DeprecationWarning):
        assert result[-1] is candidates[-1]
    with pytest.warns(DeprecationWarning):
        assert result[:1] == candidates[:1]
    with pytest.warns(DeprecationWarning):
        with pytest.raises(IndexError):
            result[len(candidates)]
    with pytest.warns(DeprecationWarning):
        assert result
    # Iteration warns once, then gives every (R, t).
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        pairs = [(R, t) for R, t in result]
    assert [w.category for w in caught] == [DeprecationWarning]
    assert len(pairs) == len(candidates)
    for (R, t), (Rc, tc) in zip(pairs, candidates):
        assert R is Rc and t is tc
    # Reading the fields by name is not deprecated.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert result["R"] is result.R and "candidates" in result


def test_other_results_are_not_lists():
    s = three_view_scene(3, 5, 4)
    result = tripose.estimate_pose_line_point_ransac(*s.points, *s.lines, s.K, s.R12, s.t12,
                                                     options=tripose.RansacOptions(min_inliers=0))
    assert result and result.R is not None
    for use in (len, iter, lambda r: r[0]):
        with pytest.raises(TypeError, match="result.candidates"):
            use(result)
