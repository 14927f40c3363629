# SPDX-License-Identifier: MIT
"""mesh() and quality(): every generator on the built-in domains, checked exactly; agreement
with the `exactmesh mesh` command on the same input; sizes as numbers, text and callables."""
import subprocess

import numpy as np
import pytest

import exactmesh


def read_ele(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    n = int(rows[0][0])
    return np.array([[int(v) for v in r[1:4]] for r in rows[1:n + 1]])


def read_node(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    n = int(rows[0][0])
    return np.array([[float(v) for v in r[1:3]] for r in rows[1:n + 1]])


@pytest.mark.parametrize("generator", exactmesh.generators)
def test_every_generator_meshes_the_key_and_passes_the_check(generator):
    kwargs = {}
    if generator in ("advancing-layers", "stretched-delaunay"):
        pytest.skip("layered generators mesh the airfoil domains (test_layers)")
    m = exactmesh.mesh(domain="key", generator=generator, **kwargs)
    assert len(m.triangles) > 100
    assert exactmesh.check_mesh(m).ok, exactmesh.check_mesh(m).problem
    assert m.construct_seconds > 0


def test_layers_on_the_airfoil():
    m = exactmesh.mesh(domain="naca0012", generator="advancing-layers", layers=(1e-4, 1.2))
    assert exactmesh.check_mesh(m).ok
    q = exactmesh.mesh(domain="naca0012", generator="advancing-layers", layers=(1e-4, 1.2, 10),
                       quads=True)
    assert len(q.quads) > 0 and q.quads.shape[1] == 4


def test_same_mesh_as_the_command(command, tmp_path):
    out = tmp_path / "key.ele"
    subprocess.run([command, "mesh", "--domain", "key", "--min-angle", "30", "-o", str(out)],
                   check=True, capture_output=True)
    m = exactmesh.mesh(domain="key", min_angle=30)
    assert (read_node(tmp_path / "key.node") == m.points).all()
    assert (read_ele(out) == m.triangles).all()


def test_rounds_on_two_threads_are_the_command_s_and_one_thread_s(command, tmp_path):
    out = tmp_path / "swh.ele"
    subprocess.run([command, "mesh", "--domain", "square-with-holes", "--size", "0.02",
                    "--min-angle", "30", "--threads", "2", "-o", str(out)],
                   check=True, capture_output=True)
    two = exactmesh.mesh(domain="square-with-holes", size=0.02, min_angle=30, threads=2)
    one = exactmesh.mesh(domain="square-with-holes", size=0.02, min_angle=30, threads=1,
                         refine_order="rounds")
    assert (read_node(tmp_path / "swh.node") == two.points).all()
    assert (read_ele(out) == two.triangles).all()
    assert (one.points == two.points).all() and (one.triangles == two.triangles).all()
    assert exactmesh.quality(two.points, two.triangles)["min_angle"] >= 30 - 1e-9
    with pytest.raises(exactmesh.InputError, match="threads and refine_order apply"):
        exactmesh.mesh(domain="key", generator="frontal", threads=2)
    with pytest.raises(exactmesh.InputError, match="worst-first refinement runs on one thread"):
        exactmesh.mesh(domain="key", threads=2, refine_order="worst-first")
    with pytest.raises(exactmesh.InputError, match="above 1024"):
        exactmesh.mesh(domain="key", threads=5000)


def test_min_angle_is_met_away_from_small_input_angles():
    m = exactmesh.mesh(domain="square-with-holes", min_angle=30)
    q = exactmesh.quality(m.points, m.triangles)
    assert q["min_angle"] >= 30 - 1e-9
    assert q["triangles"] == len(m.triangles)
    assert sum(q["angle_histogram"]) == 3 * len(m.triangles)


def test_pslg_with_callable_size_and_size_conformity():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    size = lambda x, y: 0.02 + 0.1 * x  # noqa: E731
    m = exactmesh.mesh(square, segments, generator="frontal", size=size)
    assert exactmesh.check_mesh(m).ok
    q = m.quality(size=0.05)
    assert "size_ratio_median" in q
    # Finer where the size is smaller.
    centroids = m.points[m.triangles].mean(axis=1)
    left, right = centroids[:, 0] < 0.3, centroids[:, 0] > 0.7
    assert left.sum() > 2 * right.sum()


def test_sizes_as_number_and_text_agree():
    a = exactmesh.mesh(domain="key", generator="frontal", size=0.05)
    b = exactmesh.mesh(domain="key", generator="frontal", size="0.05")
    c = exactmesh.mesh(domain="key", generator="frontal", size="uniform 0.05")
    assert (a.triangles == b.triangles).all() and (a.triangles == c.triangles).all()


def test_scaled_domain_gives_the_scaled_mesh():
    points, segments, holes = exactmesh.domain("key")
    base = exactmesh.mesh(points, segments, holes, min_angle=25)
    for e in (600, -600):
        m = exactmesh.mesh(np.ldexp(points, e), segments, np.ldexp(holes, e), min_angle=25)
        assert (m.triangles == base.triangles).all()
        assert (m.points == np.ldexp(base.points, e)).all()
