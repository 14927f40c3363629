# SPDX-License-Identifier: MIT
"""exactmesh.fuzz (issue 16): a Python callable judged exactly on the project's degenerate
inputs. Our own constructions pass everything; scipy.spatial.Delaunay (Qhull) shows its known
failures; wrong, raising and malformed programs are caught and minimized; bad arguments raise
ValueError."""
import time

import numpy as np
import pytest

import exactmesh
from conftest import scale


def count(n):
    return max(int(n * scale()), 5)


def our_triangulate(points):
    return exactmesh.triangulate(points).triangles


def our_tetrahedralize(points):
    return exactmesh.tetrahedralize(points).tetrahedra


def our_cdt(points, segments, **options):
    m = exactmesh.cdt(points, segments, **options)
    return m.points, m.triangles, m.pieces


@pytest.mark.parametrize("kind, program", [("points2d", our_triangulate),
                                           ("points3d", our_tetrahedralize),
                                           ("pslg", our_cdt)])
def test_ours_pass_everything(kind, program):
    n = count(60)
    summary, failures = exactmesh.fuzz(program, kind=kind, count=n, seed=1, max_points=400)
    assert failures == []
    assert (summary.run, summary.passed, summary.bad, summary.refused) == (n, n, 0, 0)
    assert sum(run for run, _ in summary.per_distribution.values()) == n
    assert (summary.first_seed, summary.last_seed) == (1, n)


def test_ours_pass_convex_hull_and_conforming():
    n = count(30)
    summary, _ = exactmesh.fuzz(lambda p, s: our_cdt(p, s, remove_exterior=False), kind="pslg",
                                count=n, convex_hull=True, max_points=300)
    assert summary.passed == n
    summary, _ = exactmesh.fuzz(lambda p, s: our_cdt(p, s, recovery="conforming"), kind="pslg",
                                count=n, conforming=True, max_points=300)
    assert summary.passed == n


def drop_last(program):
    def dropped(*arguments):
        answer = program(*arguments)
        if isinstance(answer, tuple):
            return (answer[0], answer[1][:-1]) + answer[2:]
        return answer[:-1]
    return dropped


@pytest.mark.parametrize("kind, program, points, problem", [
    ("points2d", our_triangulate, 3, "no triangles, but points 0, 1, 2 are not collinear"),
    ("points3d", our_tetrahedralize, 4, "no tetrahedra, but points 0, 1, 2, 3 are not coplanar"),
    ("pslg", lambda p, s: our_cdt(p, s, remove_exterior=False), 3, "no triangles"),
])
def test_dropping_the_last_cell_fails_minimized(kind, program, points, problem):
    summary, failures = exactmesh.fuzz(drop_last(program), kind=kind, seed=2, count=1,
                                       convex_hull=kind == "pslg")
    assert (summary.run, summary.failed, summary.passed) == (1, 1, 0)
    [failure] = failures
    assert failure.seed == 2 and failure.verdict == "failed" and failure.minimized
    assert failure.complete
    assert len(failure.minimized_points) == points
    assert failure.minimized_points.shape[1] == (3 if kind == "points3d" else 2)
    assert failure.minimized_verdict == "failed"
    assert problem in failure.minimized_judgement
    assert len(failure.points) > len(failure.minimized_points)
    # The minimized input, given to the program again, fails the exact check the same way.
    if kind == "points2d":
        assert not exactmesh.check_delaunay(failure.minimized_points,
                                            drop_last(program)(failure.minimized_points))


def test_a_raising_program_crashes():
    def boom(points):
        raise RuntimeError(f"boom on {len(points)} points")

    summary, failures = exactmesh.fuzz(boom, count=6, minimize_seconds=5)
    assert summary.crashed + summary.refused == 6 and summary.crashed > 0
    assert summary.passed == summary.failed == 0
    for failure in failures:
        assert failure.verdict == "crashed"
        assert failure.judgement.startswith("RuntimeError: boom on ")
        # Not below 3 points: a crash on collinear points is a refusal of an input without
        # triangles, so the minimizer stops at 3 points in general position.
        assert len(failure.minimized_points) == 3
        assert failure.minimized_judgement == "RuntimeError: boom on 3 points"


def test_keyboard_interrupt_ends_the_run():
    def interrupted(points):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        exactmesh.fuzz(interrupted, count=3)


