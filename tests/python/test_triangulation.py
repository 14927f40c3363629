# SPDX-License-Identifier: MIT
"""triangulate, tetrahedralize, cdt and the checks, against scipy.spatial.Delaunay (Qhull) on
non-degenerate inputs and on degenerate ones where scipy's output is valid."""
import numpy as np
import pytest
from conftest import scale

import exactmesh

scipy_spatial = pytest.importorskip("scipy.spatial")


def simplex_set(cells):
    return {tuple(sorted(c)) for c in np.asarray(cells).tolist()}


@pytest.mark.parametrize("algorithm", ["bowyer-watson", "green-sibson", "tanemura-merriam"])
def test_random_points_match_scipy(rng, algorithm):
    points = rng.random((max(100, int(3000 * scale())), 2))
    t = exactmesh.triangulate(points, algorithm=algorithm)
    assert exactmesh.check_delaunay(t.points, t.triangles).ok
    assert simplex_set(t.triangles) == simplex_set(scipy_spatial.Delaunay(points).simplices)


def test_input_is_read_in_place_and_results_are_not_copied(rng):
    points = rng.random((500, 2))
    t = exactmesh.triangulate(points)
    assert t.points is points  # float64 C-contiguous: used as given
    assert t.triangles.dtype == np.int32 and t.triangles.base is not None  # owns the C++ vector
    assert t.neighbors.shape == t.triangles.shape and (t.neighbors == -1).any()
    assert t.counters["points"] == 500


def test_cocircular_grid_is_delaunay_and_scipy_is_checked_exactly():
    # A 20 x 20 integer grid: every unit square has 4 cocircular corners, so the Delaunay
    # triangulation is not unique; ours and Qhull's must both pass the exact check.
    g = np.stack(np.meshgrid(np.arange(20.0), np.arange(20.0)), axis=-1).reshape(-1, 2)
    t = exactmesh.triangulate(g)
    assert exactmesh.check_delaunay(g, t.triangles).ok
    assert len(t.triangles) == 2 * 19 * 19
    theirs = scipy_spatial.Delaunay(g).simplices
    # Qhull lists triangles in either orientation: make them counter-clockwise first.
    signs = exactmesh.orient2d(g[theirs[:, 0]], g[theirs[:, 1]], g[theirs[:, 2]])
    theirs = np.where((signs < 0)[:, None], theirs[:, [0, 2, 1]], theirs)
    assert exactmesh.check_delaunay(g, theirs).ok


def test_duplicates_are_merged(rng):
    points = rng.random((200, 2))
    points = np.concatenate([points, points[:50]])
    t = exactmesh.triangulate(points)
    assert t.counters["duplicates"] == 50
    assert (t.merged_into[200:] == np.arange(50)).all()
    assert not np.isin(np.arange(200, 250), t.triangles).any()


def test_scale_invariance(rng):
    points = rng.random((300, 2))
    base = simplex_set(exactmesh.triangulate(points).triangles)
    for e in (600, -600):
        assert simplex_set(exactmesh.triangulate(np.ldexp(points, e)).triangles) == base


def test_tetrahedralize_matches_scipy(rng):
    points = rng.random((max(100, int(2000 * scale())), 3))
    for algorithm in ("bowyer-watson", "green-sibson"):
        t = exactmesh.tetrahedralize(points, algorithm=algorithm)
        assert exactmesh.check_tetrahedralization(t.points, t.tetrahedra).ok
        assert simplex_set(t.tetrahedra) == simplex_set(scipy_spatial.Delaunay(points).simplices)


