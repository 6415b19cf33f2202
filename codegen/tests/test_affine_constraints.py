import itertools

import numpy as np
import pytest

from conftest import kernel, pose_vector, random_rotation
from tripose_codegen.specs import affine_constraints as spec


def monomial_vector(c):
    """m(c) = [c_k^2, c_k c_l (k < l), c_k, 1], the column order of C."""
    d = len(c)
    return np.array([c[k] * c[k] for k in range(d)]
                    + [c[k] * c[l] for k, l in itertools.combinations(range(d), 2)]
                    + list(c) + [1.0])


def so3_quadrics(v):
    """The twenty rows of C, evaluated directly on v = [r1; r2; r3; t]."""
    R = np.column_stack([v[0:3], v[3:6], v[6:9]])
    r, p = R.T, R
    out = [r[0] @ r[1], r[1] @ r[2], r[2] @ r[0], r[0] @ r[0] - 1, r[1] @ r[1] - 1, r[2] @ r[2] - 1,
           p[0] @ p[1], p[1] @ p[2], p[2] @ p[0], p[0] @ p[0] - 1, p[1] @ p[1] - 1]
    for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        out += list(np.cross(r[a], r[b]) - r[c])
    return np.array(out)


def constraint_matrix(v0, E):
    d = len(E)
    C = kernel("affine_constraints", f"affineConstraintsD{d}")(v0=v0, e=np.ravel(E))["C"]
    return C.reshape(20, -1)


@pytest.mark.parametrize("d", spec.DIMENSIONS)
def test_matrix_reproduces_the_quadrics_on_the_affine_kernel(rng, d):
    for _ in range(10):
        v0, E = rng.normal(size=12), rng.normal(size=(d, 12))
        C = constraint_matrix(v0, E)
        assert C.shape == (20, d * (d + 3) // 2 + 1)
        c = rng.normal(size=d)
        expected = so3_quadrics(v0 + c @ E)
        np.testing.assert_allclose(C @ monomial_vector(c), expected, rtol=1e-12,
                                   atol=1e-12 * np.abs(C).max())


def subspace_through_a_rotation(rng, d, homogeneous=False):
    """v0 and an orthonormal basis E of a random d-dimensional affine kernel holding a pose,
    as an SVD returns them (v0 orthogonal to E); with @p homogeneous, v0 = 0 and the pose is a
    kernel vector (the three-view case). Returns (v0, E, c_true)."""
    v = pose_vector(random_rotation(rng), rng.normal(size=3))
    if homogeneous:
        E = np.linalg.qr(np.column_stack([v, rng.normal(size=(12, d - 1))]))[0].T
        return np.zeros(12), E, E @ v
    E = np.linalg.qr(rng.normal(size=(12, d)))[0].T
    return v - E.T @ (E @ v), E, E @ v


@pytest.mark.parametrize("d", spec.DIMENSIONS)
def test_quadrics_vanish_at_the_true_pose(rng, d):
    for homogeneous in (False, True):
        for _ in range(10):
            v0, E, c = subspace_through_a_rotation(rng, d, homogeneous)
            C = constraint_matrix(v0, E)
            np.testing.assert_allclose(C @ monomial_vector(c), 0, atol=1e-12 * np.abs(C).max())


def null_space_dimension(C, tol=1e-10):
    s = np.linalg.svd(C, compute_uv=False)
    return C.shape[1] - int(np.sum(s > tol * s[0]))


def test_the_twenty_quadrics_are_independent(rng):
    v0, E = rng.normal(size=12), rng.normal(size=(6, 12))
    assert np.linalg.matrix_rank(constraint_matrix(v0, E)) == 20


@pytest.mark.parametrize("d", spec.DIMENSIONS)
def test_linearization_determines_the_pose_up_to_d_5(rng, d):
    """Each monomial an unknown: the twenty quadrics leave a one-dimensional null space (the
    true monomial vector) for d <= 5, and the eight dimensions of a minimal problem for d = 6;
    the six column constraints alone only reach d = 2. With v0 = 0 (homogeneous) the handedness
    rows still single out the sign, which the six even column constraints cannot."""
    for homogeneous in (False, True):
        v0, E, c = subspace_through_a_rotation(rng, d, homogeneous)
        C = constraint_matrix(v0, E)
        assert null_space_dimension(C) == (1 if d <= 5 else 8)
        assert (null_space_dimension(C[:6]) == 1) == (d <= 2 and not homogeneous)
        if d <= 5:
            m = np.linalg.lstsq(C[:, :-1], -C[:, -1], rcond=None)[0]
            np.testing.assert_allclose(m[-d:], c, atol=1e-9)
