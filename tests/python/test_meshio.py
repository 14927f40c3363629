# SPDX-License-Identifier: MIT
"""meshio interchange: results to meshio.Mesh, written and read back in several formats."""
import numpy as np
import pytest

import exactmesh

meshio = pytest.importorskip("meshio")


@pytest.mark.parametrize("suffix", [".vtu", ".msh", ".off"])
def test_triangle_mesh_round_trip(tmp_path, suffix):
    m = exactmesh.mesh(domain="key", generator="frontal")
    path = tmp_path / f"key{suffix}"
    mm = m.to_meshio()
    if suffix == ".off":
        mm = meshio.Mesh(np.column_stack([m.points, np.zeros(len(m.points))]),
                         [("triangle", m.triangles)])
    meshio.write(path, mm, **({"file_format": "gmsh22", "binary": False} if suffix == ".msh" else {}))
    points, cells = exactmesh.from_meshio(meshio.read(path))
    assert np.array_equal(points, m.points)
    assert np.array_equal(cells["triangle"], m.triangles)


def test_tetrahedra_round_trip_keeps_orientation(tmp_path, rng):
    t = exactmesh.tetrahedralize(rng.random((300, 3)))
    mm = t.to_meshio()
    # VTK's right-handed order: every tetrahedron has positive volume there.
    p = mm.points[mm.cells[0].data]
    vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    assert (vol > 0).all()
    path = tmp_path / "t.vtu"
    meshio.write(path, mm)
    points, cells = exactmesh.from_meshio(meshio.read(path))
    assert np.array_equal(cells["tetra"], t.tetrahedra)
    assert exactmesh.check_tetrahedralization(points, cells["tetra"]).ok


def test_meshes_read_by_meshio_can_be_checked(tmp_path):
    m = exactmesh.cdt(*exactmesh.domain("square-with-holes")[:2])
    path = tmp_path / "m.vtu"
    meshio.write(path, m.to_meshio())
    points, cells = exactmesh.from_meshio(meshio.read(path))
    assert np.array_equal(points, m.points)
    assert np.array_equal(cells["triangle"], m.triangles)
    assert np.array_equal(cells["line"], m.pieces)
    # What came back is still the exact constrained Delaunay triangulation of the input.
    back = exactmesh.Mesh(points, cells["triangle"].astype(np.int32), m.neighbors,
                          m.input_vertex_count, m.segments, cells["line"], m.piece_segment,
                          m.merged_into, m.quads, m.holes, [], {})
    assert exactmesh.check_mesh(back).ok