def test_threads_give_the_same_simplices(rng):
    # Enough points for parallel rounds (as cli.threads): 2 and 3 threads against 1, exactly
    # checked; cocircular lattice points included (ties broken by the same perturbation).
    lattice = np.array([[i, j] for i in range(60) for j in range(60)], dtype=float) / 59
    for points in (rng.random((40000, 2)), np.vstack([lattice, rng.random((20000, 2))])):
        one = exactmesh.triangulate(points)
        for threads in (2, 3):
            t = exactmesh.triangulate(points, threads=threads)
            assert t.counters["threads"] == threads
            assert simplex_set(t.triangles) == simplex_set(one.triangles)
        assert exactmesh.check_delaunay(points, t.triangles).ok
    points = rng.random((20000, 3))
    one = exactmesh.tetrahedralize(points)
    t = exactmesh.tetrahedralize(points, threads=2)
    assert t.counters["threads"] == 2 and t.counters["parallel_points"] > 10000
    assert simplex_set(t.tetrahedra) == simplex_set(one.tetrahedra)
    with pytest.raises(exactmesh.InputError, match="above 1024"):
        exactmesh.triangulate(points[:, :2], threads=5000)


def test_tetrahedralize_coplanar_points():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
    t = exactmesh.tetrahedralize(points)
    assert t.coplanar and len(t.tetrahedra) == 0


def test_check_reports_a_non_delaunay_triangulation():
    # The square's two triangles across the wrong diagonal of a non-cocircular quad.
    points = np.array([[0, 0], [2, 0], [2, 1], [0, 3]], dtype=float)
    good = exactmesh.triangulate(points).triangles
    edges = {tuple(sorted(e)) for tri in good.tolist() for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0]))}
    bad = np.array([[0, 1, 3], [1, 2, 3]]) if (0, 2) in edges else np.array([[0, 1, 2], [0, 2, 3]])
    r = exactmesh.check_delaunay(points, bad)
    assert not r.ok and "Delaunay" in r.problem
    assert exactmesh.check_triangulation(points, bad).ok


def test_cdt_keeps_segments_and_splits_crossings():
    points = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.1, 0.3], [0.9, 0.7], [0.1, 0.7],
                       [0.9, 0.3]])
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [6, 7]])
    m = exactmesh.cdt(points, segments)
    assert m.counters["intersections"] == 1
    assert m.input_vertex_count == 8 and len(m.points) == 9
    assert (m.points[:8] == points).all()
    assert exactmesh.check_mesh(m).ok
    # Every piece comes from a segment, and the crossing splits both diagonals.
    assert len(m.pieces) == 4 + 2 + 2
    assert sorted(np.bincount(m.piece_segment).tolist()) == [1, 1, 1, 1, 2, 2]


def test_cdt_with_hole_and_recoveries():
    outer = [[0, 0], [3, 0], [3, 3], [0, 3]]
    inner = [[1, 1], [2, 1], [2, 2], [1, 2]]
    points = np.array(outer + inner, dtype=float)
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]])
    for recovery in ("swap", "cavity", "conforming"):
        m = exactmesh.cdt(points, segments, holes=[[1.5, 1.5]], recovery=recovery)
        assert exactmesh.check_mesh(m).ok
        assert len(m.triangles) == 8


@pytest.mark.parametrize("distribution", exactmesh.distributions_2d)
def test_every_2d_distribution_is_triangulated_exactly(distribution):
    points = exactmesh.points_2d(distribution, 2000, 3)
    assert points.shape == (2000, 2)
    t = exactmesh.triangulate(points)
    assert exactmesh.check_delaunay(points, t.triangles).ok
    assert t.construct_seconds > 0


@pytest.mark.parametrize("distribution", exactmesh.distributions_3d)
def test_every_3d_distribution_is_tetrahedralized_exactly(distribution):
    points = exactmesh.points_3d(distribution, 1000, 3)
    t = exactmesh.tetrahedralize(points)
    assert not t.coplanar
    assert exactmesh.check_tetrahedralization(points, t.tetrahedra).ok


def test_unknown_distribution():
    with pytest.raises(exactmesh.InputError, match="known"):
        exactmesh.points_2d("fractal", 10)


def test_constructions_run_in_threads(rng):
    # The GIL is released during construction: threads run side by side and each gets the
    # same triangulation as a sequential call (no shared state between calls).
    from concurrent.futures import ThreadPoolExecutor

    inputs = [rng.random((20000, 2)) for _ in range(4)]
    expected = [simplex_set(exactmesh.triangulate(p).triangles) for p in inputs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda p: exactmesh.triangulate(p).triangles, inputs))
    assert [simplex_set(r) for r in results] == expected