@pytest.mark.parametrize("answer, message", [
    (lambda p: exactmesh.triangulate(p).triangles.astype(float), "expected integers"),
    (lambda p: np.zeros((2, 4), dtype=int), "expected shape (N, 3)"),
    (lambda p: np.array([[0, 1, -2]]), "negative index"),
    (lambda p: None, "no cells"),
    (lambda p: (p, p, p), "tuple of 3"),
    (lambda p: np.array([[0, 1, 10**6]]), "names vertex 1000000"),
])
def test_malformed_answers_fail(answer, message):
    summary, failures = exactmesh.fuzz(answer, count=3, minimize_seconds=0)
    assert summary.failed + summary.refused == 3 and summary.failed > 0
    assert all(message in f.judgement for f in failures)


def test_orientation():
    def clockwise(points):
        return exactmesh.triangulate(points).triangles[:, ::-1]

    summary, _ = exactmesh.fuzz(clockwise, count=count(20), oriented=False)
    assert summary.passed == summary.run
    summary, failures = exactmesh.fuzz(clockwise, count=3, minimize_seconds=0)
    assert summary.failed == 3
    assert all("not counter-clockwise" in f.judgement for f in failures)


def test_added_vertices_are_matched_by_coordinates():
    # The points handed back in another order, cells renumbered: still exactly right.
    def shuffled(points):
        t = exactmesh.triangulate(points)
        order = np.arange(len(points))[::-1]
        where = np.empty_like(order)
        where[order] = np.arange(len(order))
        return points[order], where[t.triangles]

    summary, _ = exactmesh.fuzz(shuffled, count=count(20))
    assert summary.passed == summary.run


def test_scipy_delaunay_2d_known_failures():
    spatial = pytest.importorskip("scipy.spatial")
    summary, failures = exactmesh.fuzz(lambda p: spatial.Delaunay(p).simplices, count=30,
                                       max_points=200, oriented=False, minimize_seconds=10)
    assert summary.run == 30 and summary.passed > 0
    # Qhull gives up on near-collinear inputs ("initial simplex is flat") and on huge
    # coordinates: an exception, minimized to 3 points.
    assert summary.crashed > 0
    near_collinear = [f for f in failures if f.distribution == "near-collinear"]
    assert near_collinear
    for failure in failures:
        assert failure.verdict == "crashed" and failure.judgement.startswith("QhullError")
        assert len(failure.minimized_points) == 3
    assert summary.per_distribution["near-collinear"][1] > 0
    assert summary.per_distribution["uniform"][1] == 0


def test_scipy_delaunay_3d_known_failures():
    spatial = pytest.importorskip("scipy.spatial")
    summary, failures = exactmesh.fuzz(lambda p: spatial.Delaunay(p).simplices, kind="points3d",
                                       count=30, max_points=200, oriented=False,
                                       minimize_seconds=10)
    # Flat tetrahedra on grids (Qhull keeps coplanar simplices among cospherical points), and
    # exceptions on huge and tiny coordinates.
    flat = [f for f in failures if f.verdict == "failed"]
    assert flat and all(f.distribution == "grid" for f in flat)
    for failure in flat:
        assert "not positively oriented" in failure.judgement
        assert failure.minimized_verdict == "failed"
        assert 4 < len(failure.minimized_points) < 20
    crashed = [f for f in failures if f.verdict == "crashed"]
    assert crashed and all(f.distribution in ("huge", "tiny") for f in crashed)
    assert summary.per_distribution["uniform"][1] == 0


def test_progress_lines_reach_python_stderr(capsys):
    def slow(points):
        time.sleep(0.3)
        return exactmesh.triangulate(points).triangles

    summary, _ = exactmesh.fuzz(slow, count=9, quiet=False)
    assert summary.passed == 9
    assert "fuzz: " in capsys.readouterr().err


@pytest.mark.parametrize("arguments", [
    dict(kind="points4d"), dict(count=-1), dict(count=2.5), dict(max_points=3),
    dict(minimize_seconds=-1), dict(minimize_seconds="soon"), dict(conforming=True),
    dict(kind="points3d", convex_hull=True), dict(seed=-4),
])
def test_bad_arguments(arguments):
    with pytest.raises(ValueError):
        exactmesh.fuzz(our_triangulate, **arguments)


def test_not_callable():
    with pytest.raises(ValueError, match="callable"):
        exactmesh.fuzz(np.zeros((3, 2)))
