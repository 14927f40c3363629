# SPDX-License-Identifier: MIT
"""The Triangle/TetGen .node reader shared by the wrapper programs of this folder (each is run as
a script from here, so Python finds this module beside it)."""


def read_node(path):
    """The points of a Triangle (2D) or TetGen (3D) .node: (rows of coordinates, dimension,
    first index)."""
    rows = []
    with open(path, encoding="ascii") as node:
        for line in node:
            line = line.split("#", 1)[0].split()
            if line:
                rows.append(line)
    count, dimension = int(rows[0][0]), int(rows[0][1]) if len(rows[0]) > 1 else 2
    first = int(rows[1][0]) if count else 1
    points = [[float(v) for v in row[1:1 + dimension]] for row in rows[1:1 + count]]
    return points, dimension, first
