import numpy as np

from conftest import Scene, kernel, pose_vector


def null_space_planes(l1, l2, R12, t12):
    pi1 = np.concatenate([l1, [0.0]])
    pi2 = np.concatenate([R12.T @ l2, [t12 @ l2]])
    return np.vstack([pi1, pi2])


def test_line_rows_equal_point_on_plane_constraint(rng):
    line_rows = kernel("line_rows", "lineRows")
    for _ in range(20):
        qa, qb, l3 = rng.normal(size=4), rng.normal(size=4), rng.normal(size=3)
        R, t = rng.normal(size=(3, 3)), rng.normal(size=3)  # Any v: the rows are linear in it.
        rows = line_rows(qa=qa, qb=qb, l3=l3)["rows"].reshape(2, 12)
        pi3 = np.concatenate([R.T @ l3, [t @ l3]])
        v = pose_vector(R, t)
        np.testing.assert_allclose(rows @ v, [qa @ pi3, qb @ pi3], rtol=1e-13, atol=1e-13)


def test_line_null_space_is_orthonormal_basis_of_the_null_space(rng):
    null_space = kernel("line_rows", "lineNullSpace")
    for _ in range(50):
        l1, l2 = rng.normal(size=3), rng.normal(size=3)
        R12 = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        t12 = rng.normal(size=3)
        out = null_space(l1=l1, l2=l2, R12=R12.ravel(), t12=t12)
        Q = np.vstack([out["qa"], out["qb"]]).T
        np.testing.assert_allclose(Q.T @ Q, np.eye(2), atol=1e-14)
        P = null_space_planes(l1, l2, R12, t12)
        np.testing.assert_allclose(P @ Q, 0, atol=1e-14 * np.abs(P).max())
        # Same subspace as the SVD null space (the Householder Q spans it too).
        reference = np.linalg.svd(P)[2][2:].T
        np.testing.assert_allclose(Q @ Q.T, reference @ reference.T, atol=1e-13)


def test_exact_line_rows_vanish_on_true_pose(rng):
    null_space = kernel("line_rows", "lineNullSpace")
    line_rows = kernel("line_rows", "lineRows")
    for _ in range(20):
        scene = Scene(rng)
        l1, l2, l3 = scene.line()
        out = null_space(l1=l1, l2=l2, R12=scene.R12.ravel(), t12=scene.t12)
        rows = line_rows(qa=out["qa"], qb=out["qb"], l3=l3)["rows"].reshape(2, 12)
        v = pose_vector(scene.R, scene.t)
        assert np.linalg.matrix_rank(rows, tol=1e-8) == 2
        np.testing.assert_allclose(rows @ v, 0, atol=1e-12 * np.abs(rows).max() * np.abs(v).max())
