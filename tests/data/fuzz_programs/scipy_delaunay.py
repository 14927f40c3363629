#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# scipy.spatial.Delaunay (Qhull) as a program for `exactmesh fuzz --command` (issue 16: judging
# other people's triangulators): reads a Triangle .node (2D) or TetGen .node (3D), writes the
# Delaunay simplices as a Triangle .ele (counter-clockwise) or TetGen .ele (orient3d < 0 in
# Shewchuk's convention, TetGen's order). Qhull does not orient its simplices consistently, so
# each is oriented here by the exact sign of its determinant (fractions.Fraction holds a double
# exactly): what the check then judges is Qhull's choice of simplices, never this wrapper's.
#   exactmesh fuzz --kind points2d --command '/usr/bin/python3 scipy_delaunay.py {in} {out}'
# (Debian's python3-scipy: /usr/bin/python3, not a pyenv python without scipy).
"""Usage: scipy_delaunay.py IN.node OUT.ele"""
import sys
from fractions import Fraction

import numpy as np
from scipy.spatial import Delaunay

import node_file


def read_node(path):
    points, dimension, first = node_file.read_node(path)
    return np.array(points, dtype=float).reshape(len(points), dimension), first


def determinant_sign(rows):
    """Exact sign of the determinant of the differences rows[k] - rows[0]."""
    base = [Fraction(v) for v in rows[0]]
    m = [[Fraction(v) - b for v, b in zip(row, base)] for row in rows[1:]]
    if len(m) == 2:
        d = m[0][0] * m[1][1] - m[0][1] * m[1][0]
    else:
        d = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
             - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
             + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return (d > 0) - (d < 0)


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    points, first = read_node(argv[1])
    dimension = points.shape[1]
    try:
        simplices = Delaunay(points).simplices if len(points) > dimension else np.zeros((0, dimension + 1), int)
    except Exception as error:  # noqa: BLE001  (Qhull's messages run to dozens of lines)
        # The first line says what went wrong; it is the last stderr line, the one a crash
        # report quotes.
        sys.exit(f"{type(error).__name__}: {str(error).strip().splitlines()[0]}")
    with open(argv[2], "w", encoding="ascii") as ele:
        ele.write(f"{len(simplices)} {dimension + 1} 0\n")
        for number, simplex in enumerate(simplices):
            corners = [int(v) for v in simplex]
            sign = determinant_sign([points[v] for v in corners])
            # 2D: counter-clockwise (positive); 3D: TetGen's order (negative orient3d, which is
            # a positive determinant of the differences).
            if (dimension == 2 and sign < 0) or (dimension == 3 and sign < 0):
                corners[0], corners[1] = corners[1], corners[0]
            ele.write(f"{number + first} " + " ".join(str(v + first) for v in corners) + "\n")


if __name__ == "__main__":
    main(sys.argv)
