# SPDX-License-Identifier: MIT
"""meshio interchange: results to meshio.Mesh and back, so that any format meshio knows can be
read and written (meshio is imported only when used)."""
import numpy as np


def to_meshio(points, cells, cell_data=None):
    """A meshio.Mesh of points (N, 2) or (N, 3) and cells [(type, array)]."""
    import meshio

    return meshio.Mesh(np.asarray(points), [(kind, np.asarray(c)) for kind, c in cells if len(c)],
                       cell_data=cell_data or {})


def from_meshio(mesh):
    """(points, {"triangle": (M, 3), "quad": (Q, 4), "tetra": (T, 4), "line": (S, 2)}) of a
    meshio.Mesh; 3D points whose z are all zero come back as 2D."""
    points = np.asarray(mesh.points, dtype=np.float64)
    if points.ndim == 2 and points.shape[1] == 3 and not np.any(points[:, 2]):
        points = np.ascontiguousarray(points[:, :2])
    blocks = {}
    for block in mesh.cells:
        if block.type in ("triangle", "quad", "tetra", "line"):
            data = np.asarray(block.data, dtype=np.int64)
            blocks[block.type] = np.concatenate([blocks[block.type], data]) if block.type in blocks else data
    return points, blocks
