# SPDX-License-Identifier: MIT
"""scripts/slice_pictures.py's geometry: the polygons where a plane cuts a tetrahedral mesh tile
the cross-section (their areas sum to its area), vertices on the plane included, and the
smallest dihedral angle is right and scale-free. The geometry needs numpy alone."""
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import scale

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))
import slice_pictures  # noqa: E402

# The six Kuhn tetrahedra of the unit cube: the paths 0 -> e_a -> e_a + e_b -> (1, 1, 1).
KUHN = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]


def cube_grid(n):
    """[0, 1]^3 split into n^3 cubes of 6 Kuhn tetrahedra each (a conforming mesh)."""
    points = np.array([(i, j, k) for i in range(n + 1) for j in range(n + 1)
                       for k in range(n + 1)], dtype=float) / n

    def index(i, j, k):
        return (i * (n + 1) + j) * (n + 1) + k

    tets = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                for order in KUHN:
                    corner = [i, j, k]
                    path = [index(*corner)]
                    for axis in order:
                        corner[axis] += 1
                        path.append(index(*corner))
                    tets.append(path)
    return points, np.array(tets, dtype=np.int64)


def total_area(xyz, tets, axis, value):
    polygons = slice_pictures.slice_polygons(xyz, tets, axis, value)
    assert all(len(p) in (3, 4) for _, p in polygons)
    return sum(slice_pictures.polygon_area(p) for _, p in polygons), polygons


@pytest.mark.parametrize("n", [1, 3])
def test_cube_slices_tile_the_square(n):
    xyz, tets = cube_grid(n * max(1, int(scale())))
    for axis in range(3):
        for value in (0.37, 0.5 + 1e-9, 0.999):
            area, polygons = total_area(xyz, tets, axis, value)
            assert area == pytest.approx(1.0, abs=1e-12)
            # Each tetrahedron is cut at most once, and only those straddling the plane.
            cut = [t for t, _ in polygons]
            assert len(cut) == len(set(cut))


def test_vertices_on_the_plane_counted_once():
    xyz, tets = cube_grid(4)
    for value in (0.25, 0.5, 0.75):  # planes through whole layers of vertices and faces
        area, _ = total_area(xyz, tets, 2, value)
        assert area == pytest.approx(1.0, abs=1e-12)
    area, polygons = total_area(xyz, tets, 2, 1.5)
    assert area == 0 and not polygons


def hull_area(points):
    """Area of the convex hull of 2D points (monotone chain), independent of corner order."""
    p = sorted(map(tuple, points))

    def half(seq):
        chain = []
        for q in seq:
            while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (q[1] - chain[-2][1]) -
                                       (chain[-1][1] - chain[-2][1]) * (q[0] - chain[-2][0])) <= 0:
                chain.pop()
            chain.append(q)
        return chain[:-1]

    hull = np.array(half(p) + half(p[::-1]))
    return slice_pictures.polygon_area(hull)


def test_polygon_corners_in_cyclic_order(rng):
    # Two corners on each side of z = 0: the midpoints of the four crossing edges, a unit
    # diamond of area 1/2.
    xyz = np.array([[0.0, 0.0, -1.0], [1.0, 1.0, -1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
    polygons = slice_pictures.slice_polygons(xyz, np.array([[0, 1, 2, 3]]), 2, 0.0)
    assert len(polygons) == 1 and len(polygons[0][1]) == 4
    assert slice_pictures.polygon_area(polygons[0][1]) == pytest.approx(0.5, abs=1e-15)
    # Random tetrahedra: every cut is convex, so its shoelace area (corners in the order given)
    # is its convex hull's only when the order is cyclic.
    count = int(200 * scale())
    xyz = rng.uniform(-1, 1, size=(4 * count, 3))
    tets = np.arange(4 * count).reshape(count, 4)
    polygons = slice_pictures.slice_polygons(xyz, tets, 2, 0.0)
    assert sum(len(p) == 4 for _, p in polygons) > count // 10
    for _, p in polygons:
        assert slice_pictures.polygon_area(p) == pytest.approx(hull_area(p), rel=1e-9, abs=1e-15)


def test_min_dihedral_angles():
    regular = np.array([[1.0, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]])
    kuhn_xyz, kuhn = cube_grid(1)
    expected_regular = math.degrees(math.acos(1 / 3))
    for exponent in (0, 600, -600):
        angles = slice_pictures.min_dihedral_angles(np.ldexp(regular, exponent),
                                                    np.array([[0, 1, 2, 3]]))
        assert angles[0] == pytest.approx(expected_regular, abs=1e-9)
        # Every Kuhn tetrahedron has dihedral angles 45, 60 and 90 degrees: smallest 45.
        angles = slice_pictures.min_dihedral_angles(np.ldexp(kuhn_xyz, exponent), kuhn)
        assert np.allclose(angles, 45.0, atol=1e-9)


def test_exactmesh_box_with_hole_slices(command, tmp_path):
    # The built-in box with a hole ([0, 1]^3 less [0.25, 0.75]^3), recovered and refined: a
    # plane through the hole cuts 1 - 0.25, one under it 1.
    out = str(tmp_path / "box.ele")
    subprocess.run([command, "tetmesh", "--domain", "box-with-hole", "--max-volume", "0.01",
                    "-o", out], check=True, capture_output=True)
    xyz, first = slice_pictures.read_node(str(tmp_path / "box.node"))
    tets, _ = slice_pictures.read_cells(out, first, 4)
    for axis, value, expected in [(2, 0.47, 0.75), (0, 0.5, 0.75), (1, 0.11, 1.0)]:
        area, _ = total_area(xyz, tets, axis, value)
        assert area == pytest.approx(expected, abs=1e-12)
    angles = slice_pictures.min_dihedral_angles(xyz, tets)
    assert len(angles) == len(tets) and 0 < angles.min() <= angles.max() <= 70.53
