import numpy as np
from numpy.polynomial import polynomial as P

from conftest import kernel, pose_vector, random_rotation

DEGREES = (4, 4, 4, 3, 3, 2)


def unpack(u):
    out, offset = [], 0
    for d in DEGREES:
        out.append(np.asarray(u[offset:offset + d + 1]))
        offset += d + 1
    return out


def bilinear_forms():
    """The five constraints as bilinear forms B_k(a, b) on 12-vectors (q_k(v) = B_k(v, v))."""
    def block(v, i):
        return v[3 * i:3 * i + 3]

    def dot(i, j):
        return lambda a, b: 0.5 * (block(a, i) @ block(b, j) + block(b, i) @ block(a, j))

    def norm_diff(i, j):
        return lambda a, b: block(a, i) @ block(b, i) - block(a, j) @ block(b, j)

    return [dot(0, 1), dot(1, 2), dot(2, 0), norm_diff(0, 1), norm_diff(1, 2)]


def direct_matrix(vs, b3):
    """The 5x6 matrix of eq. (24) at a given beta3, built from the bilinear forms."""
    v1, v2, v3, v4 = vs
    w = b3 * v3 + v4
    rows = []
    for B in bilinear_forms():
        rows.append([B(v1, v1), B(v2, v2), 2 * B(v1, v2), 2 * B(v1, w), 2 * B(v2, w), B(w, w)])
    return np.array(rows)


def test_matrix_coefficients_match_direct_construction(rng):
    matrix = kernel("beta_n4", "betaN4Matrix")
    for _ in range(10):
        vs = rng.normal(size=(4, 12))
        M = matrix(v=vs.ravel())["M"].reshape(5, 10)
        for b3 in rng.normal(size=3):
            polys = np.column_stack([M[:, 0], M[:, 1], M[:, 2], M[:, 3] + b3 * M[:, 4],
                                     M[:, 5] + b3 * M[:, 6], M[:, 7] + b3 * M[:, 8] + b3 * b3 * M[:, 9]])
            np.testing.assert_allclose(polys, direct_matrix(vs, b3), rtol=1e-12, atol=1e-12)


def test_null_vector_equals_signed_minors(rng):
    null_vector = kernel("beta_n4", "betaN4NullVector")
    for _ in range(20):
        vs = rng.normal(size=(4, 12))
        u = unpack(null_vector(v=vs.ravel())["u"])
        for b3 in rng.normal(scale=2.0, size=4):
            A = direct_matrix(vs, b3)
            minors = [(-1) ** i * np.linalg.det(np.delete(A, i, axis=1)) for i in range(6)]
            values = [P.polyval(b3, c) for c in u]
            # Cancellation in a 5x5 determinant: compare relative to its Hadamard bound.
            scale = np.prod(np.linalg.norm(A, axis=1))
            np.testing.assert_allclose(values, minors, rtol=0, atol=1e-12 * scale)
            np.testing.assert_allclose(A @ values, 0, atol=1e-12 * scale * np.abs(A).max())


def test_consistency_and_stationarity_polynomials(rng):
    consistency = kernel("beta_n4", "betaN4Consistency")
    polynomial = kernel("beta_n4", "betaN4Polynomial")
    for _ in range(20):
        u_packed = rng.normal(size=26)
        u = unpack(u_packed)
        f_expected = [P.polysub(P.polymul(u[3], u[4]), P.polymul(u[2], u[5])),
                      P.polysub(P.polymul(u[3], u[3]), P.polymul(u[0], u[5])),
                      P.polysub(P.polymul(u[4], u[4]), P.polymul(u[1], u[5]))]
        f = consistency(u=u_packed)["f"].reshape(3, 7)
        for i in range(3):
            np.testing.assert_allclose(f[i], f_expected[i], rtol=1e-13, atol=1e-13)
        p = polynomial(u=u_packed)["p"]
        assert p.shape == (12,)
        for x in rng.normal(scale=2.0, size=5):
            expected = sum(P.polyval(x, fi) * P.polyval(x, P.polyder(fi)) for fi in f_expected)
            terms = sum(abs(P.polyval(abs(x), np.abs(fi))) * abs(P.polyval(abs(x), np.abs(P.polyder(fi))))
                        for fi in f_expected)
            assert abs(P.polyval(x, p) - expected) <= 1e-13 * terms


def test_true_coefficients_are_a_root_with_exact_data(rng):
    """v4 chosen so that b1 v1 + b2 v2 + b3 v3 + v4 is a scaled pose: b3 is a root of p and
    u(b3) is proportional to [b1^2, b2^2, b1 b2, b1, b2, 1]."""
    null_vector = kernel("beta_n4", "betaN4NullVector")
    polynomial = kernel("beta_n4", "betaN4Polynomial")
    for _ in range(20):
        v_true = 1.7 * pose_vector(random_rotation(rng), rng.normal(size=3))
        b1, b2, b3 = rng.normal(size=3)
        v1, v2, v3 = rng.normal(size=(3, 12))
        v4 = v_true - b1 * v1 - b2 * v2 - b3 * v3
        u_packed = null_vector(v=np.concatenate([v1, v2, v3, v4]))["u"]
        u = np.array([P.polyval(b3, c) for c in unpack(u_packed)])
        expected = np.array([b1 * b1, b2 * b2, b1 * b2, b1, b2, 1])
        np.testing.assert_allclose(u / u[5], expected, rtol=0, atol=1e-9 * np.linalg.norm(expected))
        p = polynomial(u=u_packed)["p"]
        scale = np.abs(p).max() * max(1.0, abs(b3)) ** 11
        assert abs(P.polyval(b3, p)) < 1e-10 * scale
