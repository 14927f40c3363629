# SPDX-License-Identifier: MIT
"""The vectorized predicates against exact rational arithmetic (fractions)."""
from fractions import Fraction

import numpy as np
import pytest

import exactmesh


def exact_orient2d(a, b, c):
    a, b, c = ([Fraction(float(v)) for v in p] for p in (a, b, c))
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def exact_incircle(a, b, c, d):
    rows = []
    for p in (a, b, c):
        x, y = Fraction(float(p[0])) - Fraction(float(d[0])), Fraction(float(p[1])) - Fraction(float(d[1]))
        rows.append((x, y, x * x + y * y))
    (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = rows
    det = a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0)
    return (det > 0) - (det < 0)


def near_collinear(rng, n):
    """c on the line ab, rounded to doubles: exact answers of every sign, and zeros."""
    a = rng.random((n, 2))
    b = rng.random((n, 2))
    t = rng.random((n, 1))
    c = a + t * (b - a)
    return a, b, c


def test_orient2d_is_exact_on_near_degenerate_inputs(rng):
    a, b, c = near_collinear(rng, 2000)
    signs = exactmesh.orient2d(a, b, c)
    assert signs.dtype == np.int8 and signs.shape == (2000,)
    expected = [exact_orient2d(*row) for row in zip(a, b, c)]
    assert signs.tolist() == expected
    assert len(set(expected)) >= 2  # the inputs do reach both sides (and often zero)


def test_orient2d_of_exact_zeros_and_broadcast():
    a = np.array([0.0, 0.0])
    b = np.array([1.0, 1.0])
    c = np.array([[2.0, 2.0], [2.0, 2.0 + 2**-50], [3.0, 3.0 - 2**-51]])
    assert exactmesh.orient2d(a, b, c).tolist() == [0, 1, -1]


def test_incircle_on_rounded_cocircular_points(rng):
    angles = rng.random((500, 4)) * 2 * np.pi
    pts = np.stack([np.cos(angles), np.sin(angles)], axis=-1)  # on the unit circle, rounded
    a, b, c, d = (np.ascontiguousarray(pts[:, i]) for i in range(4))
    # Counter-clockwise a, b, c for the convention.
    cw = exactmesh.orient2d(a, b, c) < 0
    b2, c2 = np.where(cw[:, None], c, b), np.where(cw[:, None], b, c)
    signs = exactmesh.incircle(a, b2, c2, d)
    expected = [exact_incircle(*row) if exact_orient2d(row[0], row[1], row[2]) != 0 else None
                for row in zip(a, b2, c2, d)]
    assert all(e is None or s == e for s, e in zip(signs.tolist(), expected))


def test_orient3d_and_insphere_signs(rng):
    a, b, c = (rng.random((100, 3)) for _ in range(3))
    d = a + 0.5 * (b - a) + 0.25 * (c - a)  # nearly coplanar after rounding
    o = exactmesh.orient3d(a, b, c, d)
    assert set(o.tolist()) <= {-1, 0, 1}
    # Swapping two points flips every sign.
    assert (exactmesh.orient3d(b, a, c, d) == -o).all()
    e = np.array([0.5, 0.5, 0.5])
    s = exactmesh.insphere(a, b, c, d, e)
    assert (exactmesh.insphere(b, a, c, d, e) == -s).all()


def test_in_ellipse_is_incircle_for_the_identity(rng):
    a, b, c, d = (rng.random((300, 2)) for _ in range(4))
    assert (exactmesh.in_ellipse(a, b, c, d, np.array([1.0, 0.0, 1.0])) ==
            exactmesh.incircle(a, b, c, d)).all()


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinates_are_value_errors(bad):
    with pytest.raises(ValueError, match="not finite"):
        exactmesh.orient2d([0.0, 0.0], [1.0, 0.0], [[0.5, bad]])


def test_shape_errors():
    with pytest.raises(ValueError, match="shape"):
        exactmesh.orient2d(np.zeros((3, 3)), np.zeros((3, 2)), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="rows"):
        exactmesh.orient2d(np.zeros((3, 2)), np.zeros((4, 2)), np.zeros((3, 2)))
