# SPDX-License-Identifier: MIT
"""The module and the `exactmesh` command give the same output on the same input: triangulate,
tetrahedralize and cdt, on random and degenerate point sets (the same library underneath; this
checks the wiring: numbering, orientation, duplicates, options)."""
import subprocess

import numpy as np
import pytest

import exactmesh


def data_rows(path):
    return [l.split() for l in open(path) if l.split() and not l.lstrip().startswith("#")]


def read_cells(path, corners):
    rows = data_rows(path)
    n = int(rows[0][0])
    return np.array([[int(v) for v in r[1:1 + corners]] for r in rows[1:n + 1]], dtype=np.int64)


def write_node(path, points):
    with open(path, "w") as f:
        f.write(f"{len(points)} {points.shape[1]} 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i} " + " ".join(repr(float(v)) for v in p) + "\n")


def run(command, *args):
    subprocess.run([command, *map(str, args)], check=True, capture_output=True)


@pytest.mark.parametrize("name", ["uniform", "grid", "cocircular", "near-collinear"])
@pytest.mark.parametrize("algorithm", ["bowyer-watson", "green-sibson"])
def test_triangulate_same_as_the_command(command, tmp_path, name, algorithm):
    points = exactmesh.points_2d(name, 300, 7)
    write_node(tmp_path / "in.node", points)  # 0-based, so .ele numbers are indices
    run(command, "triangulate", tmp_path / "in.node", "-o", tmp_path / "out.ele",
        "--algorithm", algorithm, "--order", "brio", "--seed", 3)
    t = exactmesh.triangulate(points, algorithm=algorithm, order="brio", seed=3)
    assert (read_cells(tmp_path / "out.ele", 3) == t.triangles).all()


@pytest.mark.parametrize("name", ["uniform", "grid"])
def test_tetrahedralize_same_as_the_command(command, tmp_path, name):
    points = exactmesh.points_3d(name, 200, 5)
    write_node(tmp_path / "in.node", points)
    run(command, "tetrahedralize", tmp_path / "in.node", "-o", tmp_path / "out.ele")
    t = exactmesh.tetrahedralize(points)
    # The command's .ele is TetGen's corner order; the module returns exactmesh's (positive
    # orient3d): the same tetrahedra, each as a set of vertices.
    ours = sorted(tuple(sorted(c)) for c in t.tetrahedra.tolist())
    theirs = sorted(tuple(sorted(c)) for c in read_cells(tmp_path / "out.ele", 4).tolist())
    assert ours == theirs


def test_cdt_same_as_the_command(command, tmp_path):
    # A square with a hole and a crossing pair of diagonals: crossings split on both sides.
    points = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3],
                       [0.5, 0.2], [3.7, 3.9]], dtype=float)
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4],
                         [8, 9], [0, 2]])
    holes = np.array([[2.0, 1.5]])
    with open(tmp_path / "in.poly", "w") as f:
        f.write(f"{len(points)} 2 0 0\n")
        for i, p in enumerate(points):
            f.write(f"{i} {p[0]!r} {p[1]!r}\n")
        f.write(f"{len(segments)} 0\n")
        for i, s in enumerate(segments):
            f.write(f"{i} {s[0]} {s[1]}\n")
        f.write(f"{len(holes)}\n0 {holes[0][0]!r} {holes[0][1]!r}\n")
    run(command, "cdt", tmp_path / "in.poly", "-o", tmp_path / "out.ele")
    c = exactmesh.cdt(points, segments, holes=holes)
    rows = data_rows(tmp_path / "out.node")
    n = int(rows[0][0])
    nodes = np.array([[float(v) for v in r[1:3]] for r in rows[1:n + 1]])
    assert (nodes == c.points).all()
    assert (read_cells(tmp_path / "out.ele", 3) == c.triangles).all()
