import numpy as np

from conftest import kernel


def columns(v):
    return v[0:3], v[3:6], v[6:9]


def test_n2_matrix_reproduces_homogeneous_constraints(rng):
    n2 = kernel("beta_constraints", "betaConstraintsN2")
    for _ in range(20):
        v1, v2 = rng.normal(size=12), rng.normal(size=12)
        C = n2(v1=v1, v2=v2)["C"].reshape(5, 3)
        b1, b2 = rng.normal(size=2)
        r1, r2, r3 = columns(b1 * v1 + b2 * v2)
        expected = [r1 @ r2, r2 @ r3, r3 @ r1, r1 @ r1 - r2 @ r2, r2 @ r2 - r3 @ r3]
        np.testing.assert_allclose(C @ [b1 * b1, b2 * b2, b1 * b2], expected, rtol=1e-12, atol=1e-12)


def test_n3_matrix_reproduces_rotation_constraints(rng):
    n3 = kernel("beta_constraints", "betaConstraintsN3")
    for _ in range(20):
        v1, v2, v3 = rng.normal(size=(3, 12))
        C = n3(v1=v1, v2=v2, v3=v3)["C"].reshape(6, 6)
        b1, b2, b3 = rng.normal(size=3)
        r1, r2, r3 = columns(b1 * v1 + b2 * v2 + b3 * v3)
        expected = [r1 @ r2, r2 @ r3, r3 @ r1, r1 @ r1, r2 @ r2, r3 @ r3]
        monomials = [b1 * b1, b2 * b2, b3 * b3, b1 * b2, b1 * b3, b2 * b3]
        np.testing.assert_allclose(C @ monomials, expected, rtol=1e-12, atol=1e-12)


def test_n3_system_recovers_a_rotation_in_the_span(rng):
    """With v a rotation in span(v1, v2, v3), C m = [0 0 0 1 1 1] has the true monomials."""
    n3 = kernel("beta_constraints", "betaConstraintsN3")
    from conftest import pose_vector, random_rotation

    v_true = pose_vector(random_rotation(rng), rng.normal(size=3))
    beta = rng.normal(size=3)
    v1, v2 = rng.normal(size=(2, 12))
    v3 = (v_true - beta[0] * v1 - beta[1] * v2) / beta[2]
    C = n3(v1=v1, v2=v2, v3=v3)["C"].reshape(6, 6)
    m = np.linalg.solve(C, [0, 0, 0, 1, 1, 1.0])
    b1, b2, b3 = beta
    np.testing.assert_allclose(m, [b1 * b1, b2 * b2, b3 * b3, b1 * b2, b1 * b3, b2 * b3], rtol=1e-9)
