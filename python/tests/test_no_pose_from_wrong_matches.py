"""The robust estimators on observations of the new view(s) that are all wrong matches (random
pixels), views 1-2 exact: with no floor on the inliers (min_inliers=0) a pose is returned only when
more features agree with it than a minimal sample holds (doc/conventions.md), never on one or two
inliers; with the default floor (15) chance matches give no pose; without a pose the result holds
no R, t or inlier."""
import numpy as np
import pytest

import tripose

K = np.array([[800.0, 0, 320], [0, 800, 240], [0, 0, 1]])
R12, t12 = np.eye(3), np.array([-0.5, 0.0, 0.0])


def project(R, t, X):
    x = (K @ (R @ X.T + t[:, None])).T
    return x[:, :2] / x[:, 2:]


def known_views(rng):
    n, m = int(rng.integers(2, 8)), int(rng.integers(2, 6))
    X = rng.uniform([-2, -2, 4], [2, 2, 8], (n, 3))
    L = rng.uniform([-2, -2, 4, -2, -2, 4], [2, 2, 8, 2, 2, 8], (m, 6))
    views = []
    for R, t in ((np.eye(3), np.zeros(3)), (R12, t12)):
        views.append((project(R, t, X), np.hstack([project(R, t, L[:, :3]), project(R, t, L[:, 3:])])))
    return views, n, m


def check(result, num_features):
    inliers = result["num_inliers"]
    if inliers == 0:
        assert result["R"] is None and result["t"] is None
        assert not np.any(result["point_inliers"]) and not np.any(result["line_inliers"])
    else:
        assert inliers >= min(4, num_features), inliers
        assert inliers == np.count_nonzero(result["point_inliers"]) + np.count_nonzero(result["line_inliers"])
    return inliers


def estimate_on_wrong_matches(estimator, seed, **options):
    """(result, number of features) of @p estimator on a scene whose new view(s) see random pixels."""
    rng = np.random.default_rng(seed)
    ((p1, l1), (p2, l2)), n, m = known_views(rng)
    wrong_points, wrong_lines = rng.uniform(0, 640, (n, 2)), rng.uniform(0, 640, (m, 4))
    if estimator == "three_view":
        result = tripose.estimate_pose_line_point_ransac(p1, p2, wrong_points, l1, l2, wrong_lines, K, R12, t12,
                                                         seed=seed, **options)
    elif estimator == "stereo":
        result = tripose.estimate_pose_line_point_stereo_ransac(
            p1, p2, wrong_points, rng.uniform(0, 640, (n, 2)), l1, l2, wrong_lines, rng.uniform(0, 640, (m, 4)),
            K, R12, t12, seed=seed, **options)
    else:
        result = tripose.estimate_pose_multiview_ransac([p1, p2, wrong_points], [l1, l2, wrong_lines], K,
                                                        [np.eye(3), R12], [np.zeros(3), t12], seed=seed, **options)
    return result, n + m


@pytest.mark.parametrize("estimator", ["three_view", "stereo", "multiview"])
def test_chance_matches_give_no_pose_under_the_default_floor(estimator):
    without_floor = 0
    for seed in range(30):
        result, num_features = estimate_on_wrong_matches(estimator, seed)
        assert check(result, num_features) == 0, (seed, result["num_inliers"])
        without_floor += check(*estimate_on_wrong_matches(estimator, seed, min_inliers=0)) > 0
    print(f"{estimator}: without the floor, a pose in {without_floor} of 30 scenes of wrong matches")


@pytest.mark.parametrize("estimator", ["three_view", "stereo", "multiview"])
def test_wrong_matches_give_no_pose_on_fewer_than_four_inliers(estimator):
    found = 0
    for seed in range(30):
        found += check(*estimate_on_wrong_matches(estimator, seed, min_inliers=0)) > 0
    print(f"{estimator}: a pose in {found} of 30 scenes of wrong matches")
